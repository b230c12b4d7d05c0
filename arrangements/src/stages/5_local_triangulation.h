// arrangements/src/stages/5_local_triangulation.h
//
// LocalTriangulation: the constrained triangulation of one input triangle, built by point
// insertion and constraint insertion with edge flips (Sloan's algorithm), for stage 5
// (5_triangulate_triangle.cpp, its only user). All decisions are the point model's exact
// orient2d (M::orient2d_local: implicit points with tritri's filtered predicates, or
// rational points) in a projection where the input triangle is not degenerate, times that
// triangle's orientation there, so that every local triangle
// is positive ("CCW"). Point location is a stochastic visibility walk seeded the same way
// for every triangle: deterministic.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <utility>
#include <vector>

#include <tritri/sign.h>

#include "arrangements/memory_budget.h"
#include "arrangements/triangle_soup.h"

namespace arrangements::local {

// A triangle of the local triangulation of one input triangle. Edge k is the edge
// opposite v[k] (from v[k+1] to v[k+2]); n[k] the triangle across it (-1: the input
// triangle's boundary); c[k] the constraint it lies on (-1: none).
struct LocalTriangle {
  int v[3];
  int n[3];
  int c[3];
};

inline int next3(int k) { return k == 2 ? 0 : k + 1; }
inline int prev3(int k) { return k == 0 ? 2 : k - 1; }

// (See the top of this file.) M: the point model (models/point_model.h).
template <class M>
class LocalTriangulation {
 public:
  std::deque<typename M::Point> pts;     // local vertices (a deque: off[i] may point into it)
  std::vector<typename M::Local> off;    // their local form (M::local; origin: a corner)
  std::vector<LocalTriangle> tris;
  std::vector<int> vtri;  // a triangle incident to each vertex
  std::vector<int> deg;   // each vertex's number of edges (find_edge walks the smaller ring)
  // The input triangle's boundary edges each vertex lies on (bit k: edge k, from corner k
  // to corner k + 1): three vertices on one edge are collinear by construction, an exact
  // zero that orient() answers without arithmetic (the exact stage of implicit points
  // is the costliest predicate there is, and points on one edge are the common case).
  std::vector<std::uint8_t> on_edge;
  // The constraint lines each vertex lies on by construction (ids the caller gives, one per
  // line; sorted): three vertices on one line are collinear, an exact zero that orient()
  // answers without arithmetic as for on_edge. Coplanar overlaps make these common: a
  // partner's edge crosses t as a chain of constraints, and fans put many lines through
  // one point (40 concurrent coplanar wedges: 7.8 M orient calls, a third of them in the
  // exact stage, before this, the shortcuts of insert_constraint and the Morton order of
  // split_triangle_of; 2.6 M after).
  std::vector<std::vector<int>> lines;

  LocalTriangulation(tritri::Plane plane, int sign, const typename M::Vertex& origin)
      : plane_(plane), sign_(sign), origin_(origin) {}

  // Starts over, as if newly constructed, keeping the containers' memory (split_triangle_of
  // reuses one object per thread: allocations were about a tenth of triangulation's time).
  void reset(tritri::Plane plane, int sign, const typename M::Vertex& origin) {
    pts.clear();
    off.clear();
    tris.clear();
    vtri.clear();
    deg.clear();
    on_edge.clear();
    lines.clear();
    plane_ = plane;
    sign_ = sign;
    origin_ = origin;
    last_ = 0;
    rng_ = kSeed;
    side_of_.clear();
    crossed_.clear();
    ring_copy_.clear();
    constraint_ = 0;
    ring_.clear();
  }

  int orient(int a, int b, int c) const {
    if ((on_edge[a] & on_edge[b] & on_edge[c]) || on_common_line(a, b, c)) return 0;
    return sign_ * tritri::to_int(M::orient2d_local(off[a], off[b], off[c], plane_));
  }

