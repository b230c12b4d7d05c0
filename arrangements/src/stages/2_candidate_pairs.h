// arrangements/src/stages/2_candidate_pairs.h
//
// Stage 2 of the pipeline: the pairs of triangles that may intersect beyond what they
// share, found and filtered in one pass, without a list of every box-overlapping pair.
//
// detect_pairs<M>(V, F, threads, polygon), for a point model M (models/point_model.h);
// detect_pairs(V, F, ...) on double vertices is detect_pairs<DoubleModel>.
//   V, F     the preprocessed soup's vertices and triangles (stage 1: finite, in range,
//            vertices merged, so equal indices are equal points and no triangle is
//            degenerate)
//   threads  worker threads; <= 0: all cores; at most kMaxThreads (thread_count.h, else
//            std::invalid_argument)
//   polygon  #F or empty: TriangleSoup::polygon (triangles of one polygon face, known to
//            meet only in shared corners and edges, share an id >= 0; never paired)
// returns `pairs`: every pair (i, j), i < j, whose closed bounding boxes overlap and that
// the embedded stars and the exact early-outs below do not settle, sorted, each once;
// `box_pairs`: how many pairs the broad phase kept for the early-outs (the stat
// candidate_pairs); `planes`: one
// M::PlaneCache per triangle (DoubleModel: tritri::PlaneFilter; stage 3 reuses them);
// `coplanar`: the pairs of `pairs` whose triangles lie in one plane (known from the
// early-outs' plane signs), for the coplanar-cluster budget (2_coplanar_budget.h).
// Search: tritri::for_each_candidate_pair for doubles (tritri/hub_pairs.h: the box pairs,
// except that the triangles around a vertex of high degree are paired by their directions
// from it, so a fan is not paired all to all; a pair left out meets only in that vertex),
// tritri::for_each_overlapping_pair on the certified intervals of rational points.
// Neighbours (doubles): a box pair of triangles sharing a vertex whose star is embedded
// (tritri/embedded_stars.h: the fan around it, in one projection, turns once around it, so
// its triangles meet only in what they share) is settled at once. On a clean mesh that is
// every vertex, and neighbours are almost all box pairs (bunny, 75 k triangles: 466 k of
// 472 k); a few orient2d per corner replace a pairwise test per pair. The grid search skips
// them itself (tritri::embedded_corner_keys: keys beside the boxes in its cells), so they
// cost no visit; the other searches leave them to the visit, after the slabs.
// Broad phase: a box pair is dropped when the triangles' extents along 10 diagonal
// directions are apart (tritri::TriangleSlabsOnDemand, tritri/direction_slabs.h: a
// certified test, such triangles do not meet; computed per triangle on first use; rational
// points: from their certified boxes). Long thin triangles lying across their boxes'
// diagonals make most box pairs: EMBER 79741+65004 has 16.7 M box pairs, of which 0.45 M
// are kept.
// Early-outs, as each pair is found (in parallel; stages/2_early_outs.h, which
// check_arrangement shares):
//   - neighbours (a shared vertex or edge by index) that provably meet only in what they
//     share: tritri::meet_only_in_shared_by_sides, 1 to 4 plane signs;
//   - other pairs where one triangle lies strictly on one side of the other's plane:
//     tritri::separated_by_plane, 2 to 6 plane signs, the first test of every classifier;
//   - coplanar pairs (every free corner of one in the other's plane): neighbours that
//     meet only in what they share, and disjoint pairs, by orient2d in a projection
//     (tritri::meet_in_shared_in_projection, tritri::separated_in_projection); flat CAD faces
//     give many of these;
//   - a triangle touching the other's plane at a vertex or edge that misses the other
//     (tritri::touches_only_in_shared);
//   - pairs that straddle each other's planes but whose projections onto an axis plane
//     are disjoint, or meet only in what the two share (tritri::separated_in_projection,
//     tritri::meet_in_shared_in_projection): long CAD triangles, vertex neighbours around
//     saddle vertices.
// Either way the classifiers would report nothing for the pair, so dropping it here
// changes no result. Plane signs come from one tritri::PlaneFilter per triangle
// (tritri/plane_filter.h: exact; decisive for slivers) with orient3d as the fallback; for
// doubles the projection test runs before the first sign the filter leaves undecided (an
// exact orient3d, exactly zero where parts touch in a plane, costs far more than orient2d).
// Exact: every decision is an exact sign. The result does not depend on `threads`.
// Cost: the search (tritri/box_pairs.h, hub_pairs.h) plus O(1) per pair, and O(n) for the
// stars; memory: 44 bytes per triangle (planes, keys), 96 per triangle whose slabs are used,
// 8 per corner while the stars are certified, plus the pairs kept (usually a small fraction
// of the box pairs).
//
// candidate_pairs(V, F, threads = 0, polygon = {}): the box pairs alone, as a sorted list
// (tritri::overlapping_triangle_pairs), for tests and tools that want them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <tritri/plane_filter.h>

#include "arrangements/triangle_soup.h"
#include "models/double_model.h"

namespace arrangements {

template <class M>
struct BasicDetectedPairs {
  std::vector<std::pair<int, int>> pairs;         // to classify, sorted
  std::vector<std::pair<int, int>> coplanar;      // those of them in one plane, sorted
  std::size_t box_pairs = 0;                      // pairs kept by the broad phase (slabs, stars)
  std::vector<typename M::PlaneCache> planes;     // M::plane_cache of each triangle, for stage 3
};
using DetectedPairs = BasicDetectedPairs<DoubleModel>;

// coplanar_budget: apply the coplanar-cluster budget (2_coplanar_budget.h; the pipeline
// does, checks of other meshes do not): throws its InputError (too_large) for the kept
// coplanar pairs. Each thread also checks its own coplanar pairs whenever their number
// doubles (from 2^14): they are a subset of the final ones, which hold at least as many
// triples, so a refusal there is sound and comes before the rest of the search (3,000
// wedges through one region: 4.5 M box pairs, each with exact early-outs; refused in 0.05 s,
// 1.2 s when only the final pairs were counted). The one exception to results that do not
// depend on `threads`: input over the budget whose final count gives up (kMaxTripleWork
// steps without reaching the budget) may be refused by a thread's earlier count or not.
template <class M>
BasicDetectedPairs<M> detect_pairs(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F, int threads,
                                   std::span<const std::int64_t> polygon = {}, bool coplanar_budget = false);

inline DetectedPairs detect_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads,
                                  std::span<const std::int64_t> polygon = {}, bool coplanar_budget = false) {
  return detect_pairs<DoubleModel>(V, F, threads, polygon, coplanar_budget);
}

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads = 0,
                                                 std::span<const std::int64_t> polygon = {});

}  // namespace arrangements
