// snap_near_coplanar_faces: the step of round_safe (arrangements/round_mesh.h) that goes back
// to the input, after merging close input vertices, for faces that nearly coincide without
// sharing vertices: parts placed by transforms rounded to doubles (a cube turned by 2 pi / 3
// about its diagonal, which maps it onto itself, and moved along a face) whose faces lie
// an ulp or so off each other's planes, shifted in the plane. Their exact arrangement
// crosses the two layers along lines wherever the rounding errors change sign, and no
// rounding keeps such crossings: the rounded layers cross again elsewhere.
//
// Made coplanar exactly, the layers give each shared region once, with the union of the
// labels. Triangles are linked when every corner of each lies within `delta` of the other's
// plane (exact squared distances) and they share a corner or their boxes, widened by
// delta, overlap; a group of linked triangles with at least one link between triangles
// that share no corner (layers, not one flat face) gets one plane, that of its largest
// triangle. Every vertex of a group moves onto its plane: onto the one plane, the line of
// two or the point of three (exact rationals); a vertex of more groups, or one that would
// move by more than 64 delta (planes nearly parallel), stays.
#pragma once

#include <cstddef>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct SnappedPlanes {
  ExactTriangleSoup soup;  // the input with snapped vertices (rationals), triangles and
                           // provenance unchanged, no polygon ids (a move may fold a polygon)
  std::size_t groups = 0;  // groups of layers made coplanar
  std::size_t moved = 0;   // vertices moved
  double max_move = 0;     // an upper bound of the largest distance a vertex moved
};

// delta > 0. Cost: one search of the pairs of widened boxes (tritri::overlapping_triangle_pairs),
// an interval filter and exact tests on them, O(1) rational work per vertex moved.
SnappedPlanes snap_near_coplanar_faces(const TriangleSoup& input, double delta, int threads);

}  // namespace arrangements