  // Records that vertex v lies on line `line` (exactly: by construction).
  void add_line(int v, int line) {
    std::vector<int>& l = lines[v];
    const auto it = std::lower_bound(l.begin(), l.end(), line);
    if (it == l.end() || *it != line) l.insert(it, line);
  }

  int add_vertex(const typename M::Point& p) {
    pts.push_back(p);
    off.push_back(M::local(pts.back(), origin_));
    vtri.push_back(-1);
    deg.push_back(0);
    on_edge.push_back(0);
    lines.emplace_back();
    return static_cast<int>(pts.size()) - 1;
  }

  void start(int a, int b, int c) {
    tris.push_back({{a, b, c}, {-1, -1, -1}, {-1, -1, -1}});
    vtri[a] = vtri[b] = vtri[c] = 0;
    deg[a] = deg[b] = deg[c] = 2;
    on_edge[a] = 0b101;
    on_edge[b] = 0b011;
    on_edge[c] = 0b110;
    last_ = 0;
  }

  // Inserts vertex p (inside the closed input triangle, distinct from every vertex).
  void insert_point(int p) {
    detail::memory_checkpoint();
    const auto [t, edge] = locate(p);
    if (edge < 0)
      split_triangle(t, p);
    else
      split_edge(t, edge, p);
  }

  // Inserts vertex p known to lie inside the boundary edge (u, w).
  void split_boundary_edge(int u, int w, int p) {
    const auto [t, k] = find_edge(u, w);
    on_edge[p] = on_edge[u] & on_edge[w];
    split_edge(t, k, p);
  }

  // Inserts the constraint segment (a, b) between two vertices, on line `line` (an id of
  // `lines`; -1: none). `crossing(cid, other)` returns a new vertex at the crossing of
  // constraint cid with constraint `other`.
  template <class Crossing>
  void insert_constraint(int a, int b, int cid, Crossing&& crossing, int line = -1) {
    detail::memory_checkpoint();
    ++constraint_;
    int cur = a, prev = -1;
    std::vector<std::array<int, 2>>& crossed = crossed_;  // scratch kept across calls: no allocation per step
    while (cur != b) {
      int target = -1;
      crossed.clear();
      // The triangle around cur whose wedge contains the direction to b. An edge to b, or
      // (past a) to a vertex on the line other than the one we came from, is the next step
      // with no predicate: the line meets cur's ring in at most one vertex on each side,
      // and an edge from cur cannot pass beyond b.
      bool done = false;
      const std::vector<int>& ring_now = around(cur);  // copied: inserting crossings changes around()'s ring
      ring_copy_.assign(ring_now.begin(), ring_now.end());
      const std::vector<int>& ring = ring_copy_;
      for (int t : ring) {
        const LocalTriangle& T = tris[t];
        const int i = index_of(T, cur);
        const int u = T.v[next3(i)], w = T.v[prev3(i)];
        auto ahead_on_line = [&](int v) { return prev >= 0 && v != prev && has_line(v, line); };
        int next = -1;
        if (u == b || w == b)
          next = b;
        else if (ahead_on_line(u))
          next = u;
        else if (ahead_on_line(w))
          next = w;
        if (next >= 0) {
          mark(t, u == next ? prev3(i) : next3(i), cid);
          target = next;
          done = true;
          break;
        }
      }
      // Else the wedge by orientation (each vertex's side of (a, b) is computed once per
      // constraint: neighbouring triangles of the ring share a vertex).
      if (side_of_.size() < pts.size()) side_of_.resize(pts.size(), {0, 0});
      auto side = [&](int v) {
        if (side_of_[v].first != constraint_) side_of_[v] = {constraint_, orient(a, b, v)};
        return side_of_[v].second;
      };
      for (std::size_t r = 0; !done && r < ring.size(); ++r) {
        const int t = ring[r];
        const LocalTriangle& T = tris[t];
        const int i = index_of(T, cur);
        const int u = T.v[next3(i)], w = T.v[prev3(i)];
        const int ou = side(u), ow = side(w);
        if (ou == 0 && ow > 0) {  // u lies on the segment, ahead of cur
          mark(t, prev3(i), cid);
          target = u;
          done = true;
        } else if (ow == 0 && ou < 0) {  // w lies on the segment, ahead of cur
          mark(t, next3(i), cid);
          target = w;
          done = true;
        } else if (ou < 0 && ow > 0) {  // the segment leaves through edge (u, w)
          target = walk(t, i, a, b, cid, crossing, crossed);
          done = true;
        }
      }
      if (!done) throw std::logic_error("triangulate: constraint direction not found around a vertex");
      if (target < 0) continue;  // a crossing was inserted: look again from cur
      if (!crossed.empty()) {
        flip_until_present(a, b, cur, target, crossed);
        const auto [t, k] = find_edge(cur, target);
        mark(t, k, cid);
      }
      if (line >= 0) add_line(target, line);  // on the segment (found exactly)
      prev = cur;
      cur = target;
    }
  }

