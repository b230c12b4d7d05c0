// tests/test_double_predicates.cpp
//
// tritri::orient3d / tritri::orient2d on doubles against an independent exact evaluation
// with GMP rationals (mpq_class(double) is exact), on inputs that are near-degenerate by
// construction: exactly coplanar / collinear points on dyadic grids, the same moved by a
// few ulps, per-axis power-of-two scalings that mix exponents from subnormal to near
// DBL_MAX (and straddle the filter and expansion thresholds), large translations,
// special values and random doubles. Also exact properties (permutation parity, exact
// scalings, negation, axis swaps, exact translations), agreement with CGAL::orientation
// on Epeck and Epick, and hand-made cases where naive double evaluation is wrong.
//
// Case counts scale with the environment variable TRITRI_TEST_SCALE (default 1.0; the
// sanitizer CI uses 0.1). At scale 1.0 each predicate sees 1,000,000 generated cases.
// Seeds are fixed; TRITRI_TEST_SEED (an integer) changes them.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tritri/cgal_kernel.h"
#include "tritri/double_kernel.h"
#include "tritri/double_predicates.h"

namespace {

using tritri::Plane;
using tritri::Sign;

// ---------------------------------------------------------------------------------------
// Configuration

double test_scale() {
  const char* s = std::getenv("TRITRI_TEST_SCALE");
  if (s == nullptr || *s == '\0') return 1.0;
  const double v = std::strtod(s, nullptr);
  return v > 0 ? v : 1.0;
}

// n scaled by TRITRI_TEST_SCALE, at least 1.
long scaled(long n) { return std::max(1L, std::lround(static_cast<double>(n) * test_scale())); }

std::uint64_t seed_for(std::uint64_t salt) {
  const char* s = std::getenv("TRITRI_TEST_SEED");
  const std::uint64_t base = (s != nullptr && *s != '\0') ? std::strtoull(s, nullptr, 10) : 20240611u;
  return base * 0x9E3779B97F4A7C15ull + salt;
}

// ---------------------------------------------------------------------------------------
// Points and cases: an orient3d case is 4 points in 3D, an orient2d case 3 points in 2D.

template <std::size_t N>
using Pt = std::array<double, N>;
template <std::size_t N>
using Case = std::array<Pt<N>, N + 1>;

int sign_of(Sign s) { return tritri::to_int(s); }

// The independent oracle: the determinant expanded by Sarrus' rule in exact rationals.
int exact_sign(const Case<3>& p) {
  mpq_class u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    const mpq_class a(p[0][k]);
    u[k] = mpq_class(p[1][k]) - a;
    v[k] = mpq_class(p[2][k]) - a;
    w[k] = mpq_class(p[3][k]) - a;
  }
  const mpq_class det = u[0] * v[1] * w[2] + u[1] * v[2] * w[0] + u[2] * v[0] * w[1] -
                        u[2] * v[1] * w[0] - u[1] * v[0] * w[2] - u[0] * v[2] * w[1];
  return sgn(det);
}

int exact_sign(const Case<2>& p) {
  const mpq_class ax(p[0][0]), ay(p[0][1]);
  const mpq_class det = (mpq_class(p[1][0]) - ax) * (mpq_class(p[2][1]) - ay) -
                        (mpq_class(p[1][1]) - ay) * (mpq_class(p[2][0]) - ax);
  return sgn(det);
}

Sign tritri_sign(const Case<3>& p) { return tritri::orient3d(p[0], p[1], p[2], p[3]); }
Sign tritri_sign(const Case<2>& p) {
  return tritri::orient2d(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]);
}

// Plain double evaluation, for statistics and for showing that hand-made cases are hard.
double naive_det(const Case<3>& p) {
  const double ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], uz = p[1][2] - p[0][2];
  const double vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1], vz = p[2][2] - p[0][2];
  const double wx = p[3][0] - p[0][0], wy = p[3][1] - p[0][1], wz = p[3][2] - p[0][2];
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}
double naive_det(const Case<2>& p) {
  return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
}
int naive_sign(double det) { return det > 0 ? 1 : (det < 0 ? -1 : 0); }  // NaN counts as 0

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
  void shuffle(C& c) { std::shuffle(c.begin(), c.end(), g_); }

 private:
  std::mt19937_64 g_;
};

