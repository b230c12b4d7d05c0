// tests/implicit_generators.h
//
// Implicit points (explicit / LPI / TPI) for the implicit-backend tests and benchmark:
//
//   - Recipe: the defining explicit points of a point, printable in hex floats;
//   - an exact reference, written from the definitions in GMP rationals and independent of
//     the library's homogeneous coordinates and of tritri::to_exact:
//       LPI = p + (n.(r-p)) / (n.(q-p)) (q-p), n = (s-r) x (t-r);
//       TPI = the solution of the 3x3 system n_i . x = n_i . a_i by Cramer's rule;
//     and reference predicates (orient3d, orient2d, lexicographic compare) on those rationals;
//   - Scene: a random set of points with exact coincidences by construction (points on one
//     plane, on one line, one point built in several ways), mapped by an exact affine map
//     (per-axis power-of-two scaling, translation; from subnormal to near DBL_MAX) so that
//     magnitudes mix;
//   - Soup: triangles with the LPIs where their edges cross the other triangles' planes and
//     several representations of every point, for sub-triangle pairs (classify tests).
//
// All randomness comes from the seeded Rng of pair_generators.h, so runs are reproducible.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tritri/tritri.h>

#include "pair_generators.h"

namespace tritri_test {

using tritri::ImplicitPoint;
using PointKind = ImplicitPoint::Kind;
using Triple = std::array<Point, 3>;  // three points spanning a plane

inline std::uint64_t seed_for(std::uint64_t salt) {
  const char* s = std::getenv("TRITRI_TEST_SEED");
  const std::uint64_t base = (s != nullptr && *s != '\0') ? std::strtoull(s, nullptr, 10) : 20240917u;
  return base * 0x9E3779B97F4A7C15ull + salt;
}

template <class T>
void shuffle(T* first, int n, Rng& rng) {
  for (int i = n - 1; i > 0; --i) std::swap(first[i], first[rng.uniform(0, i)]);
}

// ---------------------------------------------------------------------------------------
// Recipes

struct Recipe {
  PointKind kind = PointKind::Explicit;
  std::array<Point, 9> in{};  // explicit: in[0]; LPI: p, q, r, s, t; TPI: three plane triples
  int count() const { return kind == PointKind::Explicit ? 1 : (kind == PointKind::LPI ? 5 : 9); }
};

inline Recipe explicit_recipe(const Point& p) {
  Recipe r;
  r.in[0] = p;
  return r;
}

inline Recipe lpi_recipe(const Point& p, const Point& q, const Triple& plane) {
  Recipe r;
  r.kind = PointKind::LPI;
  r.in[0] = p;
  r.in[1] = q;
  for (int i = 0; i < 3; ++i) r.in[2 + i] = plane[i];
  return r;
}

inline Recipe tpi_recipe(const std::array<Triple, 3>& planes) {
  Recipe r;
  r.kind = PointKind::TPI;
  for (int i = 0; i < 9; ++i) r.in[i] = planes[i / 3][i % 3];
  return r;
}

inline const char* kind_name(PointKind k) {
  return k == PointKind::Explicit ? "explicit" : (k == PointKind::LPI ? "LPI" : "TPI");
}
inline int kind_index(PointKind k) { return k == PointKind::Explicit ? 0 : (k == PointKind::LPI ? 1 : 2); }

inline std::string describe(const Recipe& r) {
  std::string s = std::string(kind_name(r.kind)) + "(";
  for (int i = 0; i < r.count(); ++i) s += (i ? ", " : "") + to_hex(r.in[i]);
  return s + ")";
}

// The point through the library: try_lpi / try_tpi with std::array arguments, or with
// explicit ImplicitPoint arguments when `as_points`.
inline std::optional<ImplicitPoint> build(const Recipe& r, bool as_points = false) {
  const auto& v = r.in;
  if (r.kind == PointKind::Explicit) return ImplicitPoint::explicit_point(v[0]);
  if (as_points) {
    std::array<ImplicitPoint, 9> e;
    for (int i = 0; i < r.count(); ++i) e[i] = ImplicitPoint::explicit_point(v[i]);
    if (r.kind == PointKind::LPI) return ImplicitPoint::try_lpi(e[0], e[1], e[2], e[3], e[4]);
    return ImplicitPoint::try_tpi(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]);
  }
  if (r.kind == PointKind::LPI) return ImplicitPoint::try_lpi(v[0], v[1], v[2], v[3], v[4]);
  return ImplicitPoint::try_tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
}

