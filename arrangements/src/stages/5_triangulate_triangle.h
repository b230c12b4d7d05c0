// arrangements/src/stages/5_triangulate_triangle.h (internal to stage 5)
//
// split_triangle_of(soup, graph, t): the constrained triangulation of one soup triangle t
// by its intersection points and constraint segments (and those of its coplanar
// partners), built by point insertion and constraint insertion with edge flips (Sloan's
// algorithm). Returns a Piece: the local triangles (graph point ids, or -1 - k for the
// k-th new TPI of this triangle, where two constraints cross), the new TPIs, and for a
// triangle shared with coplanar partners, which soup triangles cover each local triangle.
// Exactness: every decision is orient2d on implicit points in a projection where t is not
// degenerate (checked exactly), through tritri's filtered exact predicates on offset
// points; TPIs are implicit (never rounded).
// Cost: per triangle, O(n log n)-ish expected point insertion by walking plus constraint
// insertion by edge flips (worst case quadratic in the triangle's points).
#pragma once

#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

// What one input triangle contributes.
struct Piece {
  std::vector<Tri> triangles;               // local ids: < 0 means new TPI (-1 - k), else graph id
  std::vector<tritri::ImplicitPoint> tpis;  // the new TPIs, local numbering
  std::vector<int> covered_by;              // per triangle: -1 for t itself only, else index into covers
  std::vector<std::vector<int>> covers;     // distinct sets of soup triangles covering (t included)
};

Piece split_triangle_of(const TriangleSoup& soup, const IntersectionGraph& g, int t);

}  // namespace arrangements
