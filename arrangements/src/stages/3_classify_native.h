// arrangements/src/stages/3_classify_native.h
//
// classify_pair_native: the pipeline's own classification of one candidate pair, the case
// analysis of Cherchi et al. 2020. With sB the orient3d signs of B's vertices against
// A's plane: all equal and non-zero: no intersection; all zero: coplanar, each edge of B
// is tested as a coplanar segment against A (and A's vertices inside B); two zeros: the
// edge of B in A's plane is a coplanar segment; one zero: the vertex may lie in A and, if
// the other two are on opposite sides, the opposite edge may cross A; no zeros: the two
// edges at the lonely vertex may cross A. Then the same for A against B, stopping as soon
// as two distinct points are known (non-coplanar pairs have at most two).
//
// Inputs:  k the predicates: a point model's kernel (models/point_model.h: DoubleKernel
//          or its PlaneCachedKernel, ExactModel::Kernel), or tritri::CountingKernel over it
//          to count the calls (classify_pairs picks one); without k, DoubleKernel. V
//          vertices (k's points), F triangles (no degenerate triangles, vertices merged
//          exactly), ta, tb the pair.
// Output:  out, filled when the triangles intersect beyond what they share in the mesh
//          (a common vertex or edge alone is not an intersection); returns whether so.
// Exactness: every decision is an exact double predicate (k.orient3d / k.orient2d);
//          new points are described by vertex ids, never constructed.
// Cost: O(1), at most a few dozen predicates.
#pragma once

#include <vector>

#include <tritri/counting_kernel.h>
#include <tritri/double_kernel.h>
#include <tritri/plane_filter.h>

#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

template <class K>
bool classify_pair_native(const K& k, const std::vector<typename K::Point>& V, const std::vector<Tri>& F, int ta,
                          int tb, PairIntersection& out);
extern template bool classify_pair_native(const tritri::DoubleKernel&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);
extern template bool classify_pair_native(const tritri::PlaneCachedKernel&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);
extern template bool classify_pair_native(const tritri::CountingKernel<tritri::DoubleKernel>&, const std::vector<Vec3>&,
                                          const std::vector<Tri>&, int, int, PairIntersection&);

inline bool classify_pair_native(const std::vector<Vec3>& V, const std::vector<Tri>& F, int ta, int tb,
                                 PairIntersection& out) {
  return classify_pair_native(tritri::DoubleKernel{}, V, F, ta, tb, out);
}

}  // namespace arrangements
