// tests/support/implicit_scenes.h
//
// Scenes for the implicit-predicate tests: a random set of implicit points with exact
// coincidences by construction (points on one plane, on one line, one point built in
// several ways), recorded as groups, then mapped by a random exact Transform so that
// magnitudes mix; the library's point and the exact reference of each (random_scene).
// Also the drivers of the tests on scenes: run_scenes, Picker (operands from groups) and
// operands (printing a failing case).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <tritri/tritri.h>

#include "exact_oracle.h"
#include "implicit_recipes.h"
#include "pair_generators.h"
#include "test_scale.h"

namespace tritri_test {

// ---------------------------------------------------------------------------------------
// Scenes: points with exact coincidences by construction.

enum class GroupKind {
  Coplanar,    // all members on one plane
  Collinear,   // all members on one line
  Coincident,  // all members are one point
};

struct Group {
  GroupKind kind;
  std::vector<int> members;  // indices into Scene::points
  int axes = 0;              // Coplanar: bit k set when the plane contains the direction of axis k
};

// A point as built by the library, with its recipe and exact reference coordinates.
struct Sample {
  Recipe recipe;
  ImplicitPoint point;
  Q3 exact;
  ZPoint z;
};

struct Scene {
  std::vector<Sample> points;
  std::vector<Group> groups;
  std::vector<Recipe> refused;           // exactly undefined, and the library refused them
  std::vector<Recipe> wrongly_refused;   // defined, but the library refused them
  std::vector<Recipe> wrongly_accepted;  // undefined, but the library built them
  Transform transform;
};

// Bit k set when the plane of t contains the direction of axis k (normal[k] == 0).
inline int contained_axes(const Triple& t) {
  const Q3 n = normal(exact(t[0]), exact(t[1]), exact(t[2]));
  int axes = 0;
  for (int k = 0; k < 3; ++k)
    if (n[k] == 0) axes |= 1 << k;
  return axes;
}

// A plane: on the grid, a lattice o + s u + t v (s, t half-integers), whose points and
// triples are exact; otherwise three random points, its only explicit points.
struct PlaneSpec {
  bool lattice = false;
  Point o{}, u{}, v{};
  Triple tri{};
  int axes = 0;

  Point point(Rng& rng) const {
    if (!lattice) return tri[rng.uniform(0, 2)];
    return moved(moved(o, u, 0.5 * rng.uniform(-6, 6)), v, 0.5 * rng.uniform(-6, 6));
  }
  // Three non-collinear points of the plane, in random order.
  Triple triple(Rng& rng) const {
    if (!lattice) return reordered(tri, rng);
    for (int attempt = 0; attempt < 20; ++attempt) {
      Triple t{point(rng), point(rng), point(rng)};
      if (!is_zero(cross_d({t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]},
                           {t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]})))
        return t;
    }
    return reordered({o, moved(o, u, 1), moved(o, v, 1)}, rng);
  }
};

// A line: on the grid, the points p0 + k/2 (p1 - p0); otherwise just p0 and p1.
struct LineSpec {
  bool lattice = false;
  Point p0{}, p1{};

  Point at(int k) const { return moved(p0, {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, 0.5 * k); }
  Point point(Rng& rng) const {
    if (!lattice) return rng.percent(50) ? p0 : p1;
    return at(rng.uniform(-4, 6));
  }
  // Two distinct points of the line, in random order.
  std::pair<Point, Point> pair(Rng& rng) const {
    if (!lattice) return rng.percent(50) ? std::pair{p0, p1} : std::pair{p1, p0};
    const int i = rng.uniform(-4, 6);
    int j = rng.uniform(-4, 5);
    if (j >= i) ++j;
    return {at(i), at(j)};
  }
};

// Builds a scene in small coordinates (integers, or random doubles in [-1, 1)), then maps it
// by a random exact transform. Points whose recipe is undefined are recorded, not kept.
class SceneBuilder {
 public:
  SceneBuilder(Rng& rng, bool grid) : rng_(rng), grid_(grid) {}

