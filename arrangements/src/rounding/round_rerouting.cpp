// reroute_conflicts (round_rerouting.h): slivers collapsed and edges and faces rerouted
// through vertices within delta, where the rounded mesh is not an arrangement.
#include "rounding/round_rerouting.h"

#include <CGAL/Gmpq.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>

#include <tritri/double_kernel.h>
#include <tritri/projection.h>

#include "arrangements/memory_budget.h"
#include "rounding/mesh_on_positions.h"

namespace arrangements {
namespace {

constexpr int kRoundsWithoutProgress = 3;

using Q = CGAL::Gmpq;
using QVec = std::array<Q, 3>;

QVec minus(const Vec3& p, const Vec3& q) { return {Q(p[0]) - Q(q[0]), Q(p[1]) - Q(q[1]), Q(p[2]) - Q(q[2])}; }
Q dot(const QVec& u, const QVec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
QVec cross(const QVec& u, const QVec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// The double filter of the tests below: false only when p is clearly farther than
// 2 delta from the line through a and b (the exact test decides everything else).
bool maybe_near_line(const Vec3& p, const Vec3& a, const Vec3& b, double delta) {
  const Vec3 u{p[0] - a[0], p[1] - a[1], p[2] - a[2]}, e{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Vec3 c{u[1] * e[2] - u[2] * e[1], u[2] * e[0] - u[0] * e[2], u[0] * e[1] - u[1] * e[0]};
  const double cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2], ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  return cc <= 4 * delta * delta * ee;
}

// The squared distance from p to segment ab when p projects strictly inside it and lies
// within delta of it (exact), else nullopt.
std::optional<Q> near_edge(const Vec3& p, const Vec3& a, const Vec3& b, double delta, const Q& delta2) {
  if (!maybe_near_line(p, a, b, delta)) return std::nullopt;
  const QVec u = minus(p, a), e = minus(b, a);
  const Q along = dot(u, e), length2 = dot(e, e);
  if (!(along > 0) || !(along < length2)) return std::nullopt;
  const Q d2 = dot(u, u) - along * along / length2;
  if (d2 > delta2) return std::nullopt;
  return d2;
}

// The squared distance from p to triangle f when p projects strictly inside it and lies
// within delta of its plane (exact), else nullopt.
std::optional<Q> near_face(const std::vector<Vec3>& P, int p, const Tri& f, const Q& delta2) {
  const QVec n = cross(minus(P[f[1]], P[f[0]]), minus(P[f[2]], P[f[0]]));
  const Q n2 = dot(n, n);
  const Q w = dot(minus(P[p], P[f[0]]), n);
  if (w * w > delta2 * n2) return std::nullopt;
  for (int k = 0; k < 3; ++k)
    if (!(dot(cross(minus(P[f[(k + 1) % 3]], P[f[k]]), minus(P[p], P[f[k]])), n) > 0)) return std::nullopt;
  return w * w / n2;
}

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

// What to do about one triangle (a sliver) or one violating pair.
struct Reroute {
  int vertex = -1;   // -1: nothing
  int a = -1, b = -1;  // put the vertex on edge ab, or
  int face = -1;       // split this triangle at it
  Q d2;
};

void keep_closer(Reroute& best, const Reroute& r) {
  if (r.vertex >= 0 && (best.vertex < 0 || r.d2 < best.d2)) best = r;
}

// A sliver: the apex closest to its opposite edge, within delta.
Reroute sliver(const std::vector<Vec3>& P, const Tri& f, double delta, const Q& delta2) {
  Reroute best;
  for (int k = 0; k < 3; ++k) {
    const int a = f[k], b = f[(k + 1) % 3], v = f[(k + 2) % 3];
    if (auto d2 = near_edge(P[v], P[a], P[b], delta, delta2)) keep_closer(best, {v, a, b, -1, *d2});
  }
  return best;
}

// Of triangles s and o, the vertex of one closest to an edge or the face of the other.
Reroute pair_reroute(const std::vector<Vec3>& P, const std::vector<Tri>& F, int s, int o, double delta,
                     const Q& delta2) {
  Reroute best;
  for (const auto& [x, y] : {std::pair{s, o}, std::pair{o, s}})
    for (int v : F[x]) {
      if (std::find(F[y].begin(), F[y].end(), v) != F[y].end()) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = F[y][k], b = F[y][(k + 1) % 3];
        if (auto d2 = near_edge(P[v], P[a], P[b], delta, delta2)) keep_closer(best, {v, a, b, -1, *d2});
      }
      if (auto d2 = near_face(P, v, F[y], delta2)) keep_closer(best, {v, -1, -1, y, *d2});
    }
  return best;
}

// One round of rerouting on mesh m (its triangles change); returns the vertices put on an
// edge or a face. closed: m bounds solids and must stay closed (reroute_conflicts).
std::size_t reroute_round(RoundedMesh& m, const std::vector<std::pair<int, int>>& pairs, bool every_sliver,
                          double delta, bool closed) {
  const std::vector<Vec3>& P = m.vertices;
  const Q delta2 = Q(delta) * Q(delta);
  const std::size_t nt = m.triangles.size();
  std::vector<char> in_pair(nt, 0);
  for (const auto& [i, j] : pairs) in_pair[i] = in_pair[j] = 1;
  std::vector<Reroute> slivers(nt);
  tbb::parallel_for(std::size_t{0}, nt, [&](std::size_t t) {
    if (every_sliver || in_pair[t]) slivers[t] = sliver(P, m.triangles[t], delta, delta2);
  });
  std::vector<Reroute> decided(pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t k) {
    const auto [i, j] = pairs[k];
    if (slivers[i].vertex < 0 && slivers[j].vertex < 0) decided[k] = pair_reroute(P, m.triangles, i, j, delta, delta2);
  });

  std::unordered_map<std::uint64_t, std::vector<int>> on_edge_pending;  // edge -> vertices to put on it
  std::vector<int> face_split(nt, -1);
  std::size_t rerouted = 0;
  auto take = [&](const Reroute& r) {
    if (r.vertex < 0) return;
    if (r.face >= 0) {
      if (face_split[r.face] >= 0) return;
      face_split[r.face] = r.vertex;
    } else {
      on_edge_pending[edge_key(r.a, r.b)].push_back(r.vertex);
    }
    ++rerouted;
  };
  for (const Reroute& r : slivers) take(r);
  for (const Reroute& r : decided) take(r);

  // Faces first: their pieces keep the face's edges, on which vertices may be pending.
  std::vector<char> alive(nt, 1);
  auto add = [&](int p, int q, int r, std::size_t from) {
    m.triangles.push_back({p, q, r});
    m.source.push_back(m.source[from]);
    m.label_set.push_back(m.label_set[from]);
    alive.push_back(1);
  };
  for (std::size_t t = 0; t < nt; ++t)
    if (face_split[t] >= 0) {
      const Tri f = m.triangles[t];
      alive[t] = 0;
      for (int k = 0; k < 3; ++k) add(f[k], f[(k + 1) % 3], face_split[t], t);
    }
  // Edge -> its triangles (some dead), for the edges with vertices pending only: indexing
  // every edge of the mesh cost more than the rest of a round.
  std::unordered_map<std::uint64_t, std::vector<int>> on_edge;
  auto index_pending_edges = [&](const std::unordered_map<std::uint64_t, std::vector<int>>& pending) {
    on_edge.clear();
    for (const auto& entry : pending) on_edge[entry.first];
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (alive[t])
        for (int k = 0; k < 3; ++k)
          if (auto it = on_edge.find(edge_key(m.triangles[t][k], m.triangles[t][(k + 1) % 3])); it != on_edge.end())
            it->second.push_back(static_cast<int>(t));
  };

  // Every triangle on an edge with vertices pending on it split through them, in order along
  // it (closed: a sliver over the edge, whose apex is one of them, too, leaving one piece
  // per other vertex pending and degenerate ones, dropped; so every triangle on the edge is
  // split the same way and a closed surface stays closed). Longer edges first, so that a
  // vertex pending on a piece of an edge finds that piece.
  auto split_edges = [&](std::unordered_map<std::uint64_t, std::vector<int>>& pending) {
    index_pending_edges(pending);
    std::vector<std::pair<double, std::uint64_t>> order;
    for (const auto& [key, vertices] : pending) {
      const Vec3 &a = P[key >> 32], &b = P[key & 0xffffffffu];
      order.emplace_back(
          -((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])), key);
    }
    std::sort(order.begin(), order.end());
    for (const auto& [minus_length2, key] : order) {
      const int a = static_cast<int>(key >> 32);
      std::vector<int> on = pending[key];
      std::sort(on.begin(), on.end());
      on.erase(std::unique(on.begin(), on.end()), on.end());
      // In order from a to b: by the exact projection on b - a.
      const QVec e = minus(P[static_cast<int>(key & 0xffffffffu)], P[a]);
      std::vector<std::pair<Q, int>> along;
      for (int v : on) along.emplace_back(dot(minus(P[v], P[a]), e), v);
      std::sort(along.begin(), along.end());
      const std::vector<int> triangles = on_edge[key];  // a copy: the pieces are added to on_edge
      for (int t : triangles) {
        if (!alive[t]) continue;
        const Tri f = m.triangles[t];
        alive[t] = 0;
        // Not closed: a sliver over the edge just goes (other vertices pending on its edge
        // then leave T-junctions, which the next round's check finds).
        if (!closed && std::any_of(on.begin(), on.end(), [&](int v) { return v == f[0] || v == f[1] || v == f[2]; }))
          continue;
        int k = 0;
        while (edge_key(f[k], f[(k + 1) % 3]) != key) ++k;
        std::vector<int> chain{f[k]};
        if (f[k] == a)
          for (const auto& [_, v] : along) chain.push_back(v);
        else
          for (auto it = along.rbegin(); it != along.rend(); ++it) chain.push_back(it->second);
        chain.push_back(f[(k + 1) % 3]);
        const int apex = f[(k + 2) % 3];
        for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
          if (chain[c] == apex || chain[c + 1] == apex) continue;
          add(chain[c], chain[c + 1], apex, t);
          const int piece = static_cast<int>(m.triangles.size()) - 1;
          const Tri& g = m.triangles[piece];
          for (int j = 0; j < 3; ++j)
            if (auto it = on_edge.find(edge_key(g[j], g[(j + 1) % 3])); it != on_edge.end())
              it->second.push_back(piece);
        }
      }
    }
  };
  // Closed: pieces whose corners are collinear (exactly: a second vertex pending on a
  // sliver's edge makes one) are slivers of width 0: their middle vertex goes on their long
  // edge the same way, until none is left (cleaning would drop them and open the surface).
  for (std::size_t first_new = nt, round = 0; round < 8; ++round) {
    split_edges(on_edge_pending);
    on_edge_pending.clear();
    if (!closed) break;
    const std::size_t end = m.triangles.size();
    for (std::size_t t = first_new; t < end; ++t) {
      if (!alive[t]) continue;
      const Tri& f = m.triangles[t];
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
          tritri::projection(tritri::DoubleKernel{}, P[f[0]], P[f[1]], P[f[2]]).second != 0)
        continue;  // not a flat piece of three distinct corners
      // The middle corner: the one opposite the longest side.
      Q longest = -1;
      int middle = 0;
      for (int k = 0; k < 3; ++k) {
        const QVec d = minus(P[f[(k + 1) % 3]], P[f[(k + 2) % 3]]);
        if (const Q l = dot(d, d); l > longest) longest = l, middle = k;
      }
      on_edge_pending[edge_key(f[(middle + 1) % 3], f[(middle + 2) % 3])].push_back(f[middle]);
    }
    if (on_edge_pending.empty()) break;
    first_new = end;
  }

  std::size_t kept = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (alive[t]) {
      m.triangles[kept] = m.triangles[t];
      m.source[kept] = m.source[t];
      m.label_set[kept] = m.label_set[t];
      ++kept;
    }
  m.triangles.resize(kept);
  m.source.resize(kept);
  m.label_set.resize(kept);
  return rerouted;
}

}  // namespace

