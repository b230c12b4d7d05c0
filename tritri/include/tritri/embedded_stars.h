// tritri/embedded_stars.h
//
// embedded_stars(V, F, threads = 0): for every vertex, whether the triangles around it (its
// star) provably meet one another only in what they share by index. On a clean mesh this is
// every vertex, and it settles every pair of neighbours (pairs sharing a vertex or an edge,
// about six per triangle and almost all of a box search's pairs) at once, with about three
// orient2d signs per triangle corner instead of a pairwise test.
//   V        vertex coordinates (finite doubles)
//   F        triangles, indices into V (in range)
//   threads  worker threads; <= 0: all cores (its own tbb::task_arena)
// returns one byte per vertex, 1 when embedded. Then, for any two triangles of F that share
// vertex v with embedded[v] == 1, the two meet exactly in their shared vertices and edges
// (share_embedded_star below), so a classifier reports nothing else for them.
// Certificate (every sign exact, tritri/double_predicates.h): the star of v is a fan, its
// triangles (v, a_i, a_(i+1)) in the orientation order of F, closed (a disk around v) or open
// (v on a border), and every link vertex starts one triangle and ends one (a closed fan) or
// one starts the fan and one ends it (open). In a parallel projection (along the dominant
// axis of the star's summed normals, orient2d; failing that, along the summed normal
// itself, orient3d with a point p + n: a choice that only affects which stars pass, sharp
// corners need the second), every triangle turns the same way around v, so each is projected
// one-to-one; and the direction of a_0 - v is met again by no other wedge (for a closed fan
// the wedges then turn exactly once around v). So the projected wedges meet only along the
// shared rays: non-adjacent triangles' projections meet only at v, adjacent ones only along
// their shared edge, and the triangles themselves, projected one-to-one, meet in no more.
// Anything else (a non-manifold or inconsistently oriented star, a fold, a degenerate
// projection) is simply not embedded; the pairs of such
// stars are left to the caller's pairwise tests. No precondition on duplicate vertices or
// degenerate triangles (a degenerate projection fails the certificate).
// Cost: O(n log d) for n triangles around vertices of degree at most d (sorting each fan);
// memory: 8 bytes per corner plus one byte per vertex.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "tritri/double_predicates.h"