  Point any_point() {
    Point p;
    for (double& x : p) x = grid_ ? rng_.uniform(-4, 4) : rng_.symmetric_unit();
    return p;
  }
  Triple any_triple() { return {any_point(), any_point(), any_point()}; }

  // A plane, often axis-aligned or containing an axis direction (collinear projections,
  // ties in lexicographic comparisons).
  PlaneSpec plane() {
    PlaneSpec P;
    const int mode = rng_.uniform(0, 9);
    if (!grid_) {
      P.tri = any_triple();
      const int k = rng_.uniform(0, 2);
      if (mode < 2) {
        P.tri[1][k] = P.tri[2][k] = P.tri[0][k];  // normal along axis k
      } else if (mode < 5) {
        P.tri[2] = P.tri[0];
        P.tri[2][k] = rng_.symmetric_unit();  // contains the direction of axis k
      }
    } else {
      P.lattice = true;
      P.o = any_point();
      for (;;) {
        const int k = rng_.uniform(0, 2);
        auto small = [&] {
          return Point{double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2))};
        };
        P.u = mode < 5 ? unit(k) : small();
        P.v = mode < 2 ? unit((k + 1) % 3) : small();
        if (!is_zero(cross_d(P.u, P.v))) break;
      }
      P.tri = {P.o, moved(P.o, P.u, 1), moved(P.o, P.v, 1)};
    }
    P.axes = contained_axes(P.tri);
    return P;
  }

  LineSpec line(const PlaneSpec* in_plane) {
    LineSpec L;
    L.lattice = grid_;
    for (;;) {
      if (in_plane != nullptr) {
        if (grid_) {
          L.p0 = in_plane->point(rng_);
          L.p1 = in_plane->point(rng_);
        } else {
          const Triple t = in_plane->triple(rng_);
          L.p0 = t[0];
          L.p1 = t[1];
        }
      } else if (rng_.percent(25)) {  // parallel to an axis
        L.p0 = any_point();
        L.p1 = L.p0;
        const int k = rng_.uniform(0, 2);
        L.p1[k] = grid_ ? L.p0[k] + rng_.uniform(1, 3) * (rng_.percent(50) ? 1 : -1) : rng_.symmetric_unit();
      } else {
        L.p0 = any_point();
        L.p1 = any_point();
      }
      if (L.p0 != L.p1) return L;
    }
  }

  // A plane through the line and one more point (random, so sometimes the same plane as
  // another one; then a TPI using both is undefined, which the tests also check).
  Triple plane_through(const LineSpec& L) {
    const auto [a, b] = L.pair(rng_);
    return reordered({a, b, any_point()}, rng_);
  }

  int tpi(std::array<Triple, 3> planes) {
    shuffle(planes.data(), 3, rng_);
    return add(tpi_recipe(planes));
  }

  // Points on a plane: explicit ones, LPIs of lines with it (a quarter of the lines through
  // one of its explicit points: that LPI is that point), TPIs with it as one of the planes.
  int plane_structure(const PlaneSpec& P) {
    Group g{GroupKind::Coplanar, {}, P.axes};
    const int n_explicit = grid_ ? rng_.uniform(3, 5) : 3;
    for (int i = 0; i < n_explicit; ++i) g.members.push_back(add(explicit_recipe(grid_ ? P.point(rng_) : P.tri[i])));
    for (int i = rng_.uniform(3, 6); i > 0; --i) {
      if (rng_.percent(25)) {
        const Point c = P.point(rng_), m = any_point();
        const int lpi = add(rng_.percent(50) ? lpi_recipe(c, m, P.triple(rng_)) : lpi_recipe(m, c, P.triple(rng_)));
        g.members.push_back(lpi);
        groups_.push_back({GroupKind::Coincident, {add(explicit_recipe(c)), lpi}, 0});
      } else {
        g.members.push_back(add(lpi_recipe(any_point(), any_point(), P.triple(rng_))));
      }
    }
    for (int i = rng_.uniform(2, 3); i > 0; --i) g.members.push_back(tpi({P.triple(rng_), any_triple(), any_triple()}));
    groups_.push_back(g);
    return static_cast<int>(groups_.size()) - 1;
  }

  // Points on a line (sometimes lying in the plane of group `plane_group`, then they join
  // it): explicit ones, LPIs of the line with planes, TPIs of two planes through the line.
  void line_structure(const PlaneSpec& P, int plane_group) {
    const bool in_plane = rng_.percent(30);
    const LineSpec L = line(in_plane ? &P : nullptr);
    Group g{GroupKind::Collinear, {}, 0};
    const int n_explicit = grid_ ? rng_.uniform(2, 3) : 2;
    for (int i = 0; i < n_explicit; ++i)
      g.members.push_back(add(explicit_recipe(grid_ ? L.point(rng_) : (i ? L.p1 : L.p0))));
    for (int i = rng_.uniform(3, 5); i > 0; --i) {
      const auto [a, b] = L.pair(rng_);
      g.members.push_back(add(lpi_recipe(a, b, !in_plane && rng_.percent(20) ? P.triple(rng_) : any_triple())));
    }
    for (int i = rng_.uniform(2, 3); i > 0; --i)
      g.members.push_back(tpi({plane_through(L), plane_through(L), any_triple()}));
    if (in_plane)
      for (int m : g.members) groups_[plane_group].members.push_back(m);
    groups_.push_back(g);
  }

  // One explicit point c and LPIs / TPIs that are c: lines through c meeting planes
  // through c, three planes through c.
  void vertex_structure() {
    const Point c = any_point();
    Group g{GroupKind::Coincident, {add(explicit_recipe(c))}, 0};
    auto line_through_c = [&]() -> std::pair<Point, Point> {
      if (grid_ && rng_.percent(50)) {  // c strictly between two grid points
        const Point d = {double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2))};
        return {moved(c, d, 1), moved(c, d, -0.5 * rng_.uniform(1, 4))};
      }
      const Point m = any_point();
      return rng_.percent(50) ? std::pair{c, m} : std::pair{m, c};
    };
    auto plane_through_c = [&]() -> Triple {
      if (grid_ && rng_.percent(50)) {  // c not among the defining points
        const Point u = {double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2))};
        const Point v = {double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2))};
        return reordered({moved(c, u, 1), moved(c, u, -1), moved(c, v, 1)}, rng_);
      }
      return reordered({c, any_point(), any_point()}, rng_);
    };
    for (int i = rng_.uniform(3, 4); i > 0; --i) {
      const auto [p, q] = line_through_c();
      g.members.push_back(add(lpi_recipe(p, q, plane_through_c())));
    }
    for (int i = 2; i > 0; --i) g.members.push_back(tpi({plane_through_c(), plane_through_c(), plane_through_c()}));
    groups_.push_back(g);
  }

  // One implicit point X = line pq meets plane T, built several ways: other orders and
  // other points of the line and of the plane, and TPIs of T with two planes through pq.
  void implicit_coincidence(const PlaneSpec& P) {
    const LineSpec L = line(nullptr);
    const bool on_p = rng_.percent(50);
    const PlaneSpec T = on_p ? P : plane();
    Group g{GroupKind::Coincident, {}, 0};
    for (int i = rng_.uniform(2, 4); i > 0; --i) {
      const auto [p, q] = L.pair(rng_);
      g.members.push_back(add(lpi_recipe(p, q, T.triple(rng_))));
    }
    for (int i = rng_.uniform(2, 3); i > 0; --i)
      g.members.push_back(tpi({T.triple(rng_), plane_through(L), plane_through(L)}));
    groups_.push_back(g);
  }

  // Grid only: X where two lines of a lattice plane Q cross, as LPIs of either line with a
  // plane through the other, TPIs of planes through the lines (and Q), and explicitly when X
  // is a double point. Also collinear groups along both lines and a coplanar group on Q.
  void crossing_structure() {
    const PlaneSpec Q = [&] {
      PlaneSpec q;
      do q = plane();
      while (!q.lattice);
      return q;
    }();
    LineSpec L1, L2;
    for (;;) {
      L1 = {true, Q.point(rng_), Q.point(rng_)};
      L2 = {true, Q.point(rng_), Q.point(rng_)};
      const Point d1 = {L1.p1[0] - L1.p0[0], L1.p1[1] - L1.p0[1], L1.p1[2] - L1.p0[2]};
      const Point d2 = {L2.p1[0] - L2.p0[0], L2.p1[1] - L2.p0[1], L2.p1[2] - L2.p0[2]};
      if (!is_zero(d1) && !is_zero(d2) && !is_zero(cross_d(d1, d2))) break;
    }
    Group x{GroupKind::Coincident, {}, 0};
    for (int i = 0; i < 2; ++i) {
      const auto [a, b] = L1.pair(rng_);
      x.members.push_back(add(lpi_recipe(a, b, plane_through(L2))));
      const auto [c, d] = L2.pair(rng_);
      x.members.push_back(add(lpi_recipe(c, d, plane_through(L1))));
    }
    x.members.push_back(tpi({plane_through(L1), plane_through(L1), plane_through(L2)}));
    x.members.push_back(tpi({Q.triple(rng_), plane_through(L1), plane_through(L2)}));
    x.members.push_back(tpi({plane_through(L2), plane_through(L1), plane_through(L2)}));
    const auto a = L1.pair(rng_);
    const auto X = exact_lpi(a.first, a.second, plane_through(L2));
    Point e;
    if (X && representable((*X)[0], e[0]) && representable((*X)[1], e[1]) && representable((*X)[2], e[2]))
      x.members.push_back(add(explicit_recipe(e)));
    Group on_q{GroupKind::Coplanar, x.members, Q.axes};
    for (const LineSpec* L : {&L1, &L2}) {
      Group g{GroupKind::Collinear, x.members, 0};
      for (int i = 0; i < 2; ++i) {
        const int m = add(explicit_recipe(L->point(rng_)));
        g.members.push_back(m);
        on_q.members.push_back(m);
      }
      groups_.push_back(g);
    }
    on_q.members.push_back(add(lpi_recipe(any_point(), any_point(), Q.triple(rng_))));
    groups_.push_back(x);
    groups_.push_back(on_q);
  }

  // Points in general position: explicit, LPIs and TPIs of random lines and planes.
  void random_points(int n) {
    for (int i = 0; i < n; ++i) {
      switch (rng_.uniform(0, 2)) {
        case 0:
          add(explicit_recipe(any_point()));
          break;
        case 1:
          add(lpi_recipe(any_point(), any_point(), any_triple()));
          break;
        default:
          add(tpi_recipe({any_triple(), any_triple(), any_triple()}));
          break;
      }
    }
  }

  // Maps every recipe by t (identity if that is not exact), builds the points through the
  // library and the reference, and sorts out undefined ones.
  Scene finish(const Transform& t) {
    Scene s;
    std::vector<Recipe> rs = recipes_;
    bool exact = true;
    for (Recipe& r : rs)
      for (int i = 0; i < r.count() && exact; ++i) exact = apply(t, r.in[i], r.in[i]);
    if (exact) {
      s.transform = t;
    } else {
      rs = recipes_;
    }
    std::vector<int> index(rs.size(), -1);
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const auto ref = exact_point(rs[i]);
      const auto built = build(rs[i], rng_.percent(25));
      if (!ref) {
        (built ? s.wrongly_accepted : s.refused).push_back(rs[i]);
      } else if (!built) {
        s.wrongly_refused.push_back(rs[i]);
      } else {
        index[i] = static_cast<int>(s.points.size());
        s.points.push_back({rs[i], *built, *ref, common_denominator(*ref)});
      }
    }
    for (const Group& g : groups_) {
      Group h{g.kind, {}, g.axes};
      for (int m : g.members)
        if (index[m] >= 0 && std::find(h.members.begin(), h.members.end(), index[m]) == h.members.end())
          h.members.push_back(index[m]);
      if (h.members.size() >= 2) s.groups.push_back(std::move(h));
    }
    return s;
  }

 private:
  int add(const Recipe& r) {
    recipes_.push_back(r);
    return static_cast<int>(recipes_.size()) - 1;
  }

  Rng& rng_;
  bool grid_;
  std::vector<Recipe> recipes_;
  std::vector<Group> groups_;
};

