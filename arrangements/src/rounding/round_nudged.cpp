// nudge_conflicts (round_nudged.h): moving the corners of violating pairs by 1 to 1024 steps
// of the grid, one at a time, wherever that leaves fewer violations.
#include "rounding/round_nudged.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tritri/double_kernel.h>
#include <tritri/implicit_kernel.h>
#include <tritri/projection.h>

#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "support/pair_fault.h"
#include "rounding/rounding_grid.h"
#include "rounding/violation_tracker.h"

namespace arrangements {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int, CGAL::Box_intersection_d::ID_EXPLICIT>;
constexpr int kFarthest = 1 << 10;  // steps: the positions tried are 1, 2, 4, ... steps around a corner

// The 26 offsets one step around a point, times 1, 2, 4, ..., kFarthest.
std::vector<Vec3> offsets(double step) {
  std::vector<Vec3> out;
  for (int m = 1; m <= kFarthest; m *= 2)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          if (dx != 0 || dy != 0 || dz != 0) out.push_back({m * dx * step, m * dy * step, m * dz * step});
  return out;
}

}  // namespace

Nudged nudge_conflicts(const RoundedMesh& start, double step, double move_limit, int max_rounds) {
  using K = tritri::ImplicitKernel;
  Nudged out;
  out.mesh = start;
  RoundedMesh& m = out.mesh;
  const std::size_t nv = m.vertices.size(), nt = m.triangles.size();
  std::vector<std::vector<int>> star(nv);
  for (std::size_t t = 0; t < nt; ++t)
    for (int v : m.triangles[t]) star[v].push_back(static_cast<int>(t));
  const std::vector<Vec3> offset = offsets(step);
  // A corner moves by at most kFarthest steps per coordinate (plus half a step where the
  // sum rounds), once per round; its triangles' neighbours are found at the round's start
  // within twice that, as their corners may have moved too. Larger by one step: margin.
  const double reach = 2 * (kFarthest + 1) * step;

  // The corners of triangle t with vertex v at `at`.
  auto positions = [&](int t, int v, const Vec3& at) {
    std::array<Vec3, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = m.triangles[t][k] == v ? at : m.vertices[m.triangles[t][k]];
    return p;
  };
  auto explicit_points = [](const std::array<Vec3, 3>& p) {
    return std::array<K::Point, 3>{K::Point::explicit_point(p[0]), K::Point::explicit_point(p[1]),
                                   K::Point::explicit_point(p[2])};
  };
  auto has = [&](int t, int v) {
    const Tri& f = m.triangles[t];
    return f[0] == v || f[1] == v || f[2] == v;
  };
  auto overlap = [](const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
    for (int k = 0; k < 3; ++k)
      if (std::max({a[0][k], a[1][k], a[2][k]}) < std::min({b[0][k], b[1][k], b[2][k]}) ||
          std::min({a[0][k], a[1][k], a[2][k]}) > std::max({b[0][k], b[1][k], b[2][k]}))
        return false;
    return true;
  };
  // The pairs of a triangle of v's star (its index in star[v]) with a triangle near it,
  // each once.
  struct StarPair {
    int i, u;
  };
  auto star_pairs = [&](int v, const std::vector<int>& near) {
    std::vector<StarPair> pairs;
    for (std::size_t i = 0; i < star[v].size(); ++i) {
      const int t = star[v][i];
      for (int u : near)
        if (u != t && !(u < t && has(u, v))) pairs.push_back({static_cast<int>(i), u});
    }
    return pairs;
  };
  // The violating pairs among `pairs` when v is at `at`, counted up to `bound` (a count that
  // reaches it is returned as is), in the order given; SIZE_MAX when a triangle of the star
  // is degenerate there. Pairs whose boxes do not meet do not violate. `faulty`, when given,
  // receives which pairs violate.
  auto faults_at = [&](int v, const Vec3& at, const std::vector<StarPair>& pairs, std::size_t bound,
                       std::vector<char>* faulty) {
    std::vector<std::array<Vec3, 3>> q(star[v].size());
    std::vector<std::array<K::Point, 3>> pq(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
      q[i] = positions(star[v][i], v, at);
      if (tritri::projection(tritri::DoubleKernel{}, q[i][0], q[i][1], q[i][2]).second == 0) return SIZE_MAX;
      pq[i] = explicit_points(q[i]);
    }
    std::size_t n = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto [i, u] = pairs[k];
      const std::array<Vec3, 3> qu = positions(u, v, at);
      if (!overlap(q[i], qu)) continue;
      if (pair_fault<K>(m.triangles[star[v][i]], pq[i], m.triangles[u], explicit_points(qu)) != PairFault::none) {
        if (faulty) (*faulty)[k] = 1;
        if (++n >= bound) return n;
      }
    }
    return n;
  };

  // The violating pairs of each round: all of them checked in the first; later, the pairs
  // with a triangle a move changed are checked again and the others carry over. Triangles
  // never change, only positions, and a pair's verdict depends on its corners' positions
  // and identities alone, so this is the full check's result. Matched by index, not by
  // position as ViolationTracker does: moves may put two vertices at one position, where
  // the tracker falls back to full checks.
  std::vector<std::pair<int, int>> violating = check_arrangement(m, 0).violating_pairs;
  std::vector<char> changed(nt, 0);  // the triangles of the corners moved since the last check
  std::size_t changed_count = 0;
  for (out.rounds = 1;; ++out.rounds) {
    if (out.rounds > 1) {
      if (full_check_costs_less(changed_count, nt)) {
        violating = check_arrangement(m, 0).violating_pairs;
      } else {
        std::vector<std::pair<int, int>> now = check_arrangement_touching(m, changed, 0).violating_pairs;
        for (const auto& pair : violating)
          if (!changed[pair.first] && !changed[pair.second]) now.push_back(pair);
        std::sort(now.begin(), now.end());
        now.erase(std::unique(now.begin(), now.end()), now.end());
        violating = std::move(now);
      }
      std::fill(changed.begin(), changed.end(), 0);
      changed_count = 0;
    }
    out.violations = violating.size();
    if (violating.empty() || out.rounds >= max_rounds) break;
    std::vector<int> conflict;
    for (const auto& [i, j] : violating)
      for (int t : {i, j})
        for (int v : m.triangles[t]) conflict.push_back(v);
    std::sort(conflict.begin(), conflict.end());
    conflict.erase(std::unique(conflict.begin(), conflict.end()), conflict.end());
    // The triangles near each conflicting corner's star.
    auto box_of = [&](int t, double grow) {
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        lo[k] = hi[k] = m.vertices[m.triangles[t][0]][k];
        for (int c = 1; c < 3; ++c) {
          lo[k] = std::min(lo[k], m.vertices[m.triangles[t][c]][k]);
          hi[k] = std::max(hi[k], m.vertices[m.triangles[t][c]][k]);
        }
        lo[k] -= grow;
        hi[k] += grow;
      }
      return CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    };
    std::vector<Box> stars, all;
    for (std::size_t c = 0; c < conflict.size(); ++c) {
      CGAL::Bbox_3 b;
      for (int t : star[conflict[c]]) b += box_of(t, 2 * reach);
      stars.emplace_back(b, static_cast<int>(c));
    }
    for (std::size_t t = 0; t < nt; ++t) all.emplace_back(box_of(static_cast<int>(t), 0), static_cast<int>(t));
    std::vector<std::vector<int>> near(conflict.size());
    CGAL::box_intersection_d<CGAL::Sequential_tag>(
        stars.begin(), stars.end(), all.begin(), all.end(),
        [&](const Box& s, const Box& t) { near[s.info()].push_back(t.info()); },
        CGAL::Box_intersection_d::Box_traits_d<Box>(), 10, CGAL::Box_intersection_d::CLOSED,
        CGAL::Box_intersection_d::BIPARTITE);

    bool moved = false;
    std::vector<std::size_t> faults(26);
    for (std::size_t c = 0; c < conflict.size(); ++c) {
      const int v = conflict[c];
      std::vector<StarPair> pairs = star_pairs(v, near[c]);
      std::vector<char> faulty(pairs.size());
      const std::size_t now = faults_at(v, m.vertices[v], pairs, SIZE_MAX, &faulty);
      if (now == 0) continue;  // mended by a move before it
      // The violating pairs first: where a position leaves them as they are (most do), its
      // count reaches `now` after them and stops (the counts, capped at `now`, are the same
      // in any order).
      std::vector<StarPair> ordered;
      ordered.reserve(pairs.size());
      for (int first : {1, 0})
        for (std::size_t k = 0; k < pairs.size(); ++k)
          if (faulty[k] == first) ordered.push_back(pairs[k]);
      const ExactVec3 from = to_exact(start.vertices[v]);
      // The nearest ring with a better position: the smallest move that mends most.
      for (std::size_t ring = 0; ring < offset.size(); ring += 26) {
        tbb::parallel_for(std::size_t{0}, std::size_t{26}, [&](std::size_t o) {
          Vec3 at;
          for (int k = 0; k < 3; ++k) at[k] = m.vertices[v][k] + offset[ring + o][k];
          const bool finite = std::isfinite(at[0]) && std::isfinite(at[1]) && std::isfinite(at[2]);
          faults[o] = !finite || distance_bound(from, at) > move_limit ? SIZE_MAX
                                                                       : faults_at(v, at, ordered, now, nullptr);
        });
        const std::size_t best = std::min_element(faults.begin(), faults.end()) - faults.begin();
        if (faults[best] >= now) continue;
        for (int k = 0; k < 3; ++k) m.vertices[v][k] += offset[ring + best][k];
        for (int t : star[v])
          if (!changed[t]) changed[t] = 1, ++changed_count;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (m.vertices[v] != start.vertices[v]) {
      ++out.moved;
      out.max_move = std::max(out.max_move, distance_bound(to_exact(start.vertices[v]), m.vertices[v]));
    }
  return out;
}

}  // namespace arrangements