 private:
  tritri::Plane plane_;
  int sign_;
  typename M::Vertex origin_;
  int last_ = 0;
  static constexpr std::uint64_t kSeed = 0x9E3779B97F4A7C15ull;
  std::uint64_t rng_ = kSeed;

  bool has_line(int v, int line) const {
    return line >= 0 && std::binary_search(lines[v].begin(), lines[v].end(), line);
  }
  std::vector<std::pair<int, int>> side_of_;  // per vertex: (constraint_, its orient(a, b, v))
  std::vector<std::array<int, 2>> crossed_;   // insert_constraint's scratch: the edges a step crosses
  std::vector<int> ring_copy_;                // insert_constraint's scratch: the ring of its vertex
  int constraint_ = 0;                         // insert_constraint calls so far

  // Whether a, b and c lie on one recorded line: the shortest list is searched in the others.
  bool on_common_line(int a, int b, int c) const {
    if (lines[b].size() < lines[a].size()) std::swap(a, b);
    if (lines[c].size() < lines[a].size()) std::swap(a, c);
    for (const int line : lines[a])
      if (has_line(b, line) && has_line(c, line)) return true;
    return false;
  }

  static int index_of(const LocalTriangle& T, int v) { return T.v[0] == v ? 0 : (T.v[1] == v ? 1 : 2); }

  int random3() {
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 7;
    rng_ ^= rng_ << 17;
    return static_cast<int>(rng_ % 3);
  }

  // Stochastic visibility walk (terminates in any triangulation with probability 1; the
  // generator is seeded the same way for every input triangle: deterministic).
  std::pair<int, int> locate(int p) {
    int t = last_;
    for (std::size_t steps = 0;; ++steps) {
      if (steps > 4 * tris.size() + 64) throw std::logic_error("triangulate: point location did not terminate");
      const LocalTriangle& T = tris[t];
      const int off = random3();
      int zeros = 0, on_edge = -1, next = -2;
      for (int r = 0; r < 3; ++r) {
        const int k = (off + r) % 3;
        const int o = orient(T.v[next3(k)], T.v[prev3(k)], p);
        if (o < 0) {
          next = T.n[k];
          break;
        }
        if (o == 0) {
          ++zeros;
          on_edge = k;
        }
      }
      if (next == -1) throw std::logic_error("triangulate: a point lies outside its triangle");
      if (next >= 0) {
        t = next;
        continue;
      }
      if (zeros >= 2) throw std::logic_error("triangulate: a point coincides with a vertex");
      return {t, zeros == 1 ? on_edge : -1};
    }
  }

  void set_vtri(int t) {
    for (int v : tris[t].v) vtri[v] = t;
  }

  void replace_neighbor(int t, int from, int to) {
    if (t < 0) return;
    for (int& x : tris[t].n)
      if (x == from) x = to;
  }