// A scene of about 70 points: two planes with their points, a line, an explicit point and
// an implicit point built several ways, (grid) two line crossings, and random points. 70%
// on the integer grid, 30% from random doubles; then a random exact transform.
inline Scene random_scene(Rng& rng) {
  const bool grid = rng.percent(70);
  SceneBuilder b(rng, grid);
  const PlaneSpec p1 = b.plane();
  const int g1 = b.plane_structure(p1);
  b.line_structure(p1, g1);
  const PlaneSpec p2 = b.plane();
  const int g2 = b.plane_structure(p2);
  b.line_structure(p2, g2);
  b.vertex_structure();
  b.implicit_coincidence(p1);
  if (grid) {
    b.crossing_structure();
    b.crossing_structure();
  } else {
    b.vertex_structure();
    b.implicit_coincidence(p2);
  }
  b.random_points(rng.uniform(6, 10));
  return b.finish(random_transform(rng, grid));
}

// ---------------------------------------------------------------------------------------
// Driving tests on scenes.

// Drives scenes until `target` cases have run; `body(scene, rng, left)` returns the number
// of cases it ran on one scene (at most `left`).
template <class Body>
void run_scenes(std::uint64_t salt, long long target, Body body) {
  Rng rng(seed_for(salt));
  for (long long done = 0; done < target;) {
    const Scene s = random_scene(rng);
    if (s.points.size() < 4) continue;
    done += body(s, rng, target - done);
  }
}

