// Stage 2: box pairs filtered by exact early-outs as they are found (see 2_candidate_pairs.h).
#include "stages/2_candidate_pairs.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <stdexcept>
#include <string>
#include <type_traits>

#include <tritri/box_pairs.h>
#include <tritri/hub_pairs.h>
#include <tritri/shared_vertices.h>

#include "arrangements/memory_budget.h"
#include "arrangements/thread_count.h"
#include "models/exact_model.h"

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
                                   std::span<const std::int64_t> polygon) {
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
  };
  tbb::enumerable_thread_specific<Found> found;
  const VertexBoxes<M> boxes(V);
  auto visit = [&](int i, int j) {
    detail::memory_checkpoint();
    Found& local = found.local();
    ++local.box_pairs;
    const Tri& a = F[i];
    const Tri& b = F[j];
    int in_b[3];
    const bool shares = tritri::detail::shared_corners(a, b, in_b) > 0;
    // Projections that meet only in what the two share (or not at all) rule out other
    // contact, for any pair (tritri/shared_vertices.h).
    auto in_projection = [&] {
      const typename M::Kernel k;
      const std::array<Vertex, 3> pa{V[a[0]], V[a[1]], V[a[2]]}, pb{V[b[0]], V[b[1]], V[b[2]]};
      return shares ? tritri::meet_in_shared_in_projection(k, pa, a, pb, b) : tritri::separated_in_projection(k, pa, pb);
    };
    // side(t, k): corner k of the other triangle against the plane of triangle t (0: a),
    // each evaluated at most once.
    tritri::Sign known[2][3];
    bool have[2][3] = {};
    // Whether the projection test ran (before the first plane sign the filter left
    // undecided: an exact orient3d costs far more than the orient2d of a projection, and
    // exactly coplanar contacts, common where parts touch, are all such signs), and
    // whether it settled the pair, in which case the plane tests' answers are discarded.
    bool projection_tried = false, settled_in_projection = false;
    auto side = [&](int t, int corner) {
      if (!have[t][corner]) {
        const Tri& p = t == 0 ? a : b;
        const Tri& o = t == 0 ? b : a;
        const auto& plane = planes[t == 0 ? i : j];
        if constexpr (!M::kProjectionFirst) {
          if (const auto s = M::certified_side_of_plane(plane, V[p[0]], V[o[corner]])) {
            known[t][corner] = *s;
            have[t][corner] = true;
            return *s;
          }
          if (settled_in_projection) return tritri::Sign::Zero;  // discarded
          if (!projection_tried) {
            projection_tried = true;
            settled_in_projection = in_projection();
            if (settled_in_projection) return tritri::Sign::Zero;  // discarded
          }
        }
        known[t][corner] = M::side_of_plane(plane, V[p[0]], V[p[1]], V[p[2]], V[o[corner]]);
        have[t][corner] = true;
      }
      return known[t][corner];
    };
    // Coplanar: b's free corners (not shared with a) all in plane(a). Usually a known
    // nonzero sign answers at once.
    auto coplanar = [&] {
      for (int c = 0; c < 3; ++c)
        if (b[c] != a[0] && b[c] != a[1] && b[c] != a[2] && side(0, c) != tritri::Sign::Zero) return false;
      return true;
    };
    if constexpr (M::kProjectionFirst) {
      // Projections first: for rational points an exact zero (coplanar pieces of one
      // input triangle, common in an arrangement arranged again) costs far more than the
      // orient2d that the intervals decide.
      projection_tried = true;
      if (in_projection()) return;
    }
    bool settled = shares ? tritri::meet_only_in_shared_by_sides(a, b, side) : tritri::separated_by_plane(side);
    if (settled_in_projection) return;
    bool flat = false;  // every kept pair gets here unsettled, so flat is known for it
    if (!settled) {
      const typename M::Kernel k;
      const std::array<Vertex, 3> pa{V[a[0]], V[a[1]], V[a[2]]}, pb{V[b[0]], V[b[1]], V[b[2]]};
      flat = coplanar();
      if (settled_in_projection) return;
      if (!flat) {  // one triangle touching the other's plane without crossing it
        const tritri::Sign sb[3] = {side(0, 0), side(0, 1), side(0, 2)};
        if (settled_in_projection) return;
        settled = tritri::touches_only_in_shared(k, pa, a, pb, b, sb);
        if (!settled) {  // a's signs only now: most pairs are settled by b's
          const tritri::Sign sa[3] = {side(1, 0), side(1, 1), side(1, 2)};
          if (settled_in_projection) return;
          settled = tritri::touches_only_in_shared(k, pb, b, pa, a, sa);
        }
      }
      // Coplanar, or each straddling the other's plane: projections that meet only in what
      // the two share (or not at all) rule out other contact.
      if (!settled && !projection_tried) settled = in_projection();
    }
    if (settled) return;
    if (local.chunks.empty() || local.chunks.back().size() == kChunk) {
      local.chunks.emplace_back();
      local.chunks.back().reserve(kChunk);
    }
    local.chunks.back().emplace_back(i, j);
    if (flat) local.coplanar.emplace_back(i, j);
  };
  // Doubles: the triangles around a hub vertex are paired by their directions from it
  // (tritri/hub_pairs.h: a fan of n triangles makes O(n) pairs, not n^2 / 2); rational
  // points: every box pair of their certified intervals.
  if constexpr (std::is_same_v<Vertex, Vec3>)
    tritri::for_each_candidate_pair(std::span<const Vec3>(V), F, threads, polygon, visit);
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
  return out;
}

template DetectedPairs detect_pairs<DoubleModel>(const std::vector<Vec3>&, const std::vector<Tri>&, int,
                                                 std::span<const std::int64_t>);
template BasicDetectedPairs<ExactModel> detect_pairs<ExactModel>(const std::vector<ExactModel::Vertex>&,
                                                                 const std::vector<Tri>&, int,
                                                                 std::span<const std::int64_t>);

std::vector<std::pair<int, int>> candidate_pairs(const std::vector<Vec3>& V, const std::vector<Tri>& F, int threads,
                                                 std::span<const std::int64_t> polygon) {
  check_threads(threads);
  return tritri::overlapping_triangle_pairs(V, F, threads, polygon);
}

}  // namespace arrangements