// Exponent k with 2^(k-1) <= max |x| < 2^k over one axis of a case (0 if all zero).
template <std::size_t N>
int axis_exponent(const Case<N>& p, int axis) {
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
    for (std::size_t k = 0; k < N; ++k) p[i][k] = static_cast<double>(r.integer(static_cast<std::int64_t>(-range), static_cast<std::int64_t>(range)));
  const int variant = static_cast<int>(r.integer(0, 19));
  if (variant == 0) p[1] = p[0];                       // a repeated point
  if (variant == 1 && N == 3)                          // first three collinear
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
  Near1,         // [-8, 8]
  FilterEdge,    // around 2^-250 and 2^250 (the filter's range for differences)
  ExpansionEdge, // around 2^-280 and 2^280 (the expansion stage's range for coordinates)
  Overflowing,   // products of differences overflow or underflow double
  Subnormal,     // into the subnormal range
  Huge,          // near DBL_MAX
  Anywhere,      // uniform over all exponents
};

int pick_exponent(Rng& r, Scales s) {
  switch (s) {
    case Scales::Near1: return static_cast<int>(r.integer(-8, 8));
    case Scales::FilterEdge: return static_cast<int>(r.sign() * r.integer(236, 264));
    case Scales::ExpansionEdge: return static_cast<int>(r.sign() * r.integer(266, 294));
    case Scales::Overflowing: return static_cast<int>(r.sign() * r.integer(330, 560));
    case Scales::Subnormal: return static_cast<int>(r.integer(-1100, -1000));
    case Scales::Huge: return static_cast<int>(r.integer(900, 1100));
    case Scales::Anywhere: return static_cast<int>(r.integer(-1100, 1100));
  }
  return 0;
}

Scales random_scales(Rng& r) { return static_cast<Scales>(r.integer(0, 6)); }

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

double special_value(Rng& r) {
  static const double kSpecial[] = {0.0,          1.0,        DBL_MIN,    DBL_TRUE_MIN, DBL_MAX,
                                    0x1p-250,     0x1p250,    0x1p-280,   0x1p280,      0x1p-511,
                                    0x1p511,      0x1p-1022,  0x1p1023,   3.0,          0.5};
  double x = kSpecial[r.integer(0, std::size(kSpecial) - 1)];
  if (r.chance(0.3)) x = std::nextafter(x, r.chance(0.5) ? 0.0 : HUGE_VAL);
  return r.sign() * x;
}

double random_exponent_value(Rng& r) {
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
      if (kind <= 1) x = r.real(-1, 1);
      else if (kind == 2) x = static_cast<double>(r.integer(-3, 3));  // small integers: often degenerate
      else x = r.sign() * std::ldexp(r.mantissa(), static_cast<int>(r.integer(-30, 30)));
    }
  return p;
}

// ---------------------------------------------------------------------------------------
// Families of generated cases.

enum class Family { Grid, Rounded, Scaled, Thresholds, Translated, Extreme, Random };

