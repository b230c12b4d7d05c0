// Stage 2: box pairs filtered by exact early-outs as they are found (see 2_candidate_pairs.h).
#include "stages/2_candidate_pairs.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <tritri/box_pairs.h>
#include <tritri/direction_slabs.h>
#include <tritri/embedded_stars.h>
#include <tritri/hub_pairs.h>

#include "arrangements/memory_budget.h"
#include "arrangements/thread_count.h"
#include "models/exact_model.h"
#include "stages/2_coplanar_budget.h"
#include "stages/2_early_outs.h"

namespace arrangements {
namespace {

void check_threads(int threads) {
  if (threads > kMaxThreads)
    throw std::invalid_argument("candidate_pairs: threads must be at most " + std::to_string(kMaxThreads));
}

// Every vertex's box: the vertices themselves for doubles (no copy), certified intervals
// otherwise.
template <class M>
struct VertexBoxes {
  std::vector<Vec3> lo, hi;
  std::span<const Vec3> lo_span, hi_span;
  explicit VertexBoxes(const std::vector<typename M::Vertex>& V) {
    if constexpr (std::is_same_v<typename M::Vertex, Vec3>) {
      lo_span = hi_span = V;
    } else {
      lo.resize(V.size());
      hi.resize(V.size());
      for (std::size_t v = 0; v < V.size(); ++v) M::bounds(V[v], lo[v], hi[v]);
      lo_span = lo;
      hi_span = hi;
    }
  }
};

}  // namespace

template <class M>
BasicDetectedPairs<M> detect_pairs(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F, int threads,
                                   std::span<const std::int64_t> polygon, bool coplanar_budget) {
  using Vertex = typename M::Vertex;
  check_threads(threads);
  BasicDetectedPairs<M> out;
  std::vector<typename M::PlaneCache>& planes = out.planes;
  planes.resize(F.size());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, F.size(),
                      [&](std::size_t t) { planes[t] = M::plane_cache(V[F[t][0]], V[F[t][1]], V[F[t][2]]); });
  });

  // Kept pairs in fixed-size chunks per thread: no doubling slack, and the chunks are freed
  // one by one as they are gathered (peak memory: the pairs once, plus one chunk).
  using Pairs = std::vector<std::pair<int, int>>;
  constexpr std::size_t kChunk = 1 << 14;
  struct Found {
    std::vector<Pairs> chunks;
    Pairs coplanar;  // the kept pairs that lie in one plane (few, usually)
    std::size_t box_pairs = 0;
    std::size_t next_budget_check = std::size_t{1} << 14;  // coplanar pairs (coplanar_budget)
  };
  // ets_key_per_instance: local() is a native thread-local lookup, not a hash of the
  // thread id (which cost 6% of detection on pairs that a box search yields by millions).
  tbb::enumerable_thread_specific<Found, tbb::cache_aligned_allocator<Found>, tbb::ets_key_per_instance> found;
  const VertexBoxes<M> boxes(V);
  // Every triangle's extents along 10 diagonal directions (tritri/direction_slabs.h; rational
  // points: from their certified boxes), a certified test after the boxes' that rejects most
  // box pairs of long thin triangles. Computed on first use: on a clean mesh most triangles
  // are in no pair that reaches the test.
  const tritri::TriangleSlabsOnDemand slabs(boxes.lo_span, boxes.hi_span, F);
  // Doubles: vertices whose star is embedded (tritri/embedded_stars.h) settle every pair of
  // their neighbours at once; on a clean mesh that is almost every box pair. The search skips
  // most of them itself (keys: the corners, the unembedded ones unique), in the grid's cells
  // where the keys sit beside the boxes; visit settles the others after the slabs (where the
  // grid declines, on crowded inputs, most pairs are apart by their slabs).
  std::vector<std::uint8_t> embedded;
  std::vector<std::array<int, 3>> keys;
  if constexpr (std::is_same_v<Vertex, Vec3>) {
    embedded = tritri::embedded_stars(V, F, threads);
    keys = tritri::embedded_corner_keys(F, embedded);
  }
  auto visit = [&](int i, int j) {
    if (slabs.apart(static_cast<std::size_t>(i), static_cast<std::size_t>(j))) return;
    if constexpr (std::is_same_v<Vertex, Vec3>)
      if (tritri::share_embedded_star(F[i], F[j], embedded)) return;
    detail::memory_checkpoint();
    Found& local = found.local();
    ++local.box_pairs;
    const EarlyOut decided = early_out<M>(V, F, planes, i, j);
    if (decided.settled) return;
    if (local.chunks.empty() || local.chunks.back().size() == kChunk) {
      local.chunks.emplace_back();
      local.chunks.back().reserve(kChunk);
    }
    local.chunks.back().emplace_back(i, j);
    if (!decided.flat) return;
    local.coplanar.emplace_back(i, j);
    if (coplanar_budget && local.coplanar.size() >= local.next_budget_check) {
      local.next_budget_check *= 2;
      Pairs sorted = local.coplanar;
      std::sort(sorted.begin(), sorted.end());
      refuse_huge_coplanar_clusters(F.size(), sorted);
    }
  };
  // Doubles: the triangles around a hub vertex are paired by their directions from it
  // (tritri/hub_pairs.h: a fan of n triangles makes O(n) pairs, not n^2 / 2); rational
  // points: every box pair of their certified intervals.
  if constexpr (std::is_same_v<Vertex, Vec3>)
    tritri::for_each_candidate_pair(std::span<const Vec3>(V), F, threads, polygon, visit, keys);
  else
    tritri::for_each_overlapping_pair(boxes.lo_span, boxes.hi_span, F, threads, polygon, visit);

  std::size_t kept = 0;
  for (const Found& f : found) {
    out.box_pairs += f.box_pairs;
    for (const Pairs& c : f.chunks) kept += c.size();
  }
  out.pairs.reserve(kept);
  for (Found& f : found) {
    for (Pairs& c : f.chunks) {
      out.pairs.insert(out.pairs.end(), c.begin(), c.end());
      Pairs().swap(c);
    }
    out.coplanar.insert(out.coplanar.end(), f.coplanar.begin(), f.coplanar.end());
  }
  arena.execute([&] {
    tbb::parallel_sort(out.pairs.begin(), out.pairs.end());
    tbb::parallel_sort(out.coplanar.begin(), out.coplanar.end());
  });
  if (coplanar_budget) refuse_huge_coplanar_clusters(F.size(), out.coplanar);
  return out;
}

template DetectedPairs detect_pairs<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&, int,
                                                 std::span<const std::int64_t>, bool);
template BasicDetectedPairs<ExactModel> detect_pairs<ExactModel>(const std::vector<ExactModel::Vertex>&,
                                                                 const std::vector<Tri>&, int,
                                                                 std::span<const std::int64_t>, bool);

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads,
                                                 std::span<const std::int64_t> polygon) {
  check_threads(threads);
  return tritri::overlapping_triangle_pairs(V, F, threads, polygon);
}

}  // namespace arrangements
