// arrangements/src/stages/2_candidate_pairs.h
//
// Stage 4 of the pipeline: the pairs of triangles that may intersect.
//
// std::vector<std::pair<int, int>> candidate_pairs(V, F, threads = 0, polygon = {})
//   V        #V list of vertex coordinates (finite)
//   F        #F list of triangles, indices into V
//   threads  worker threads; <= 0: all cores; at most kMaxThreads (thread_count.h)
//   polygon  #F or empty: TriangleSoup::polygon (triangles of one polygon face, known to
//            meet only in shared corners and edges, share an id >= 0)
// returns every pair (i, j), i < j, of triangles whose closed axis-aligned bounding boxes
// overlap (boxes that only touch count), sorted lexicographically, each pair once; except
// pairs of one polygon face (same id >= 0): a face with n corners would otherwise give up
// to n^2 / 2 pairs (its triangles may all share a corner), none of which can intersect.
//
// Pairs that share mesh vertices are included: they can still intersect away from what
// they share, and the classifier decides what a shared vertex or edge contributes.
// Bounding boxes are exact (minima and maxima of the corners' coordinates), so no pair
// that touches is missed.
//
// Computed with CGAL's box_intersection_d segment tree (closed boxes). In parallel (oneTBB,
// inside a tbb::task_arena of `threads` threads, so the rest of the program keeps its own
// parallelism) the boxes are sorted by xmin and cut into chunks, one task per chunk (see
// candidate_pairs.cpp); below ~4000 triangles, or with one thread, one sequential call.
// The result does not depend on `threads`. Memory: about 3 copies of 64 bytes per triangle,
// plus the pairs.
// Throws std::invalid_argument for an index out of range or a non-finite coordinate.
// Cost: O(n log^3 n + k) expected for n triangles and k pairs (CGAL's segment tree).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F,
                                                 int threads = 0, std::span<const std::int64_t> polygon = {});

}  // namespace arrangements
