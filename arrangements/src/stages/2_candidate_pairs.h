// arrangements/src/stages/2_candidate_pairs.h
//
// Stage 2 of the pipeline: the pairs of triangles that may intersect.
//
// std::vector<std::pair<int, int>> candidate_pairs(V, F, threads = 0, polygon = {})
//   V, F     the preprocessed soup's vertices and triangles (stage 1: finite, in range)
//   threads  worker threads; <= 0: all cores; at most kMaxThreads (thread_count.h, else
//            std::invalid_argument)
//   polygon  #F or empty: TriangleSoup::polygon (triangles of one polygon face, known to
//            meet only in shared corners and edges, share an id >= 0)
// returns every pair (i, j), i < j, of triangles whose closed axis-aligned bounding boxes
// overlap, sorted, each once; except pairs of one polygon face: a face with n corners
// would otherwise give up to n^2 / 2 pairs (its triangles may all share a corner), none of
// which can intersect. Pairs that share mesh vertices are included: they can still
// intersect away from what they share; stage 3 settles most of them cheaply.
// This is tritri::overlapping_triangle_pairs (tritri/box_pairs.h: method, exactness,
// cost), the search the batch API uses too.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads = 0,
                                                 std::span<const std::int64_t> polygon = {});

}  // namespace arrangements
