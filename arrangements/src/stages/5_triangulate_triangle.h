// arrangements/src/stages/5_triangulate_triangle.h (internal to stage 5)
//
// split_triangle_of<M>(soup, graph, t), for a point model M (models/point_model.h): the
// constrained triangulation of one soup triangle t by its intersection points and
// constraint segments (and those of its coplanar partners), built by point insertion and
// constraint insertion with edge flips (Sloan's algorithm). Returns a Piece: the local
// triangles (graph point ids, or -1 - k for the k-th new TPI of this triangle, where two
// constraints cross), the new TPIs, and for a triangle shared with coplanar partners,
// which soup triangles cover each local triangle.
// Exactness: every decision is orient2d on the model's points in a projection where t is
// not degenerate (checked exactly): DoubleModel, tritri's filtered exact predicates on
// offset implicit points (TPIs implicit, never rounded); ExactModel, Epeck's.
// Cost: per triangle, O(n log n)-ish expected: interior points inserted by walking, then
// the constraints in a shuffled order, each right after its endpoints (edge points are
// inserted when first needed, so each splits only the region between the constraints
// around it: a randomized incremental construction), by edge flips; worst case quadratic
// in the triangle's points.
#pragma once

#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

// What one input triangle contributes.
template <class Point>
struct Piece {
  std::vector<Tri> triangles;               // local ids: < 0 means new TPI (-1 - k), else graph id
  std::vector<Point> tpis;                  // the new TPIs, local numbering
  std::vector<int> covered_by;              // per triangle: -1 for t itself only, else index into covers
  std::vector<std::vector<int>> covers;     // distinct sets of soup triangles covering (t included)
};

// points_along_edge<M>(g, from, to, e): the points strictly inside edge e of the graph
// (from corner `from` to corner `to`), in order from `from`: sorted by the model's exact
// order, which is monotone along any line (tritri::compare_along_direction: a projection,
// ties by xyz; intervals settle it where xyz would meet exact ties on axis-parallel
// edges). O(k log k) comparisons for k points.
template <class M>
std::vector<int> points_along_edge(const BasicIntersectionGraph<typename M::Point>& g, int from, int to, int e);

template <class M>
Piece<typename M::Point> split_triangle_of(const BasicTriangleSoup<typename M::Vertex>& soup,
                                           const BasicIntersectionGraph<typename M::Point>& g, int t);

}  // namespace arrangements