const char* family_name(Family f) {
  switch (f) {
    case Family::Grid: return "Grid";
    case Family::Rounded: return "Rounded";
    case Family::Scaled: return "Scaled";
    case Family::Thresholds: return "Thresholds";
    case Family::Translated: return "Translated";
    case Family::Extreme: return "Extreme";
    case Family::Random: return "Random";
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
constexpr FamilyPlan kPlans[] = {
    {Family::Grid, 250000},       {Family::Rounded, 150000}, {Family::Scaled, 200000},
    {Family::Thresholds, 150000}, {Family::Translated, 100000}, {Family::Extreme, 100000},
    {Family::Random, 50000},
};

// Which stage the documented thresholds of double_predicates.h send a case to; only for
// the report printed by the tests (uses the header's evaluation order for the filter).
enum Stage { kTrivial, kFilter, kExpansion, kGmp, kStages };

template <std::size_t N>
Stage documented_stage(const Case<N>& p) {
  double m[N] = {};
  for (std::size_t i = 1; i <= N; ++i)
    for (std::size_t k = 0; k < N; ++k) m[k] = std::max(m[k], std::fabs(p[i][k] - p[0][k]));
  double prod = 1;
  bool in_range = true;
  for (std::size_t k = 0; k < N; ++k) {
    if (m[k] == 0) return kTrivial;
    in_range &= tritri::detail::in_filter_range(m[k]);
    prod *= m[k];
  }
  const double bound = (N == 3 ? tritri::detail::kOrient3dBound : tritri::detail::kOrient2dBound) * prod;
  if (in_range && std::fabs(naive_det(p)) > bound) return kFilter;
  for (const auto& q : p)
    for (double x : q)
      if (!tritri::detail::expansion_safe(x)) return kGmp;
  return kExpansion;
}

// Running totals printed at the end of the run.
struct Tally {
  long cases = 0, zero = 0, naive_wrong = 0, stage[kStages] = {};
  void add(const Tally& t) {
    cases += t.cases;
    zero += t.zero;
    naive_wrong += t.naive_wrong;
    for (int s = 0; s < kStages; ++s) stage[s] += t.stage[s];
  }
  void print(const std::string& what) const {
    std::printf("[ stats    ] %-28s %8ld cases: exact zero %7ld, naive double wrong %7ld; "
                "stages (documented thresholds): trivial %ld, filter %ld, expansion %ld, gmp %ld\n",
                what.c_str(), cases, zero, naive_wrong, stage[kTrivial], stage[kFilter],
                stage[kExpansion], stage[kGmp]);
  }
};
Tally g_total3, g_total2;

class TotalsReport : public ::testing::Environment {
 public:
  void TearDown() override {
    if (g_total3.cases) g_total3.print("orient3d total");
    if (g_total2.cases) g_total2.print("orient2d total");
  }
};
::testing::Environment* const g_report = ::testing::AddGlobalTestEnvironment(new TotalsReport);

constexpr int kMaxReportedFailures = 10;

// orient2d of 3D points whose projection onto `plane` is the 2D case; the dropped
// coordinate is unrelated junk, so reading the wrong axes shows up as wrong signs.
Pt<3> embed(const Pt<2>& q, Plane plane, double junk) {
  switch (plane) {
    case Plane::XY: return {q[0], q[1], junk};
    case Plane::YZ: return {junk, q[0], q[1]};
    case Plane::ZX: return {q[1], junk, q[0]};
  }
  return {};
}

// ---------------------------------------------------------------------------------------
// Generated cases against the rational oracle.

class GeneratedCases : public ::testing::TestWithParam<FamilyPlan> {};

TEST_P(GeneratedCases, Orient3dMatchesExactRationalSign) {
  const FamilyPlan plan = GetParam();
  Rng r(seed_for(100 + static_cast<int>(plan.family)));
  const long n = scaled(plan.count);
  Tally t;
  int failures = 0;
  for (long i = 0; i < n && failures < kMaxReportedFailures; ++i) {
    const Case<3> p = generate<3>(plan.family, r);
    const int want = exact_sign(p);
    const int got = sign_of(tritri_sign(p));
    ++t.cases;
    t.zero += want == 0;
    t.naive_wrong += naive_sign(naive_det(p)) != want;
    ++t.stage[documented_stage(p)];
    if (got != want) {
      ++failures;
      ADD_FAILURE() << "orient3d" << describe(p) << " = " << got << ", exact " << want;
    }
  }
  t.print(std::string("orient3d ") + family_name(plan.family));
  g_total3.add(t);
}

TEST_P(GeneratedCases, Orient2dMatchesExactRationalSignOnEveryPlane) {
  const FamilyPlan plan = GetParam();
  Rng r(seed_for(200 + static_cast<int>(plan.family)));
  const long n = scaled(plan.count);
  Tally t;
  int failures = 0;
  for (long i = 0; i < n && failures < kMaxReportedFailures; ++i) {
    const Case<2> p = generate<2>(plan.family, r);
    const int want = exact_sign(p);
    ++t.cases;
    t.zero += want == 0;
    t.naive_wrong += naive_sign(naive_det(p)) != want;
    ++t.stage[documented_stage(p)];
    const int got = sign_of(tritri_sign(p));
    if (got != want) {
      ++failures;
      ADD_FAILURE() << "orient2d" << describe(p) << " = " << got << ", exact " << want;
    }
    for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
      Pt<3> q[3];
      for (int j = 0; j < 3; ++j) q[j] = embed(p[j], plane, r.real(-1e6, 1e6));
      const int got3 = sign_of(tritri::orient2d(q[0], q[1], q[2], plane));
      if (got3 != want) {
        ++failures;
        ADD_FAILURE() << "orient2d on plane " << static_cast<int>(plane) << " of " << describe(p)
                      << " = " << got3 << ", exact " << want;
      }
    }
  }
  t.print(std::string("orient2d ") + family_name(plan.family));
  g_total2.add(t);
}

INSTANTIATE_TEST_SUITE_P(Families, GeneratedCases, ::testing::ValuesIn(kPlans),
                         [](const ::testing::TestParamInfo<FamilyPlan>& param_info) {
                           return std::string(family_name(param_info.param.family));
                         });

// ---------------------------------------------------------------------------------------
// Exact properties, without the oracle.

// A mixture of all families, for the property tests.
template <std::size_t N>
Case<N> mixed_case(Rng& r) {
  return generate<N>(kPlans[r.integer(0, std::size(kPlans) - 1)].family, r);
}

TEST(Orient3dProperties, SignFollowsPermutationParity) {
  Rng r(seed_for(300));
  std::array<int, 4> perm0 = {0, 1, 2, 3};
  for (long i = 0, n = scaled(20000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    const int s = sign_of(tritri_sign(p));
    std::array<int, 4> perm = perm0;
    do {
      int inversions = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) inversions += perm[a] > perm[b];
      const Case<3> q = {p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]]};
      const int parity = inversions % 2 ? -1 : 1;
      ASSERT_EQ(sign_of(tritri_sign(q)), parity * s)
          << describe(p) << " permuted " << perm[0] << perm[1] << perm[2] << perm[3];
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
}

TEST(Orient2dProperties, SignFollowsPermutationParity) {
  Rng r(seed_for(301));
  for (long i = 0, n = scaled(50000); i < n; ++i) {
    const Case<2> p = mixed_case<2>(r);
    const int s = sign_of(tritri_sign(p));
    // Cyclic rotations keep the sign, transpositions flip it.
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[1], p[2], p[0]})), s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[2], p[0], p[1]})), s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[1], p[0], p[2]})), -s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[0], p[2], p[1]})), -s) << describe(p);
    ASSERT_EQ(sign_of(tritri_sign(Case<2>{p[2], p[1], p[0]})), -s) << describe(p);
  }
}

