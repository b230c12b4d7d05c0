// tests/support/orient_cases.h
//
// Generated cases for tritri::orient3d / orient2d on doubles (namespace tritri_test::
// orient): an orient3d case is 4 points in 3D, an orient2d case 3 points in 2D, mostly
// near-degenerate by construction:
//   families (Family, generate, kPlans)  exactly coplanar / collinear points on dyadic
//        grids, the same moved by a few ulps, per-axis power-of-two scalings from subnormal
//        to near DBL_MAX (straddling the filter and expansion thresholds), large
//        translations, special values and random doubles; mixed_case draws from all;
//   exact_sign   the sign from the exact oracle (exact_oracle.h); tritri_sign the
//        library's; naive_det plain doubles (statistics, and to show that a case is hard);
//   describe     a case in hex floats, pasteable.
// Randomness: a std::mt19937_64 with the std distributions (Rng here; not pair_generators'
// splitmix64, so that the cases stay the ones these tests were written with), seeded by
// orient_seed (TRITRI_TEST_SEED, test_scale.h).
#pragma once

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include "tritri/double_predicates.h"

#include "exact_oracle.h"
#include "test_scale.h"

namespace tritri_test::orient {

using tritri::Plane;
using tritri::Sign;

inline std::uint64_t orient_seed(std::uint64_t salt) { return seed_for(salt, 20240611u); }

// ---------------------------------------------------------------------------------------
// Points and cases: an orient3d case is 4 points in 3D, an orient2d case 3 points in 2D.

template <std::size_t N>
using Pt = std::array<double, N>;
template <std::size_t N>
using Case = std::array<Pt<N>, N + 1>;

inline int sign_of(Sign s) { return tritri::to_int(s); }

// The exact sign, from the oracle (exact_oracle.h).
inline int exact_sign(const Case<3>& p) { return orient3d(exact(p[0]), exact(p[1]), exact(p[2]), exact(p[3])); }

inline int exact_sign(const Case<2>& p) {
  auto lift = [](const Pt<2>& q) { return exact(Pt<3>{q[0], q[1], 0}); };
  return orient2d(lift(p[0]), lift(p[1]), lift(p[2]), tritri::Plane::XY);
}

inline Sign tritri_sign(const Case<3>& p) { return tritri::orient3d(p[0], p[1], p[2], p[3]); }
inline Sign tritri_sign(const Case<2>& p) {
  return tritri::orient2d(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]);
}

// Plain double evaluation, for statistics and for showing that hand-made cases are hard.
inline double naive_det(const Case<3>& p) {
  const double ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], uz = p[1][2] - p[0][2];
  const double vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1], vz = p[2][2] - p[0][2];
  const double wx = p[3][0] - p[0][0], wy = p[3][1] - p[0][1], wz = p[3][2] - p[0][2];
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}
inline double naive_det(const Case<2>& p) {
  return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
}
inline int naive_sign(double det) { return det > 0 ? 1 : (det < 0 ? -1 : 0); }  // NaN counts as 0

template <std::size_t N>
std::string describe(const Case<N>& p) {
  std::ostringstream os;
  os << "{";
  for (std::size_t i = 0; i <= N; ++i) {
    os << (i ? ", " : "") << "{";
    for (std::size_t k = 0; k < N; ++k) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%a", p[i][k]);
      os << (k ? ", " : "") << buf;
    }
    os << "}";
  }
  os << "}";
  return os.str();
}

template <std::size_t N>
bool all_finite(const Case<N>& p) {
  for (const auto& q : p)
    for (double x : q)
      if (!std::isfinite(x)) return false;
  return true;
}

// ---------------------------------------------------------------------------------------
// Random building blocks

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(g_);
  }
  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(g_) < p; }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }
  // A full 53-bit significand in [1, 2).
  double mantissa() { return 1.0 + std::ldexp(static_cast<double>(g_() >> 12), -52); }
  // k / 2^m with |k| <= 16, m <= 4: a small dyadic factor.
  double small_dyadic() { return std::ldexp(static_cast<double>(integer(-16, 16)), -static_cast<int>(integer(0, 4))); }
  double finite_bits() {
    for (;;) {
      const std::uint64_t b = g_();
      double x;
      static_assert(sizeof x == sizeof b);
      std::memcpy(&x, &b, sizeof x);
      if (std::isfinite(x)) return x;
    }
  }
  template <class C>
  void shuffle(C& c) {
    std::shuffle(c.begin(), c.end(), g_);
  }

 private:
  std::mt19937_64 g_;
};