  void split_triangle(int t, int p) {
    const LocalTriangle T = tris[t];
    const int a = T.v[0], b = T.v[1], c = T.v[2];
    const int t1 = static_cast<int>(tris.size()), t2 = t1 + 1;
    tris[t] = {{p, b, c}, {T.n[0], t1, t2}, {T.c[0], -1, -1}};
    tris.push_back({{a, p, c}, {t, T.n[1], t2}, {-1, T.c[1], -1}});
    tris.push_back({{a, b, p}, {t, t1, T.n[2]}, {-1, -1, T.c[2]}});
    replace_neighbor(T.n[1], t, t1);
    replace_neighbor(T.n[2], t, t2);
    set_vtri(t);
    set_vtri(t1);
    set_vtri(t2);
    deg[p] = 3;
    ++deg[a];
    ++deg[b];
    ++deg[c];
    last_ = t;
  }

  // Splits edge k of triangle t (and the triangle across it) at vertex p inside it.
  void split_edge(int t, int k, int p) {
    const LocalTriangle T = tris[t];
    const int a = T.v[k], b = T.v[next3(k)], c = T.v[prev3(k)];
    const int u = T.n[k], ce = T.c[k];
    const int t2 = static_cast<int>(tris.size());
    int u2 = -1;
    LocalTriangle U{};
    int j = 0;
    if (u >= 0) {
      U = tris[u];
      for (j = 0; j < 3; ++j)
        if (U.n[j] == t) break;
      u2 = t2 + 1;
    }
    // t = (a, b, p), t2 = (a, p, c)
    tris[t] = {{a, b, p}, {u2, t2, T.n[prev3(k)]}, {ce, -1, T.c[prev3(k)]}};
    tris.push_back({{a, p, c}, {u, T.n[next3(k)], t}, {ce, T.c[next3(k)], -1}});
    replace_neighbor(T.n[next3(k)], t, t2);
    if (u >= 0) {
      const int d = U.v[j];  // U = (d, c, b)
      tris[u] = {{d, c, p}, {t2, u2, U.n[prev3(j)]}, {ce, -1, U.c[prev3(j)]}};
      tris.push_back({{d, p, b}, {t, U.n[next3(j)], u}, {ce, U.c[next3(j)], -1}});
      replace_neighbor(U.n[next3(j)], u, u2);
      set_vtri(u);
      set_vtri(u2);
      ++deg[d];
      ++deg[p];
    }
    deg[p] += 3;  // edges to b, c and a, plus d's above
    ++deg[a];
    set_vtri(t);
    set_vtri(t2);
    last_ = t;
  }

  // The triangles around vertex v (collected first: callers may change the mesh).
  const std::vector<int>& around(int v) {
    ring_.clear();
    const int t0 = vtri[v];
    int t = t0;
    do {
      ring_.push_back(t);
      const LocalTriangle& T = tris[t];
      t = T.n[next3(index_of(T, v))];  // across edge (v, w): counterclockwise
    } while (t >= 0 && t != t0);
    if (t == t0) return ring_;
    t = tris[t0].n[prev3(index_of(tris[t0], v))];  // the other way from t0
    while (t >= 0) {
      ring_.push_back(t);
      const LocalTriangle& T = tris[t];
      t = T.n[prev3(index_of(T, v))];
    }
    return ring_;
  }
  std::vector<int> ring_;

  // The triangle and edge index of edge (u, w), found around its endpoint of smaller degree.
  std::pair<int, int> find_edge(int u, int w) {
    return deg[w] < deg[u] ? find_edge_around(w, u) : find_edge_around(u, w);
  }
  std::pair<int, int> find_edge_around(int u, int w) {
    for (int t : around(u)) {
      const LocalTriangle& T = tris[t];
      const int i = index_of(T, u);
      if (T.v[next3(i)] == w) return {t, prev3(i)};
      if (T.v[prev3(i)] == w) return {t, next3(i)};
    }
    throw std::logic_error("triangulate: edge not found");
  }