// Applies f to every coordinate and reports whether every result is exact (as checked
// by the rational f_exact) so the transformed case has a predictable sign.
template <std::size_t N, class F, class FExact>
bool transform_exactly(const Case<N>& p, Case<N>& out, F f, FExact f_exact) {
  for (std::size_t i = 0; i <= N; ++i)
    for (std::size_t k = 0; k < N; ++k) {
      out[i][k] = f(p[i][k], k);
      if (!std::isfinite(out[i][k]) || mpq_class(out[i][k]) != f_exact(mpq_class(p[i][k]), k)) return false;
    }
  return true;
}

mpq_class times_power_of_two(const mpq_class& x, int e) {
  mpq_class y = x;
  if (e >= 0) mpq_mul_2exp(y.get_mpq_t(), y.get_mpq_t(), static_cast<unsigned long>(e));
  else mpq_div_2exp(y.get_mpq_t(), y.get_mpq_t(), static_cast<unsigned long>(-e));
  return y;
}

template <std::size_t N>
void check_exact_transformations(Rng& r, long n) {
  const int odd = N == 3 ? -1 : 1;  // sign factor of negating all N coordinates
  long scaled_checked = 0, translated_checked = 0;
  for (long i = 0; i < n; ++i) {
    const Case<N> p = mixed_case<N>(r);
    const int s = sign_of(tritri_sign(p));
    Case<N> q{};

    // Negating one axis flips the sign; negating all multiplies it by (-1)^N.
    const int axis = static_cast<int>(r.integer(0, N - 1));
    for (std::size_t j = 0; j <= N; ++j) {
      q[j] = p[j];
      q[j][axis] = -q[j][axis];
    }
    ASSERT_EQ(sign_of(tritri_sign(q)), -s) << describe(p) << " axis " << axis << " negated";
    for (std::size_t j = 0; j <= N; ++j)
      for (std::size_t k = 0; k < N; ++k) q[j][k] = -p[j][k];
    ASSERT_EQ(sign_of(tritri_sign(q)), odd * s) << describe(p) << " negated";

    // Swapping two axes flips the sign.
    for (std::size_t j = 0; j <= N; ++j) {
      q[j] = p[j];
      std::swap(q[j][0], q[j][N - 1]);
    }
    ASSERT_EQ(sign_of(tritri_sign(q)), -s) << describe(p) << " axes swapped";

    // Positive power-of-two scaling per axis keeps the sign (when it is exact).
    int e[N];
    for (std::size_t k = 0; k < N; ++k) e[k] = static_cast<int>(r.integer(-300, 300));
    if (transform_exactly<N>(
            p, q, [&](double x, int k) { return std::ldexp(x, e[k]); },
            [&](const mpq_class& x, int k) { return times_power_of_two(x, e[k]); })) {
      ++scaled_checked;
      ASSERT_EQ(sign_of(tritri_sign(q)), s) << describe(p) << " scaled to " << describe(q);
    }

    // Translation keeps the sign (when every translated coordinate is exact).
    double t[N];
    for (std::size_t k = 0; k < N; ++k) {
      const int shift = std::min(1000, axis_exponent(p, k) - static_cast<int>(r.integer(-8, 30)));
      t[k] = r.sign() * std::ldexp(static_cast<double>(r.integer(1, 255)), shift);
    }
    if (transform_exactly<N>(
            p, q, [&](double x, int k) { return x + t[k]; },
            [&](const mpq_class& x, int k) { return mpq_class(x + mpq_class(t[k])); })) {
      ++translated_checked;
      ASSERT_EQ(sign_of(tritri_sign(q)), s) << describe(p) << " translated to " << describe(q);
    }
  }
  // The generators must leave enough exact cases for the last two checks to mean something.
  EXPECT_GT(scaled_checked, n / 10);
  EXPECT_GT(translated_checked, n / 20);
  std::printf("[ stats    ] exact scalings checked %ld, exact translations checked %ld of %ld\n",
              scaled_checked, translated_checked, n);
}

