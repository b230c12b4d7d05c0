// arrangements/src/stages/3_classify_pairs.h
//
// classify_pairs: runs a pair classifier over all candidate pairs, in parallel (TBB), and
// keeps the pairs that intersect beyond what they share in the mesh.
//
// classify_pairs<M> for a point model M (models/point_model.h); without M, DoubleModel.
// Inputs:  V, F the preprocessed soup; pairs candidate pairs (i < j); classifier which
//          classifier; threads (<= 0: all cores).
// Output:  one PairIntersection per intersecting pair, in the order of `pairs`
//          (deterministic for any number of threads), as PairRecords (the loop's chunks,
//          not concatenated).
// Pairs that share vertices and meet only there give no record (the classifiers drop
// them); in the pipeline stage 2 has already dropped most of them (detect_pairs).
// counts: null (the default) runs every predicate on M::Kernel, nothing counted; otherwise
// every predicate of the classifiers runs through a tritri::CountingKernel over it, one
// PredicateCounts per chunk of pairs, and their sums are added to *counts.
// planes: empty, or #F cached planes (tritri::plane_filter of each triangle, as stage 2
// computes them): then, when not counting, each pair is classified with
// tritri::PlaneCachedKernel, whose answers are DoubleKernel's, found cheaper.
// Cost: O(#pairs) classifications, parallel.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include <tritri/counting_kernel.h>
#include <tritri/plane_filter.h>

#include "arrangements/arrange.h"
#include "models/double_model.h"
#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

template <class M>
PairRecords classify_pairs(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                           const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                           tritri::PredicateCounts* counts = nullptr,
                           std::span<const typename M::PlaneCache> planes = {});

inline PairRecords classify_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                  const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                                  tritri::PredicateCounts* counts = nullptr,
                                  std::span<const tritri::PlaneFilter> planes = {}) {
  return classify_pairs<DoubleModel>(V, F, pairs, classifier, counts, planes);
}

}  // namespace arrangements