// ---------------------------------------------------------------------------------------
// The exact reference (GMP rationals; mpq_class(double) is exact).

using QPoint = std::array<mpq_class, 3>;

inline QPoint to_q(const Point& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
inline QPoint q_sub(const QPoint& a, const QPoint& b) {
  return {mpq_class(a[0] - b[0]), mpq_class(a[1] - b[1]), mpq_class(a[2] - b[2])};
}
inline QPoint q_cross(const QPoint& a, const QPoint& b) {
  return {mpq_class(a[1] * b[2] - a[2] * b[1]), mpq_class(a[2] * b[0] - a[0] * b[2]),
          mpq_class(a[0] * b[1] - a[1] * b[0])};
}
inline mpq_class q_dot(const QPoint& a, const QPoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Normal (b-a) x (c-a) of the plane through a triple.
inline QPoint q_normal(const Triple& t) {
  const QPoint a = to_q(t[0]);
  return q_cross(q_sub(to_q(t[1]), a), q_sub(to_q(t[2]), a));
}

// p + (n.(r-p)) / (n.(q-p)) (q-p); nullopt when n.(q-p) = 0 (also for p == q or collinear r, s, t).
inline std::optional<QPoint> exact_lpi(const Point& p, const Point& q, const Triple& plane) {
  const QPoint P = to_q(p), R = to_q(plane[0]);
  const QPoint n = q_normal(plane);
  const QPoint d = q_sub(to_q(q), P);
  const mpq_class den = q_dot(n, d);
  if (den == 0) return std::nullopt;
  const mpq_class lambda = q_dot(n, q_sub(R, P)) / den;
  return QPoint{mpq_class(P[0] + lambda * d[0]), mpq_class(P[1] + lambda * d[1]), mpq_class(P[2] + lambda * d[2])};
}

inline mpq_class q_det3(const mpq_class (&m)[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Plane i is n_i . x = n_i . a_i; Cramer's rule on the 3x3 system; nullopt when singular.
inline std::optional<QPoint> exact_tpi(const std::array<Triple, 3>& planes) {
  mpq_class m[3][3], k[3];
  for (int i = 0; i < 3; ++i) {
    const QPoint n = q_normal(planes[i]);
    for (int j = 0; j < 3; ++j) m[i][j] = n[j];
    k[i] = q_dot(n, to_q(planes[i][0]));
  }
  const mpq_class det = q_det3(m);
  if (det == 0) return std::nullopt;
  QPoint x;
  for (int j = 0; j < 3; ++j) {
    mpq_class mj[3][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) mj[i][c] = c == j ? k[i] : m[i][c];
    x[j] = q_det3(mj) / det;
  }
  return x;
}

inline std::optional<QPoint> exact_point(const Recipe& r) {
  const auto& v = r.in;
  if (r.kind == PointKind::Explicit) return to_q(v[0]);
  if (r.kind == PointKind::LPI) return exact_lpi(v[0], v[1], {v[2], v[3], v[4]});
  return exact_tpi({Triple{v[0], v[1], v[2]}, Triple{v[3], v[4], v[5]}, Triple{v[6], v[7], v[8]}});
}

// A rational point over one positive common denominator, for fast exact determinants.
struct ZPoint {
  std::array<mpz_class, 3> num;
  mpz_class den;
};

inline ZPoint common_denominator(const QPoint& q) {
  ZPoint z;
  z.den = 1;
  for (const mpq_class& c : q) mpz_lcm(z.den.get_mpz_t(), z.den.get_mpz_t(), c.get_den_mpz_t());
  for (int k = 0; k < 3; ++k) z.num[k] = q[k].get_num() * (z.den / q[k].get_den());
  return z;
}

inline int sgn(const mpz_class& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// sign det[b-a; c-a; d-a]. Row i is x_i D_a - x_a D_i = D_a D_i (p_i - p_a), a positive
// multiple of the difference.
inline int exact_orient3d(const ZPoint& a, const ZPoint& b, const ZPoint& c, const ZPoint& d) {
  const ZPoint* r[3] = {&b, &c, &d};
  mpz_class m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = r[i]->num[k] * a.den - a.num[k] * r[i]->den;
  const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

// The projected coordinates of a plane: XY -> (x, y), YZ -> (y, z), ZX -> (z, x).
inline std::array<int, 2> projected_axes(tritri::Plane plane) {
  switch (plane) {
    case tritri::Plane::XY: return {0, 1};
    case tritri::Plane::YZ: return {1, 2};
    default: return {2, 0};
  }
}

// The projection that drops axis k (in which a direction along axis k vanishes).
inline tritri::Plane projection_dropping(int k) {
  return k == 2 ? tritri::Plane::XY : (k == 0 ? tritri::Plane::YZ : tritri::Plane::ZX);
}

// sign det[b-a; c-a] on projected coordinates.
inline int exact_orient2d(const ZPoint& a, const ZPoint& b, const ZPoint& c, tritri::Plane plane) {
  const auto ax = projected_axes(plane);
  mpz_class m[2][2];
  const ZPoint* r[2] = {&b, &c};
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) m[i][k] = r[i]->num[ax[k]] * a.den - a.num[ax[k]] * r[i]->den;
  return sgn(mpz_class(m[0][0] * m[1][1] - m[0][1] * m[1][0]));
}

// Lexicographic (x, y, z) comparison: -1, 0, +1.
inline int exact_compare(const QPoint& a, const QPoint& b) {
  for (int k = 0; k < 3; ++k) {
    const int c = cmp(a[k], b[k]);
    if (c != 0) return c < 0 ? -1 : 1;
  }
  return 0;
}

inline bool q_collinear(const QPoint& a, const QPoint& b, const QPoint& c) {
  const QPoint n = q_cross(q_sub(b, a), q_sub(c, a));
  return n[0] == 0 && n[1] == 0 && n[2] == 0;
}

// True when the rational is a double (then `out` is that double).
inline bool representable(const mpq_class& q, double& out) {
  out = q.get_d();
  return std::isfinite(out) && mpq_class(out) == q;
}

inline std::string q_string(const QPoint& q) {
  return "(" + q[0].get_str() + ", " + q[1].get_str() + ", " + q[2].get_str() + ")";
}

// ---------------------------------------------------------------------------------------
// Exact affine maps: (p + shift) * 2^exponent per axis. Lines, planes and the incidences
// between them are preserved, so every coincidence built before the map survives it.

struct Transform {
  Point shift{0, 0, 0};
  std::array<int, 3> exponent{0, 0, 0};
};

// `out` = t(p); false when that is not exact (the sum rounds, or the scaling under- or
// overflows).
inline bool apply(const Transform& t, const Point& p, Point& out) {
  Point r;
  for (int k = 0; k < 3; ++k) {
    const double s = p[k] + t.shift[k];
    const double dv = s - p[k];  // Knuth's two-sum: the rounding error of s must be zero
    if ((p[k] - (s - dv)) + (t.shift[k] - dv) != 0) return false;
    const double y = std::ldexp(s, t.exponent[k]);
    if (!std::isfinite(y) || std::ldexp(y, -t.exponent[k]) != s) return false;
    r[k] = y;
  }
  out = r;
  return true;
}

// Identity, uniform or per-axis scalings by 2^k with k in [-60, 60], huge and tiny ones
// (2^+-300; rarely 2^+-600, 2^+-900, 2^1000, 2^1010 and subnormal 2^-1040, 2^-1068, where
// the filters' products over- or underflow), and translations by small or large integers
// when `shift` is allowed. Maps that are not exact for some point fall back to the identity.
inline Transform random_transform(Rng& rng, bool shift) {
  Transform t;
  switch (rng.uniform(0, 9)) {
    case 0:
    case 1:
    case 2: break;
    case 3:
    case 4: t.exponent.fill(rng.uniform(-60, 60)); break;
    case 5:
    case 6:
      for (int& e : t.exponent) e = rng.uniform(-60, 60);
      break;
    case 7: t.exponent.fill(rng.percent(50) ? 300 : -300); break;
    case 8: {
      static constexpr int kMixed[] = {-300, -60, 0, 60, 300};
      for (int& e : t.exponent) e = kMixed[rng.uniform(0, 4)];
      break;
    }
    default: {
      static constexpr int kExtreme[] = {-1068, -1040, -900, -600, 600, 900, 1000, 1010};
      t.exponent.fill(kExtreme[rng.uniform(0, 7)]);
      break;
    }
  }
  if (shift && rng.percent(40)) {
    const double unit = rng.percent(50) ? 1.0 : 0x1p30;
    for (double& s : t.shift) s = unit * rng.uniform(-4, 4);
  }
  return t;
}

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
  QPoint exact;
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

// p + s d
inline Point moved(const Point& p, const Point& d, double s) { return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]}; }
inline Point unit(int k) {
  Point e{0, 0, 0};
  e[k] = 1;
  return e;
}
inline Point cross_d(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool is_zero(const Point& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// The same plane, its triple rotated and possibly reversed.
inline Triple reordered(Triple t, Rng& rng) {
  std::rotate(t.begin(), t.begin() + rng.uniform(0, 2), t.end());
  if (rng.percent(50)) std::swap(t[1], t[2]);
  return t;
}

// Bit k set when the plane of t contains the direction of axis k (normal[k] == 0).
inline int contained_axes(const Triple& t) {
  const QPoint n = q_normal(t);
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
        auto small = [&] { return Point{double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2)), double(rng_.uniform(-2, 2))}; };
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
    for (int i = 0; i < n_explicit; ++i) g.members.push_back(add(explicit_recipe(grid_ ? L.point(rng_) : (i ? L.p1 : L.p0))));
    for (int i = rng_.uniform(3, 5); i > 0; --i) {
      const auto [a, b] = L.pair(rng_);
      g.members.push_back(add(lpi_recipe(a, b, !in_plane && rng_.percent(20) ? P.triple(rng_) : any_triple())));
    }
    for (int i = rng_.uniform(2, 3); i > 0; --i) g.members.push_back(tpi({plane_through(L), plane_through(L), any_triple()}));
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
    for (int i = rng_.uniform(2, 3); i > 0; --i) g.members.push_back(tpi({T.triple(rng_), plane_through(L), plane_through(L)}));
    groups_.push_back(g);
  }

  // Grid only: X where two lines of a lattice plane Q cross, as LPIs of either line with a
  // plane through the other, TPIs of planes through the lines (and Q), and explicitly when X
  // is a double point. Also collinear groups along both lines and a coplanar group on Q.
  void crossing_structure() {
    const PlaneSpec Q = [&] {
      PlaneSpec q;
      do q = plane(); while (!q.lattice);
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
        case 0: add(explicit_recipe(any_point())); break;
        case 1: add(lpi_recipe(any_point(), any_point(), any_triple())); break;
        default: add(tpi_recipe({any_triple(), any_triple(), any_triple()})); break;
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
// Soups: triangles, the points where their edges cross the other triangles' planes, and
// every point with several representations (explicit when it is a double point, LPIs,
// TPIs), for pairs of sub-triangles that share vertices, have vertices on each other's
// edges, are coplanar, ... All tests are exact (rationals), in the mapped coordinates.

struct SoupPoint {
  QPoint exact;
  std::vector<Recipe> reps;
};

struct Soup {
  std::vector<Triple> triangles;
  std::vector<SoupPoint> points;
  std::vector<std::vector<int>> on;  // on[t]: the points in the plane of triangle t
  std::vector<Recipe> rejected;      // representations whose exact point differed (generator bug)
};

class SoupBuilder {
 public:
  SoupBuilder(Rng& rng, bool grid, const Transform& t) : rng_(rng), grid_(grid), t_(t) {}

  Point any_point() {
    Point p;
    for (double& x : p) x = grid_ ? rng_.uniform(-3, 3) : rng_.symmetric_unit();
    return mapped(p);
  }

  Soup build(int n_triangles) {
    for (int i = 0; i < n_triangles; ++i) add_triangle();
    const int n = static_cast<int>(soup_.triangles.size());
    soup_.on.resize(n);
    for (int i = 0; i < n; ++i)
      for (const Point& v : soup_.triangles[i]) {
        const int id = point_id(explicit_recipe(v));
        soup_.on[i].push_back(id);
        // The line from v to a point off the plane meets the plane at v.
        const Point m = any_point();
        if (sign_against(soup_.triangles[i], m) != 0) add_rep(id, lpi_recipe(v, m, reordered(soup_.triangles[i], rng_)));
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) cross_edges(i, j);
    for (auto& on : soup_.on) {
      std::sort(on.begin(), on.end());
      on.erase(std::unique(on.begin(), on.end()), on.end());
    }
    return std::move(soup_);
  }

 private:
  Point mapped(const Point& p) {
    Point q;
    return apply(t_, p, q) ? q : p;
  }

  static int sign_against(const Triple& t, const Point& p) {
    const mpq_class d = q_dot(q_normal(t), q_sub(to_q(p), to_q(t[0])));
    return sgn(d);
  }

  // Triangles on the grid (or random), some sharing an edge or a vertex with an earlier
  // one, some coplanar with an earlier one (affine combinations of its vertices).
  void add_triangle() {
    for (;;) {
      Triple t{any_point(), any_point(), any_point()};
      if (!soup_.triangles.empty()) {
        const Triple& o = soup_.triangles[rng_.uniform(0, static_cast<int>(soup_.triangles.size()) - 1)];
        const int mode = rng_.uniform(0, 9);
        if (mode < 2) {
          t[0] = o[rng_.uniform(0, 2)];
        } else if (mode < 4) {
          const int e = rng_.uniform(0, 2);
          t[0] = o[e];
          t[1] = o[(e + 1) % 3];
        } else if (mode < 6 && grid_) {  // coplanar: affine combinations (w0 o0 + w1 o1 + w2 o2) / 4
          for (Point& v : t) {
            const int w0 = rng_.uniform(-2, 5), w1 = rng_.uniform(-2, 5);
            const int w2 = 4 - w0 - w1;
            for (int k = 0; k < 3; ++k) v[k] = (w0 * o[0][k] + w1 * o[1][k] + w2 * o[2][k]) * 0.25;
          }
        }
      }
      if (!q_collinear(to_q(t[0]), to_q(t[1]), to_q(t[2]))) {
        soup_.triangles.push_back(t);
        return;
      }
    }
  }

  // The id of the point of r (a new point if none has its exact coordinates).
  int point_id(const Recipe& r) {
    const auto q = exact_point(r);
    for (std::size_t i = 0; i < soup_.points.size(); ++i)
      if (soup_.points[i].exact == *q) {
        add_rep(static_cast<int>(i), r);
        return static_cast<int>(i);
      }
    soup_.points.push_back({*q, {r}});
    Point e;  // a point that is a double point also gets its explicit representation
    if (r.kind != PointKind::Explicit && representable((*q)[0], e[0]) && representable((*q)[1], e[1]) &&
        representable((*q)[2], e[2]))
      soup_.points.back().reps.push_back(explicit_recipe(e));
    return static_cast<int>(soup_.points.size()) - 1;
  }

  void add_rep(int id, const Recipe& r) {
    const auto q = exact_point(r);
    if (!q) return;  // undefined alternative (e.g. a random plane through the line)
    if (*q != soup_.points[id].exact) {
      soup_.rejected.push_back(r);
      return;
    }
    for (const Recipe& o : soup_.points[id].reps)
      if (o.kind == r.kind && o.in == r.in) return;
    soup_.points[id].reps.push_back(r);
  }

  // Edges of triangle i crossing (or touching) the plane of triangle j.
  void cross_edges(int i, int j) {
    const Triple& T = soup_.triangles[i];
    const Triple& U = soup_.triangles[j];
    int s[3];
    for (int k = 0; k < 3; ++k) s[k] = sign_against(U, T[k]);
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      if (s[k] == 0) {  // vertex k of T lies in U's plane
        soup_.on[j].push_back(soup_.on[i][k]);
        // The line of an edge that leaves U's plane meets it at the vertex.
        if (s[l] != 0) add_rep(soup_.on[i][k], lpi_recipe(T[k], T[l], reordered(U, rng_)));
        continue;
      }
      if (s[k] * s[l] >= 0) continue;
      const Point a = T[k], b = T[l];
      const int id = point_id(lpi_recipe(a, b, reordered(U, rng_)));
      soup_.on[i].push_back(id);
      soup_.on[j].push_back(id);
      add_rep(id, lpi_recipe(b, a, reordered(U, rng_)));
      std::array<Triple, 3> planes = {reordered(U, rng_), reordered(T, rng_), reordered({a, b, any_point()}, rng_)};
      shuffle(planes.data(), 3, rng_);
      add_rep(id, tpi_recipe(planes));
      planes = {reordered(U, rng_), reordered({a, b, any_point()}, rng_), reordered({b, a, any_point()}, rng_)};
      shuffle(planes.data(), 3, rng_);
      add_rep(id, tpi_recipe(planes));
    }
  }

  Rng& rng_;
  bool grid_;
  Transform t_;
  Soup soup_;
};

// 4 to 6 triangles, 75% on the integer grid [-3, 3]^3, under a random exact transform.
inline Soup random_soup(Rng& rng) {
  const bool grid = rng.percent(75);
  const Transform t = random_transform(rng, grid);
  return SoupBuilder(rng, grid, t).build(rng.uniform(4, 6));
}

}  // namespace tritri_test