// Exponent k with 2^(k-1) <= max |x| < 2^k over one axis of a case (0 if all zero).
template <std::size_t N>
inline int axis_exponent(const Case<N>& p, int axis) {
  double m = 0;
  for (const auto& q : p) m = std::max(m, std::fabs(q[axis]));
  int e = 0;
  std::frexp(m, &e);
  return m == 0 ? 0 : e;
}

// ---------------------------------------------------------------------------------------
// Base cases: exactly degenerate on a dyadic grid, or degenerate up to rounding.

// Integer points, the last one an exact dyadic affine combination of the first N, so all
// N+1 points are exactly coplanar (3D) or collinear (2D). Sometimes lower-dimensional:
// repeated points, all points on one line, or one axis constant.
template <std::size_t N>
Case<N> grid_degenerate(Rng& r) {
  static constexpr int kBits[] = {1, 2, 3, 4, 8, 16, 24};
  const double range = std::ldexp(1.0, kBits[r.integer(0, 6)]);
  Case<N> p{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < N; ++k)
      p[i][k] = static_cast<double>(r.integer(static_cast<std::int64_t>(-range), static_cast<std::int64_t>(range)));
  const int variant = static_cast<int>(r.integer(0, 19));
  if (variant == 0) p[1] = p[0];  // a repeated point
  if (variant == 1 && N == 3)     // first three collinear
    for (std::size_t k = 0; k < N; ++k) p[2][k] = p[0][k] + r.small_dyadic() * (p[1][k] - p[0][k]);
  double coef[N];
  for (std::size_t i = 1; i < N; ++i) coef[i] = r.small_dyadic();
  for (std::size_t k = 0; k < N; ++k) {
    double x = p[0][k];
    for (std::size_t i = 1; i < N; ++i) x += coef[i] * (p[i][k] - p[0][k]);  // exact: < 2^31, 1/16 grid
    p[N][k] = x;
  }
  if (variant == 2) {  // one axis constant
    const int axis = static_cast<int>(r.integer(0, N - 1));
    for (auto& q : p) q[axis] = p[0][axis];
  }
  return p;
}

// Random points with full significands, the last an affine combination rounded to double.
template <std::size_t N>
Case<N> rounded_degenerate(Rng& r) {
  Case<N> p{};
  const int e = static_cast<int>(r.integer(-4, 4));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < N; ++k) p[i][k] = std::ldexp(r.real(-1, 1), e);
  double coef[N];
  for (std::size_t i = 1; i < N; ++i) coef[i] = r.real(-1.5, 2.5);
  for (std::size_t k = 0; k < N; ++k) {
    double x = p[0][k];
    for (std::size_t i = 1; i < N; ++i) x += coef[i] * (p[i][k] - p[0][k]);
    p[N][k] = x;
  }
  return p;
}

template <std::size_t N>
Case<N> base_degenerate(Rng& r) {
  return r.chance(0.6) ? grid_degenerate<N>(r) : rounded_degenerate<N>(r);
}

// ---------------------------------------------------------------------------------------
// Transformations: translate, scale axes by powers of two, move by ulps, shuffle.

// Adds one large offset per axis; the offset has few significant bits half of the time
// so that the translated grid points often stay exact.
template <std::size_t N>
void translate(Case<N>& p, Rng& r, int min_shift, int max_shift) {
  for (std::size_t k = 0; k < N; ++k) {
    const int e = axis_exponent(p, k) + static_cast<int>(r.integer(min_shift, max_shift));
    const double m = r.chance(0.5) ? static_cast<double>(r.integer(1, 1024)) / 1024 : r.mantissa() / 2;
    const double offset = r.sign() * std::ldexp(m, e);
    for (auto& q : p) q[k] += offset;
  }
}