namespace tritri {
namespace detail::embedded_stars {

// Per-thread scratch for one star (reused from vertex to vertex).
struct Scratch {
  std::vector<int> next, order, by_start;
  std::vector<char> has_prev;
};

// The fan order of the star of a vertex (its triangles' other corners, in F's orientation:
// (v, link[i][0], link[i][1]), d of them) into s.order: each triangle followed by the one
// that starts where it ends. Returns 0 for a closed fan, 1 for an open one, -1 otherwise (a
// link vertex that starts or ends two triangles, several fans).
inline int fan_order(const std::array<int, 2>* link, int d, Scratch& s) {
  s.next.assign(static_cast<std::size_t>(d), -1);
  s.has_prev.assign(static_cast<std::size_t>(d), 0);
  auto link_to = [&](int i, int j) {  // triangle j starts where triangle i ends
    if (j == i || s.has_prev[static_cast<std::size_t>(j)]) return false;
    s.next[static_cast<std::size_t>(i)] = j;
    s.has_prev[static_cast<std::size_t>(j)] = 1;
    return true;
  };
  if (d <= 16) {  // the usual star: a quadratic search beats a sort (counted without branches)
    int start[16];
    for (int j = 0; j < d; ++j) start[j] = link[j][0];
    for (int i = 0; i < d; ++i) {
      const int end = link[i][1];
      int count = 0, found = -1;
      for (int j = 0; j < d; ++j) {
        const bool match = start[j] == end;
        count += match;
        found = match ? j : found;
      }
      if (count > 1 || (count == 1 && !link_to(i, found))) return -1;  // two start where i ends
    }
  } else {
    s.by_start.resize(static_cast<std::size_t>(d));
    for (int i = 0; i < d; ++i) s.by_start[static_cast<std::size_t>(i)] = i;
    std::sort(s.by_start.begin(), s.by_start.end(), [&](int a, int b) { return link[a][0] < link[b][0]; });
    for (int k = 1; k < d; ++k)
      if (link[s.by_start[static_cast<std::size_t>(k)]][0] == link[s.by_start[static_cast<std::size_t>(k) - 1]][0])
        return -1;  // a link vertex starts two triangles
    for (int i = 0; i < d; ++i) {
      const auto it = std::lower_bound(s.by_start.begin(), s.by_start.end(), link[i][1],
                                       [&](int j, int vertex) { return link[j][0] < vertex; });
      if (it != s.by_start.end() && link[*it][0] == link[i][1] && !link_to(i, *it)) return -1;
    }
  }
  int starts = 0, first = 0;
  for (int i = 0; i < d; ++i)
    if (!s.has_prev[static_cast<std::size_t>(i)]) {
      ++starts;
      first = i;
    }
  if (starts > 1) return -1;  // several fans around the vertex
  s.order.clear();
  for (int i = first; static_cast<int>(s.order.size()) < d;) {
    s.order.push_back(i);
    i = s.next[static_cast<std::size_t>(i)];
    if (i < 0 || i == first) break;
  }
  if (static_cast<int>(s.order.size()) != d) return -1;  // a cycle that misses some triangles
  return starts;
}

// Whether the star of p, in fan order, passes the certificate above in the projection
// given by orient(b, c) (the sign of the turn p, b, c seen along the projection): every
// triangle turns the way the first one does (not zero), and once.
template <class Orient>
bool turns_once(const std::array<int, 2>* link, const std::vector<int>& order, bool closed, const Orient& orient) {
  const auto d = static_cast<int>(order.size());
  const Sign turn = orient(link[order[0]][0], link[order[0]][1]);
  if (turn == Sign::Zero) return false;
  const Sign against = turn == Sign::Positive ? Sign::Negative : Sign::Positive;
  for (int k = 1; k < d; ++k)
    if (orient(link[order[static_cast<std::size_t>(k)]][0], link[order[static_cast<std::size_t>(k)]][1]) != turn)
      return false;
  // No wedge but the first (and, closed, the last, which ends on it) holds the direction
  // of a_0 - p, boundary rays included: otherwise the wedges turn around p more than once.
  const int a0 = link[order[0]][0];
  for (int k = 1; k < (closed ? d - 1 : d); ++k) {
    const auto& w = link[order[static_cast<std::size_t>(k)]];
    if (orient(w[0], a0) != against && orient(a0, w[1]) != against) return false;
  }
  return true;
}

// Whether the star of v passes the certificate: projected along the dominant axis of its
// summed normals (orient2d), else along the summed normal itself (orient3d with a point
// p + n: the parallel projection along the exact direction of that double point minus p).
inline bool star_embedded(std::span<const std::array<double, 3>> V, int v, const std::array<int, 2>* link, int d,
                          Scratch& s) {
  if (d < 2) return true;  // no pair
  const int fan = fan_order(link, d, s);
  if (fan < 0) return false;
  const bool closed = fan == 0;
  const std::array<double, 3>& p = V[static_cast<std::size_t>(v)];
  // The summed normal only chooses the projection (every decision below is exact). It is
  // computed on the edge vectors as they are, and again scaled by a power of two to about 1
  // where that sum left the range of comfortably normal doubles (overflow, underflow).
  auto reach = [&] {
    double r = 0;
    for (int i = 0; i < d; ++i)
      for (int c = 0; c < 2; ++c)
        for (int k = 0; k < 3; ++k) r = std::max(r, std::fabs(V[static_cast<std::size_t>(link[i][c])][k] - p[k]));
    return r;
  };
  auto summed_normal = [&](double (&n)[3], auto&& scaled) {
    n[0] = n[1] = n[2] = 0;
    for (int i = 0; i < d; ++i) {
      const auto& a = V[static_cast<std::size_t>(link[i][0])];
      const auto& b = V[static_cast<std::size_t>(link[i][1])];
      double e[3], f[3];
      for (int k = 0; k < 3; ++k) {
        e[k] = scaled(a[k] - p[k]);
        f[k] = scaled(b[k] - p[k]);
      }
      n[0] += e[1] * f[2] - e[2] * f[1];
      n[1] += e[2] * f[0] - e[0] * f[2];
      n[2] += e[0] * f[1] - e[1] * f[0];
    }
    return std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
  };
  double n[3];
  double m = summed_normal(n, [](double x) { return x; });
  if (!(m >= 0x1p-900 && m <= 0x1p900) || std::isnan(n[0] + n[1] + n[2])) {  // (max ignores a later NaN)
    const double r = reach();
    if (!(r > 0) || !std::isfinite(r)) return false;
    int exponent = 0;
    std::frexp(r, &exponent);
    // x 2^-exponent: one product by that power of two when it is a normal double (the same
    // value as std::ldexp, which is a library call per coordinate), else std::ldexp.
    const bool by_product = exponent > -1000 && exponent < 1000;
    const double scale = by_product ? std::ldexp(1.0, -exponent) : 0;
    m = summed_normal(n, [&](double x) { return by_product ? x * scale : std::ldexp(x, -exponent); });
  }
  if (!(m > 0) || !std::isfinite(m)) return false;
  const int axis = std::fabs(n[0]) == m ? 0 : (std::fabs(n[1]) == m ? 1 : 2);
  const int x = (axis + 1) % 3, y = (axis + 2) % 3;
  auto orient_axis = [&](int b, int c) {
    const auto& q = V[static_cast<std::size_t>(b)];
    const auto& r = V[static_cast<std::size_t>(c)];
    return orient2d(p[x], p[y], q[x], q[y], r[x], r[y]);
  };
  if (turns_once(link, s.order, closed, orient_axis)) return true;
  // Along the normal (sharp corners, where an axis sees some triangle edge-on): the point
  // q = p + n scaled to the larger of |p| and the star's reach, so that rounding q moves
  // q - p by a relative 2^-52 at most and the direction stays that of n.
  std::array<double, 3> q;
  const double size = std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]), reach()});
  for (int k = 0; k < 3; ++k) q[k] = p[k] + (n[k] / m) * size;
  if (!std::isfinite(q[0] + q[1] + q[2]) || q == p) return false;
  auto orient_normal = [&](int b, int c) {
    return orient3d(p, V[static_cast<std::size_t>(b)], V[static_cast<std::size_t>(c)], q);
  };
  return turns_once(link, s.order, closed, orient_normal);
}

}  // namespace detail::embedded_stars

