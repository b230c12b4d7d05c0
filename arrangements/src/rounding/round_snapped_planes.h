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
// triangle. A group whose triangles all lie within delta of the plane of a neighbouring
// layered group (boxes overlapping) joins it, the larger anchor's plane kept: linked only
// through small triangles, whose planes tilt with their rounding errors, one face would
// otherwise get nearly parallel planes (a turned CSG model: vertices on two of them would
// stay, its layers crossing again). Every vertex of a group moves onto its plane: onto the
// one plane, the line of two or the point of three (exact rationals); a vertex of more
// groups, or one that would move by more than 64 delta (planes nearly parallel), stays.
//
// With `contacts`, contacts the transforms broke are made exact too: a part whose edge or
// vertex lay on another's face (an edge of one triangle in the plane of another, as in
// Cherchi's sc2 test) lies 1e-17 off it once turned, and its exact arrangement cuts slivers
// 1e-17 wide along the whole edge, which no rounding holds. A corner of one triangle touches
// another when it lies within delta of the other's plane, is not one of its corners (nor at
// the position of one), and lies in its box (widened by delta) or on an edge whose other end
// lies within delta of the plane too; the touched triangle's group is then made flat like a
// layered one, and the corner moves onto that plane as well (with the planes of its own
// groups: the line of two, the point of three).
#pragma once

#include <cstddef>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct SnappedPlanes {
  ExactTriangleSoup soup;  // the input with snapped vertices (rationals), triangles and
                           // provenance unchanged, no polygon ids (a move may fold a polygon)
  std::size_t groups = 0;  // groups made flat: of layers, or (with contacts) touched by a corner
  std::size_t moved = 0;   // vertices moved
  double max_move = 0;     // an upper bound of the largest distance a vertex moved
};

// delta > 0. Cost: one search of the pairs of widened boxes (tritri::overlapping_triangle_pairs),
// an interval filter and exact tests on them, O(1) rational work per vertex moved; joining
// groups, a pass over those pairs per round (a few) and three tests per triangle of a group
// each time it is tried.
SnappedPlanes snap_near_coplanar_faces(const TriangleSoup& input, double delta, int threads, bool contacts);

}  // namespace arrangements