TEST(Orient3dProperties, ExactNegationsAxisSwapsScalingsAndTranslationsActAsExpected) {
  Rng r(seed_for(302));
  check_exact_transformations<3>(r, scaled(20000));
}

TEST(Orient2dProperties, ExactNegationsAxisSwapsScalingsAndTranslationsActAsExpected) {
  Rng r(seed_for(303));
  check_exact_transformations<2>(r, scaled(20000));
}

// ---------------------------------------------------------------------------------------
// Agreement with CGAL.

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class CK>
typename CK::Point_3 to_cgal(const Pt<3>& p) {
  return typename CK::Point_3(p[0], p[1], p[2]);
}

int from_cgal(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0); }

TEST(Orient3dAgreesWithCgal, OrientationOnEpeckAndEpick) {
  Rng r(seed_for(400));
  for (long i = 0, n = scaled(5000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    const int got = sign_of(tritri_sign(p));
    const int epeck = from_cgal(CGAL::orientation(to_cgal<Epeck>(p[0]), to_cgal<Epeck>(p[1]),
                                                  to_cgal<Epeck>(p[2]), to_cgal<Epeck>(p[3])));
    const int epick = from_cgal(CGAL::orientation(to_cgal<Epick>(p[0]), to_cgal<Epick>(p[1]),
                                                  to_cgal<Epick>(p[2]), to_cgal<Epick>(p[3])));
    ASSERT_EQ(got, epeck) << describe(p);
    ASSERT_EQ(got, epick) << describe(p);
  }
}

// The kernel adapters must agree with the double predicates on every projection.
TEST(Orient2dAgreesWithCgal, CgalKernelProjectionsOnEveryPlane) {
  Rng r(seed_for(401));
  for (long i = 0, n = scaled(3000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
      const int got = sign_of(tritri::orient2d(p[0], p[1], p[2], plane));
      const int epeck = sign_of(tritri::CgalKernel<Epeck>::orient2d(
          to_cgal<Epeck>(p[0]), to_cgal<Epeck>(p[1]), to_cgal<Epeck>(p[2]), plane));
      const int epick = sign_of(tritri::CgalKernel<Epick>::orient2d(
          to_cgal<Epick>(p[0]), to_cgal<Epick>(p[1]), to_cgal<Epick>(p[2]), plane));
      ASSERT_EQ(got, epeck) << describe(p) << " plane " << static_cast<int>(plane);
      ASSERT_EQ(got, epick) << describe(p) << " plane " << static_cast<int>(plane);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Conventions and hand-made cases.

TEST(PredicateConventions, PositiveForRightHandedTetrahedronAndCounterClockwiseTriangle) {
  const Pt<3> o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(tritri::orient3d(o, x, y, z), Sign::Positive);  // det(I) = 1, as CGAL
  EXPECT_EQ(tritri::orient3d(o, y, x, z), Sign::Negative);
  EXPECT_EQ(tritri::orient3d(o, x, y, Pt<3>{5, -7, 0}), Sign::Zero);
  EXPECT_EQ(tritri::orient2d(0, 0, 1, 0, 0, 1), Sign::Positive);
  // Each projection is seen from the positive side of the dropped axis.
  EXPECT_EQ(tritri::orient2d(o, x, y, Plane::XY), Sign::Positive);
  EXPECT_EQ(tritri::orient2d(o, y, z, Plane::YZ), Sign::Positive);
  EXPECT_EQ(tritri::orient2d(o, z, x, Plane::ZX), Sign::Positive);
  EXPECT_EQ(tritri::orient2d(o, x, z, Plane::ZX), Sign::Negative);
}

// Shewchuk's classic: a = (0.5 + i*u, 0.5 + j*u) against the line through (12, 12) and
// (24, 24), u = 2^-53 the ulp of 0.5 (so a is exact). The exact sign is sign(j - i);
// naive double evaluation gets many of them wrong.
TEST(PredicateRegressions, NearlyCollinearGridWhereNaiveOrient2dFails) {
  const double u = 0x1p-53;
  int naive_wrong = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const Case<2> p = {Pt<2>{0.5 + i * u, 0.5 + j * u}, Pt<2>{12, 12}, Pt<2>{24, 24}};
      const int want = exact_sign(p);
      ASSERT_EQ(want, (j > i) - (j < i)) << describe(p);  // a is above the line y = x iff j > i
      naive_wrong += naive_sign(naive_det(p)) != want;
      ASSERT_EQ(sign_of(tritri_sign(p)), want) << describe(p);
      ASSERT_EQ(sign_of(tritri::orient2d(Pt<3>{p[0][0], p[0][1], 1}, Pt<3>{12, 12, 2},
                                          Pt<3>{24, 24, 3}, Plane::XY)),
                want);
    }
  EXPECT_GT(naive_wrong, 1000);  // the construction really is beyond plain doubles
}

// The same in 3D: a near the plane x = y through b, c, d (on it exactly when i == j).
TEST(PredicateRegressions, NearlyCoplanarGridWhereNaiveOrient3dFails) {
  const double u = 0x1p-53;
  int naive_wrong = 0;
  for (int i = 0; i < 128; ++i)
    for (int j = 0; j < 128; ++j) {
      const Case<3> p = {Pt<3>{0.5 + i * u, 0.5 + j * u, 0.5 + (i ^ j) * u}, Pt<3>{12, 12, 0},
                         Pt<3>{24, 24, 0}, Pt<3>{13, 13, 7}};
      const int want = exact_sign(p);
      naive_wrong += naive_sign(naive_det(p)) != want;
      ASSERT_EQ(want == 0, i == j) << describe(p);
      ASSERT_EQ(sign_of(tritri_sign(p)), want) << describe(p);
    }
  EXPECT_GT(naive_wrong, 100);
}

// Products that underflow to zero in double, and differences that overflow.
TEST(PredicateRegressions, TinyAndHugeTetrahedraHaveTheirExactSign) {
  for (double m : {DBL_TRUE_MIN, 0x1p-1070, DBL_MIN, 0x1p-400, 0x1p-300, 0x1p-281, 0x1p-251,
                   0x1p251, 0x1p281, 0x1p400, 0x1p700, DBL_MAX}) {
    const Pt<3> o{0, 0, 0}, x{m, 0, 0}, y{0, m, 0}, z{0, 0, m};
    EXPECT_EQ(tritri::orient3d(o, x, y, z), Sign::Positive) << m;
    EXPECT_EQ(tritri::orient3d(o, x, z, y), Sign::Negative) << m;
    EXPECT_EQ(tritri::orient2d(0, 0, m, 0, 0, m), Sign::Positive) << m;
    // Corners of a cube spanning [-m, m]: differences 2m overflow when m is near DBL_MAX.
    const Case<3> cube = {Pt<3>{-m, -m, -m}, Pt<3>{m, -m, -m}, Pt<3>{-m, m, -m}, Pt<3>{-m, -m, m}};
    EXPECT_EQ(sign_of(tritri_sign(cube)), 1) << m;
    EXPECT_EQ(exact_sign(cube), 1) << m;
    const Case<3> face = {Pt<3>{-m, -m, -m}, Pt<3>{m, -m, -m}, Pt<3>{-m, m, -m}, Pt<3>{m, m, -m}};
    EXPECT_EQ(sign_of(tritri_sign(face)), 0) << m;
    // A point one ulp above that face.
    Case<3> above = face;
    above[3][2] = std::nextafter(-m, HUGE_VAL);
    EXPECT_EQ(sign_of(tritri_sign(above)), exact_sign(above)) << describe(above);
    EXPECT_EQ(exact_sign(above), 1) << describe(above);
  }
}

// Mixed magnitudes in one determinant: a huge and a subnormal difference in one term.
TEST(PredicateRegressions, MixedMagnitudesAcrossTheWholeExponentRange) {
  const double big = 0x1.fffp1023, tiny = DBL_TRUE_MIN;
  const std::vector<Case<3>> cases = {
      {Pt<3>{0, 0, 0}, Pt<3>{big, 0, 0}, Pt<3>{0, tiny, 0}, Pt<3>{0, 0, 1}},
      {Pt<3>{0, 0, 0}, Pt<3>{big, tiny, 0}, Pt<3>{big, 0, 0}, Pt<3>{1, 1, tiny}},
      {Pt<3>{1, 1, 1}, Pt<3>{big, 1, 1}, Pt<3>{1, std::nextafter(1.0, 2.0), 1}, Pt<3>{1, 1, std::nextafter(1.0, 0.0)}},
      {Pt<3>{0x1p-280, 0x1p280, 0}, Pt<3>{0x1p-281, 0x1p280, 0x1p-290}, Pt<3>{0, 0x1p281, 1}, Pt<3>{0x1p-279, 0, 0x1p279}},
      {Pt<3>{-big, big, 0}, Pt<3>{big, -big, 0}, Pt<3>{tiny, -tiny, tiny}, Pt<3>{0, 0, -tiny}},
  };
  for (const auto& p : cases) {
    const int want = exact_sign(p);
    EXPECT_EQ(sign_of(tritri_sign(p)), want) << describe(p);
    const Case<2> q = {Pt<2>{p[0][0], p[0][1]}, Pt<2>{p[1][0], p[1][1]}, Pt<2>{p[2][0], p[2][1]}};
    EXPECT_EQ(sign_of(tritri_sign(q)), exact_sign(q)) << describe(q);
  }
}

}  // namespace