// Exponent ranges for per-axis scaling.
enum class Scales {
  Near1,          // [-8, 8]
  FilterEdge,     // around 2^-250 and 2^250 (the filter's range for differences)
  ExpansionEdge,  // around 2^-280 and 2^280 (the expansion stage's range for coordinates)
  Overflowing,    // products of differences overflow or underflow double
  Subnormal,      // into the subnormal range
  Huge,           // near DBL_MAX
  Anywhere,       // uniform over all exponents
};

inline int pick_exponent(Rng& r, Scales s) {
  switch (s) {
    case Scales::Near1:
      return static_cast<int>(r.integer(-8, 8));
    case Scales::FilterEdge:
      return static_cast<int>(r.sign() * r.integer(236, 264));
    case Scales::ExpansionEdge:
      return static_cast<int>(r.sign() * r.integer(266, 294));
    case Scales::Overflowing:
      return static_cast<int>(r.sign() * r.integer(330, 560));
    case Scales::Subnormal:
      return static_cast<int>(r.integer(-1100, -1000));
    case Scales::Huge:
      return static_cast<int>(r.integer(900, 1100));
    case Scales::Anywhere:
      return static_cast<int>(r.integer(-1100, 1100));
  }
  return 0;
}

inline Scales random_scales(Rng& r) { return static_cast<Scales>(r.integer(0, 6)); }

// Multiplies each axis by 2^k (k per axis, or one k for all), clamped so nothing
// overflows. Positive per-axis scaling keeps exact degeneracy whenever no bits are lost
// to the subnormal range.
template <std::size_t N>
void scale_axes(Case<N>& p, Rng& r, Scales s) {
  const bool same = r.chance(0.3);
  const int common = pick_exponent(r, s);
  for (std::size_t k = 0; k < N; ++k) {
    int e = same ? common : pick_exponent(r, s);
    e = std::min(e, 1024 - axis_exponent(p, k));
    for (auto& q : p) q[k] = std::ldexp(q[k], e);
  }
}

