// tests/test_double_predicates_generated.cpp
//
// tritri::orient3d / orient3d_each / orient2d on doubles against the exact oracle, on the
// generated families of support/orient_cases.h (orient2d also on 3D points projected to
// XY, YZ and ZX, the dropped coordinate junk). Prints per family how many cases are exact
// zeros, how many plain double evaluation gets wrong, and which stage the documented
// thresholds of double_predicates.h send them to. The two exact stages for coordinates
// outside the double expansions' range (long double expansions, GMP integers) are also
// called one by one against the oracle.
//
// Case counts scale with the environment variable TRITRI_TEST_SCALE (default 1.0; the
// sanitizer CI uses 0.1). At scale 1.0 each predicate sees 1,000,000 generated cases.
// Seeds are fixed; TRITRI_TEST_SEED (an integer) changes them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tritri/double_predicates.h"

#include "support/orient_cases.h"
#include "support/test_scale.h"

namespace {

using namespace tritri_test::orient;

// Which stage the documented thresholds of double_predicates.h send a case to; only for
// the report printed by the tests (uses the header's evaluation order for the filter).
// kWide: outside the double expansions' range, long double expansions (x87) or GMP.
enum Stage { kTrivial, kFilter, kExpansion, kWide, kStages };

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
      if (!tritri::detail::expansion_safe(x)) return kWide;
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
    std::printf(
        "[ stats    ] %-28s %8ld cases: exact zero %7ld, naive double wrong %7ld; "
        "stages (documented thresholds): trivial %ld, filter %ld, expansion %ld, wide range %ld\n",
        what.c_str(), cases, zero, naive_wrong, stage[kTrivial], stage[kFilter], stage[kExpansion], stage[kWide]);
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
    case Plane::XY:
      return {q[0], q[1], junk};
    case Plane::YZ:
      return {junk, q[0], q[1]};
    case Plane::ZX:
      return {q[1], junk, q[0]};
  }
  return {};
}

// ---------------------------------------------------------------------------------------
// Generated cases against the rational oracle.

class GeneratedCases : public ::testing::TestWithParam<FamilyPlan> {};

TEST_P(GeneratedCases, Orient3dMatchesExactRationalSign) {
  const FamilyPlan plan = GetParam();
  Rng r(orient_seed(100 + static_cast<int>(plan.family)));
  const long n = tritri_test::scaled_count(plan.count);
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

// orient3d_each shares one normal between three queries against plane(p0, p1, p2): the
// generated fourth point (near the plane in most families), a vertex of the plane (an
// exact zero) and the fourth point of another case of the family, in rotating slots.
TEST_P(GeneratedCases, Orient3dEachMatchesExactRationalSign) {
  const FamilyPlan plan = GetParam();
  Rng r(orient_seed(400 + static_cast<int>(plan.family)));
  const long n = tritri_test::scaled_count(plan.count / 4);
  int failures = 0;
  for (long i = 0; i < n && failures < kMaxReportedFailures; ++i) {
    const Case<3> p = generate<3>(plan.family, r), q = generate<3>(plan.family, r);
    const int slot = static_cast<int>(i % 3);
    Pt<3> d[3];
    d[slot] = p[3];
    d[(slot + 1) % 3] = p[(slot + 1) % 3];
    d[(slot + 2) % 3] = q[3];
    const double* const dp[3] = {d[0].data(), d[1].data(), d[2].data()};
    Sign got[3];
    tritri::orient3d_each(p[0].data(), p[1].data(), p[2].data(), dp, got);
    for (int j = 0; j < 3; ++j) {
      const Case<3> c = {p[0], p[1], p[2], d[j]};
      const int want = exact_sign(c);
      if (sign_of(got[j]) != want) {
        ++failures;
        ADD_FAILURE() << "orient3d_each, query " << j << describe(c) << " = " << sign_of(got[j]) << ", exact "
                      << want;
      }
    }
  }
}

TEST_P(GeneratedCases, Orient2dMatchesExactRationalSignOnEveryPlane) {
  const FamilyPlan plan = GetParam();
  Rng r(orient_seed(200 + static_cast<int>(plan.family)));
  const long n = tritri_test::scaled_count(plan.count);
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
        ADD_FAILURE() << "orient2d on plane " << static_cast<int>(plane) << " of " << describe(p) << " = " << got3
                      << ", exact " << want;
      }
    }
  }
  t.print(std::string("orient2d ") + family_name(plan.family));
  g_total2.add(t);
}

// The two exact stages for inputs outside the double expansions' range, each called
// directly (the predicates take one of them per platform): long double expansions and GMP
// integers, against the oracle on every family (the extreme and scaled ones reach them).
TEST_P(GeneratedCases, WideRangeStagesMatchExactRationalSign) {
  const FamilyPlan plan = GetParam();
  Rng r(orient_seed(300 + static_cast<int>(plan.family)));
  const long n = tritri_test::scaled_count(plan.count / 4);
  long wide = 0;
  int failures = 0;
  for (long i = 0; i < n && failures < kMaxReportedFailures; ++i) {
    const Case<3> p3 = generate<3>(plan.family, r);
    const Case<2> p2 = generate<2>(plan.family, r);
    double f3[12], f2[6];
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) f3[3 * j + k] = p3[j][k];
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k) f2[2 * j + k] = p2[j][k];
    wide += documented_stage(p3) == kWide;
    const int want3 = exact_sign(p3), want2 = exact_sign(p2);
    const int ld3 = tritri::detail::orient3d_expansion<long double>(f3), gmp3 = tritri::detail::orient3d_gmp(f3);
    const int ld2 = tritri::detail::orient2d_expansion<long double>(f2), gmp2 = tritri::detail::orient2d_gmp(f2);
    if (ld3 != want3 || gmp3 != want3 || ld2 != want2 || gmp2 != want2) {
      ++failures;
      ADD_FAILURE() << "orient3d" << describe(p3) << ": long double " << ld3 << ", gmp " << gmp3 << ", exact "
                    << want3 << "; orient2d" << describe(p2) << ": long double " << ld2 << ", gmp " << gmp2
                    << ", exact " << want2;
    }
  }
  std::printf("[ stats    ] wide-range stages, %-12s %ld cases, %ld of them in the wide range\n",
              family_name(plan.family), n, wide);
}

INSTANTIATE_TEST_SUITE_P(Families, GeneratedCases, ::testing::ValuesIn(kPlans),
                         [](const ::testing::TestParamInfo<FamilyPlan>& param_info) {
                           return std::string(family_name(param_info.param.family));
                         });

}  // namespace