// Random operands: n distinct members of a random group of `kind` (with the axis bits
// `axes`), or any points.
class Picker {
 public:
  Picker(const Scene& s, Rng& rng) : s_(s), rng_(rng) {}

  int any() { return rng_.uniform(0, static_cast<int>(s_.points.size()) - 1); }

  bool from_group(GroupKind kind, int n, int axes, int* out) {
    std::vector<const Group*> fit;
    for (const auto& g : s_.groups)
      if (g.kind == kind && static_cast<int>(g.members.size()) >= n && (g.axes & axes) == axes) fit.push_back(&g);
    if (fit.empty()) return false;
    std::vector<int> m = fit[rng_.uniform(0, static_cast<int>(fit.size()) - 1)]->members;
    for (int i = 0; i < n; ++i) {
      std::swap(m[i], m[rng_.uniform(i, static_cast<int>(m.size()) - 1)]);
      out[i] = m[i];
    }
    return true;
  }

 private:
  const Scene& s_;
  Rng& rng_;
};

inline std::string transform_string(const Transform& t) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "(scene map: shift {%a, %a, %a}, scale 2^{%d, %d, %d})", t.shift[0], t.shift[1],
                t.shift[2], t.exponent[0], t.exponent[1], t.exponent[2]);
  return buf;
}

// The operands of a failing case, pasteable (hex) and with their exact coordinates.
inline std::string operands(const Scene& s, const int* idx, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) {
    const auto& p = s.points[idx[i]];
    out +=
        std::string("  ") + char('a' + i) + " = " + describe(p.recipe) + "\n      exact " + to_string(p.exact) + "\n";
  }
  return out + "  " + transform_string(s.transform);
}

}  // namespace tritri_test