// Moves up to three coordinates by one to three ulps (a third of the cases: none).
template <std::size_t N>
void perturb(Case<N>& p, Rng& r) {
  const int moves = static_cast<int>(r.integer(0, 2)) == 0 ? 0 : static_cast<int>(r.integer(1, 3));
  for (int m = 0; m < moves; ++m) {
    double& x = p[r.integer(0, N)][r.integer(0, N - 1)];
    const double toward = r.sign() * HUGE_VAL;
    const int steps = r.chance(0.7) ? 1 : static_cast<int>(r.integer(2, 3));
    for (int s = 0; s < steps; ++s) {
      const double y = std::nextafter(x, toward);
      if (std::isfinite(y)) x = y;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Extreme inputs: random exponents, special values, bit patterns, differences that
// overflow, subnormal grids.

inline double special_value(Rng& r) {
  static const double kSpecial[] = {0.0,     1.0,      DBL_MIN, DBL_TRUE_MIN, DBL_MAX,  0x1p-250, 0x1p250, 0x1p-280,
                                    0x1p280, 0x1p-511, 0x1p511, 0x1p-1022,    0x1p1023, 3.0,      0.5};
  double x = kSpecial[r.integer(0, std::size(kSpecial) - 1)];
  if (r.chance(0.3)) x = std::nextafter(x, r.chance(0.5) ? 0.0 : HUGE_VAL);
  return r.sign() * x;
}

inline double random_exponent_value(Rng& r) {
  if (r.chance(0.1)) return 0.0;
  return r.sign() * std::ldexp(r.mantissa(), static_cast<int>(r.integer(-1075, 1023)));
}

template <std::size_t N>
Case<N> extreme_case(Rng& r) {
  for (;;) {
    Case<N> p{};
    switch (r.integer(0, 5)) {
      case 0:  // every coordinate with its own random exponent
        for (auto& q : p)
          for (double& x : q) x = random_exponent_value(r);
        break;
      case 1: {  // the same, last point an affine combination rounded to double
        for (auto& q : p)
          for (double& x : q) x = random_exponent_value(r);
        for (std::size_t k = 0; k < N; ++k) {
          double x = p[0][k];
          for (std::size_t i = 1; i < N; ++i) x += r.real(-1, 2) * (p[i][k] - p[0][k]);
          p[N][k] = x;
        }
        break;
      }
      case 2:  // grid points spread to [2^1023, 2^1024): differences overflow
        p = grid_degenerate<N>(r);
        for (std::size_t k = 0; k < N; ++k) {
          const int e = 1024 - axis_exponent(p, k);
          for (auto& q : p) q[k] = std::ldexp(q[k], e);
        }
        perturb(p, r);
        break;
      case 3: {  // grid points in the subnormal range (some lose bits)
        p = grid_degenerate<N>(r);
        for (std::size_t k = 0; k < N; ++k) {
          const int e = static_cast<int>(r.integer(-1074, -1040));
          for (auto& q : p) q[k] = std::ldexp(q[k], e);
        }
        perturb(p, r);
        break;
      }
      case 4:  // special values (often repeated, so often degenerate)
        for (auto& q : p)
          for (double& x : q) x = special_value(r);
        break;
      default:  // random finite bit patterns
        for (auto& q : p)
          for (double& x : q) x = r.finite_bits();
        break;
    }
    if (all_finite(p)) return p;
  }
}

template <std::size_t N>
Case<N> random_case(Rng& r) {
  Case<N> p{};
  const int kind = static_cast<int>(r.integer(0, 3));
  for (auto& q : p)
    for (double& x : q) {
      if (kind <= 1)
        x = r.real(-1, 1);
      else if (kind == 2)
        x = static_cast<double>(r.integer(-3, 3));  // small integers: often degenerate
      else
        x = r.sign() * std::ldexp(r.mantissa(), static_cast<int>(r.integer(-30, 30)));
    }
  return p;
}

// ---------------------------------------------------------------------------------------
// Families of generated cases.

enum class Family { Grid, Rounded, Scaled, Thresholds, Translated, Extreme, Random };

inline const char* family_name(Family f) {
  switch (f) {
    case Family::Grid:
      return "Grid";
    case Family::Rounded:
      return "Rounded";
    case Family::Scaled:
      return "Scaled";
    case Family::Thresholds:
      return "Thresholds";
    case Family::Translated:
      return "Translated";
    case Family::Extreme:
      return "Extreme";
    case Family::Random:
      return "Random";
  }
  return "?";
}

template <std::size_t N>
Case<N> generate(Family f, Rng& r) {
  Case<N> p{};
  switch (f) {
    case Family::Grid:
      p = grid_degenerate<N>(r);
      perturb(p, r);
      break;
    case Family::Rounded:
      p = rounded_degenerate<N>(r);
      perturb(p, r);
      break;
    case Family::Scaled:
      p = base_degenerate<N>(r);
      scale_axes(p, r, random_scales(r));
      perturb(p, r);
      break;
    case Family::Thresholds:
      p = base_degenerate<N>(r);
      if (r.chance(0.5)) translate(p, r, 1, 40);
      scale_axes(p, r, r.chance(0.5) ? Scales::FilterEdge : Scales::ExpansionEdge);
      perturb(p, r);
      break;
    case Family::Translated:
      p = base_degenerate<N>(r);
      translate(p, r, 4, 60);
      if (r.chance(0.3)) scale_axes(p, r, random_scales(r));
      perturb(p, r);
      break;
    case Family::Extreme:
      p = extreme_case<N>(r);
      break;
    case Family::Random:
      p = random_case<N>(r);
      break;
  }
  r.shuffle(p);
  return p;
}

struct FamilyPlan {
  Family family;
  long count;  // cases at scale 1.0
};

// 1,000,000 cases per predicate at scale 1.0.
inline constexpr FamilyPlan kPlans[] = {
    {Family::Grid, 250000},       {Family::Rounded, 150000}, {Family::Scaled, 200000}, {Family::Thresholds, 150000},
    {Family::Translated, 100000}, {Family::Extreme, 100000}, {Family::Random, 50000},
};

// A mixture of all families, for the property tests.
template <std::size_t N>
Case<N> mixed_case(Rng& r) {
  return generate<N>(kPlans[r.integer(0, std::size(kPlans) - 1)].family, r);
}

}  // namespace tritri_test::orient