inline std::vector<std::uint8_t> embedded_stars(std::span<const std::array<double, 3>> V,
                                                std::span<const std::array<int, 3>> F, int threads = 0) {
  using namespace detail::embedded_stars;
  // Each vertex's triangles as (next corner, corner after it): counting sort by vertex.
  std::vector<std::uint32_t> first(V.size() + 1, 0);
  for (const auto& t : F)
    for (int v : t) ++first[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < V.size(); ++v) first[v + 1] += first[v];
  std::vector<std::array<int, 2>> link(first.back());
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (const auto& t : F)
      for (int k = 0; k < 3; ++k) link[fill[static_cast<std::size_t>(t[k])]++] = {t[(k + 1) % 3], t[(k + 2) % 3]};
  }
  std::vector<std::uint8_t> embedded(V.size(), 0);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, V.size(), 2048), [&](const tbb::blocked_range<std::size_t>& r) {
      Scratch scratch;
      for (std::size_t v = r.begin(); v < r.end(); ++v) {
        // The link's coordinates a few vertices ahead: neighbours' indices are scattered, so
        // the loads, not the signs, dominate.
        constexpr std::size_t kAhead = 4;
        if (v + kAhead < V.size())
          for (std::uint32_t k = first[v + kAhead]; k < first[v + kAhead + 1]; ++k)
            __builtin_prefetch(V[static_cast<std::size_t>(link[k][0])].data());
        const auto d = static_cast<int>(first[v + 1] - first[v]);
        embedded[v] = star_embedded(V, static_cast<int>(v), link.data() + first[v], d, scratch);
      }
    });
  });
  return embedded;
}

// Keys for tritri::for_each_overlapping_pair / for_each_candidate_pair that skip exactly
// the pairs share_embedded_star settles: each triangle's corners, a corner whose star is not
// embedded replaced by -1 - t, a value no other triangle's key holds (keys are only compared
// between different triangles; any int index t). Two triangles' keys share a value iff they
// share a vertex with an embedded star.
inline std::vector<std::array<int, 3>> embedded_corner_keys(std::span<const std::array<int, 3>> F,
                                                            std::span<const std::uint8_t> embedded) {
  std::vector<std::array<int, 3>> keys(F.size());
  for (std::size_t t = 0; t < F.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = F[t][k];
      keys[t][k] = embedded[static_cast<std::size_t>(v)] ? v : -1 - static_cast<int>(t);
    }
  return keys;
}

// Whether triangles a and b (corner indices) share a vertex whose star is embedded, so that
// they meet exactly in their shared vertices and edges.
// Without branches on the comparisons: a box search calls this for every neighbour pair
// (most of a clean mesh's box pairs), where early exits were mispredicted branches.
inline bool share_embedded_star(const std::array<int, 3>& a, const std::array<int, 3>& b,
                                std::span<const std::uint8_t> embedded) {
  bool shared = false;
  for (int u : a)
    shared |= ((u == b[0]) | (u == b[1]) | (u == b[2])) & (embedded[static_cast<std::size_t>(u)] != 0);
  return shared;
}

}  // namespace tritri
