// arrangements/src/stages/3_classify_pairs.h
//
// classify_pairs: runs a pair classifier over all candidate pairs, in parallel (TBB), and
// keeps the pairs that intersect beyond what they share in the mesh.
//
// Inputs:  V, F the preprocessed soup; pairs candidate pairs (i < j); classifier which
//          classifier; threads (<= 0: all cores).
// Output:  one PairIntersection per intersecting pair, in the order of `pairs`
//          (deterministic for any number of threads).
// Neighbours first: a pair that shares a vertex or an edge (by index; V is merged) and
// provably meets only there (tritri::meet_only_in_shared, 1 to 4 exact orient3d) is
// dropped without classification, as the classifier would drop it; most candidate pairs
// of a mesh are such neighbours.
// counts: null (the default) runs every predicate on tritri::DoubleKernel, nothing
// counted; otherwise every predicate of this stage (neighbour tests and classifiers) runs
// through a tritri::CountingKernel over it, one PredicateCounts per chunk of pairs, and
// their sums are added to *counts.
// Cost: O(#pairs) classifications, parallel.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <tritri/counting_kernel.h>

#include "arrangements/arrange.h"
#include "stages/3_pair_intersection.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

std::vector<PairIntersection> classify_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                             const std::vector<std::pair<int, int>>& pairs, Classifier classifier,
                                             tritri::PredicateCounts* counts = nullptr);

}  // namespace arrangements
