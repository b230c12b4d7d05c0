// arrangements/src/stages/4_intersection_graph.h
//
// IntersectionGraph: the classified intersections of a triangle soup, ready for
// triangulation. build_intersection_graph merges the per-pair records of any classifier.
//
// Points (M::Point of the point model: implicit over doubles, or rational): ids
// [0, num_input_vertices) are the input vertices (explicit); the others are new LPIs,
// each geometrically distinct from every other point and from every input vertex
// (deduplicated exactly: first by definition, then by exact coordinate comparison).
// Per triangle t: triangle_points[t] the points strictly inside it; edge_points[e] for
// each of its edges e = triangle_edges[t][k] the points strictly inside that edge (edges
// are shared between triangles); triangle_segments[t] the constraint segments (point id
// pairs, smaller id first) that lie in it, except those along its own edges (the edge
// already bounds it; the segment's points are on the edge); coplanar_partners[t] the
// triangles that overlap
// it in a common plane. Coplanar partners also receive each other's points and segments
// (inside the partner's closed triangle), so that both are split alike.
// segment_supports: for every distinct constraint segment (a, b), for each pair that
// reports it (distinct records only), two planes whose
// intersection is the segment's line, each as three vertex ids (an id below 0 stands for
// the auxiliary point of triangle -1 - id, see 3_pair_intersection.h); triangulation builds
// the TPI where two constraints cross from the triangle's plane and, for each constraint,
// one of its planes that is transverse to that triangle. For a non-coplanar pair they are
// the two triangles' planes; for a coplanar pair, the common plane and the plane through
// the edge the segment runs along and the auxiliary point of that edge's triangle.
// All lists are sorted and unique: the graph does not depend on thread count.
#pragma once

#include <array>
#include <vector>

#include <tritri/implicit_point.h>

#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"
#include "models/double_model.h"

namespace arrangements {

struct SegmentSupport {
  std::array<int, 2> ends;
  std::array<std::array<int, 3>, 2> planes;
  friend auto operator<=>(const SegmentSupport&, const SegmentSupport&) = default;
  friend bool operator==(const SegmentSupport&, const SegmentSupport&) = default;
};

template <class Point>
struct BasicIntersectionGraph {
  int num_input_vertices = 0;
  std::vector<Point> points;
  std::vector<std::array<int, 2>> edges;           // unique undirected edges, smaller id first
  std::vector<std::array<int, 3>> triangle_edges;  // edge id of each triangle's edge k
  std::vector<std::vector<int>> edge_points;
  std::vector<std::vector<int>> triangle_points;
  std::vector<std::vector<std::array<int, 2>>> triangle_segments;
  std::vector<std::vector<int>> coplanar_partners;
  std::vector<SegmentSupport> segment_supports;  // sorted (by ends first), unique
  std::vector<int> new_points_sorted;            // ids of the new points in the model's order (M::compare)

  // Statistics.
  std::size_t intersecting_pairs = 0;
  std::size_t coplanar_pairs = 0;
  std::size_t new_points = 0;  // distinct new points (LPIs)
  std::size_t segments = 0;    // distinct constraint segments over all triangles
};

using IntersectionGraph = BasicIntersectionGraph<tritri::ImplicitPoint>;

// build_intersection_graph<M>, for a point model M (models/point_model.h); without M,
// DoubleModel.
// Inputs:  V, F the preprocessed soup (merged vertices, no degenerate triangles);
//          pairs the records of intersecting pairs (classify_pairs).
//          share: run share_coplanar (4_share_coplanar.h) at the end; false only to test
//          that step on its own.
// Output:  the graph. Exact. Cost: O(P log P) for P new points plus the records.
template <class M>
BasicIntersectionGraph<typename M::Point> build_intersection_graph(const std::vector<typename M::Vertex>& V,
                                                                   const std::vector<Tri>& F,
                                                                   const PairRecords& pairs, bool share = true);

inline IntersectionGraph build_intersection_graph(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                                  const PairRecords& pairs) {
  return build_intersection_graph<DoubleModel>(V, F, pairs);
}

}  // namespace arrangements