  void mark(int t, int k, int cid) {
    LocalTriangle& T = tris[t];
    if (T.c[k] >= 0) return;  // already on a constraint (overlapping constraints)
    T.c[k] = cid;
    const int u = T.n[k];
    if (u < 0) return;
    const int a = T.v[next3(k)], b = T.v[prev3(k)];
    LocalTriangle& U = tris[u];
    for (int j = 0; j < 3; ++j)
      if (U.v[j] != a && U.v[j] != b) U.c[j] = cid;
  }

  // From triangle t, whose edge i the open segment (a, b) crosses, collects the crossed
  // edges up to the first vertex on the segment (returned). If a crossed edge lies on a
  // constraint, inserts the crossing point instead and returns -1.
  template <class Crossing>
  int walk(int t, int i, int a, int b, int cid, Crossing& crossing, std::vector<std::array<int, 2>>& crossed) {
    for (;;) {
      const LocalTriangle& T = tris[t];
      const int u = T.v[next3(i)], w = T.v[prev3(i)];
      if (T.c[i] >= 0) {
        const int x = crossing(cid, T.c[i]);
        split_edge(t, i, x);
        return -1;
      }
      const int n = T.n[i];
      if (n < 0) throw std::logic_error("triangulate: a constraint leaves its triangle");
      crossed.push_back({u, w});
      const LocalTriangle& N = tris[n];
      int j = 0;
      while (N.n[j] != t) ++j;
      const int x = N.v[j];  // N = (x, w, u)
      if (x == b) return b;
      const int ox = orient(a, b, x);
      if (ox == 0) return x;
      t = n;
      i = ox < 0 ? prev3(j) : next3(j);  // next crossed edge: (x, w) or (u, x)
    }
  }

  // Sloan's flips: until no edge crosses the open segment (from, to) on line (a, b).
  void flip_until_present(int a, int b, int from, int to, std::vector<std::array<int, 2>>& crossed) {
    std::deque<std::array<int, 2>> queue(crossed.begin(), crossed.end());
    std::size_t stalled = 0;
    while (!queue.empty()) {
      const auto [u, w] = queue.front();
      queue.pop_front();
      const auto [t, i] = find_edge(u, w);
      const LocalTriangle T = tris[t];
      const int n = T.n[i];
      const LocalTriangle N = tris[n];
      int j = 0;
      while (N.n[j] != t) ++j;
      const int p1 = T.v[i], p2 = N.v[j];
      const int uu = T.v[next3(i)], ww = T.v[prev3(i)];
      if (orient(p1, p2, uu) * orient(p1, p2, ww) >= 0) {  // not strictly convex: later
        queue.push_back({u, w});
        if (++stalled > 2 * queue.size() + 16) throw std::logic_error("triangulate: constraint flips stalled");
        continue;
      }
      stalled = 0;
      // T = (p1, uu, ww), N = (p2, ww, uu)  ->  T = (p1, uu, p2), N = (p2, ww, p1)
      tris[t] = {{p1, uu, p2}, {N.n[next3(j)], n, T.n[prev3(i)]}, {N.c[next3(j)], -1, T.c[prev3(i)]}};
      tris[n] = {{p2, ww, p1}, {T.n[next3(i)], t, N.n[prev3(j)]}, {T.c[next3(i)], -1, N.c[prev3(j)]}};
      replace_neighbor(N.n[next3(j)], n, t);
      replace_neighbor(T.n[next3(i)], t, n);
      set_vtri(t);
      set_vtri(n);
      --deg[uu];
      --deg[ww];
      ++deg[p1];
      ++deg[p2];
      if (p1 != from && p1 != to && p2 != from && p2 != to && orient(a, b, p1) * orient(a, b, p2) < 0)
        queue.push_back({p1, p2});
    }
    last_ = vtri[from];
  }
};

}  // namespace arrangements::local
