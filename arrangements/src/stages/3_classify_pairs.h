// arrangements/src/stages/3_classify_pairs.h
//
// classify_pairs: runs a pair classifier over all candidate pairs, in parallel (TBB), and
// keeps the pairs that intersect beyond what they share in the mesh.
//
// Inputs:  V, F the preprocessed soup; pairs candidate pairs (i < j); classifier which
//          classifier; threads (<= 0: all cores).
// Output:  one PairIntersection per intersecting pair, in the order of `pairs`
//          (deterministic for any number of threads), as PairRecords (the loop's chunks,
//          not concatenated).
// Pairs that share vertices and meet only there give no record (the classifiers drop
// them); in the pipeline stage 2 has already dropped most of them (detect_pairs).
// counts: null (the default) runs every predicate on tritri::DoubleKernel, nothing
// counted; otherwise every predicate of the classifiers runs
// through a tritri::CountingKernel over it, one PredicateCounts per chunk of pairs, and
// their sums are added to *counts.
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
#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

PairRecords classify_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                           const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                           tritri::PredicateCounts* counts = nullptr, std::span<const tritri::PlaneFilter> planes = {});

}  // namespace arrangements
