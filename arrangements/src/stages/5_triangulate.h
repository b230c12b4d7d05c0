// arrangements/src/stages/5_triangulate.h
//
// Stage 6 of the pipeline: split every triangle that has intersection points or
// constraint segments, exactly.
//
// Triangulation triangulate(soup, graph)
//   soup   the preprocessed soup (merged vertices, no degenerate or duplicate triangles)
//   graph  its intersection graph after propagate_coplanar
// returns
//   points       graph.points followed by the new TPIs (crossings of two constraint
//                segments inside a triangle; distinct from each other and from every
//                graph point, compared exactly)
//   num_tpi      the number of new TPIs
//   triangles    the output triangles (indices into points); a triangle without points
//                or constraints is copied as it is
//   owner        per output triangle, the soup triangle it lies in (for a region covered
//                by several coplanar triangles: the smallest such triangle id; the region
//                is emitted once)
//   label_set / label_sets   per output triangle, the union of the label sets of every soup
//                triangle that covers it
// Exactness: every decision is orient2d on implicit points in the triangle's dominant
// axis projection (largest normal component; checked exactly to be non-degenerate),
// through tritri's filtered exact predicates on offset points; TPIs are implicit.
// Output does not depend on the number of threads.
// Cost: per triangle, O(n log n)-ish expected point insertion by walking plus constraint
// insertion by edge flips (worst case quadratic in the triangle's points); parallel over
// triangles (TBB).
#pragma once

#include <cstddef>
#include <vector>

#include <tritri/implicit_point.h>

#include "stages/4_intersection_graph.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

struct Triangulation {
  std::vector<tritri::ImplicitPoint> points;
  std::size_t num_tpi = 0;
  std::vector<Tri> triangles;
  std::vector<int> owner;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
};

Triangulation triangulate(const TriangleSoup& soup, const IntersectionGraph& graph);

}  // namespace arrangements