Rerouting reroute_conflicts(const std::vector<Vec3>& position, const std::vector<Tri>& triangles,
                            const std::vector<std::int64_t>& source, const std::vector<int>& label_set,
                            const std::vector<LabelSet>& label_sets, double delta, int max_rounds,
                            ViolationTracker& tracker, bool closed) {
  Rerouting now{triangles, source, label_set, label_sets, 0, 0, 0};
  Rerouting best;
  best.violations = std::numeric_limits<std::size_t>::max();
  int rounds_since_best = 0;
  for (int round = 1; round <= max_rounds; ++round) {
    detail::memory_checkpoint();
    MeshOnPositions c = mesh_on_positions(position, now.triangles, now.source, now.label_set, now.label_sets, closed);
    const std::vector<std::pair<int, int>> violating = tracker.violations(c.mesh);
    best.rounds = round;
    if (violating.size() < best.violations) {
      const int rounds = best.rounds;
      best = now;
      best.violations = violating.size();
      best.rounds = rounds;
      rounds_since_best = 0;
      if (violating.empty()) break;
    } else if (++rounds_since_best == kRoundsWithoutProgress) {
      break;
    }
    now.rerouted += reroute_round(c.mesh, violating, round == 1, delta, closed);
    // Back to the input's vertices (one per position: the first).
    std::vector<int> input_of(c.mesh.vertices.size(), -1);
    for (std::size_t v = c.vertex_of.size(); v-- > 0;)
      if (c.vertex_of[v] >= 0) input_of[c.vertex_of[v]] = static_cast<int>(v);
    for (Tri& f : c.mesh.triangles)
      for (int& v : f) v = input_of[v];
    now.triangles = std::move(c.mesh.triangles);
    now.source = std::move(c.mesh.source);
    now.label_set = std::move(c.mesh.label_set);
    now.label_sets = std::move(c.mesh.label_sets);
  }
  return best;
}

}  // namespace arrangements
