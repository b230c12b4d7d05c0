// tests/support/implicit_recipes.h
//
// Implicit points (explicit / LPI / TPI) by their definitions, for the implicit-backend
// tests and benchmark:
//   Recipe          the defining explicit points of a point, printable in hex floats
//                   (describe); build() makes it through the library, exact_point() from
//                   the definition in rationals (exact_oracle.h)
//   Transform       an exact affine map (per-axis power-of-two scaling and translation)
//                   that keeps every incidence between lines and planes; apply(),
//                   random_transform() (from subnormal to near DBL_MAX)
//   moved, unit, cross_d, is_zero, reordered   small exact helpers on double points and
//                   plane triples
// All randomness comes from the seeded Rng of pair_generators.h, so runs are reproducible.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <tritri/tritri.h>

#include "exact_oracle.h"
#include "pair_generators.h"

namespace tritri_test {

using tritri::ImplicitPoint;
using PointKind = ImplicitPoint::Kind;
using Triple = std::array<Point, 3>;  // three points spanning a plane

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

// The point from its definition in rationals; nullopt when it is undefined.
inline std::optional<Q3> exact_point(const Recipe& r) {
  const auto& v = r.in;
  if (r.kind == PointKind::Explicit) return exact(v[0]);
  if (r.kind == PointKind::LPI) return exact_lpi(v[0], v[1], {v[2], v[3], v[4]});
  return exact_tpi({Triple{v[0], v[1], v[2]}, Triple{v[3], v[4], v[5]}, Triple{v[6], v[7], v[8]}});
}

// ---------------------------------------------------------------------------------------
// Double points and triples.

// p + s d
inline Point moved(const Point& p, const Point& d, double s) {
  return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
}
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
    case 2:
      break;
    case 3:
    case 4:
      t.exponent.fill(rng.uniform(-60, 60));
      break;
    case 5:
    case 6:
      for (int& e : t.exponent) e = rng.uniform(-60, 60);
      break;
    case 7:
      t.exponent.fill(rng.percent(50) ? 300 : -300);
      break;
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

}  // namespace tritri_test
