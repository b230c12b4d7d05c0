// tests/test_implicit_predicates.cpp
//
// The implicit-point predicates (implicit_predicates.h) against the exact reference
// computed in GMP rationals from the defining points (support/exact_oracle.h),
// independent of the library's homogeneous coordinates and of tritri::to_exact:
//   - orient3d, orient2d (XY, YZ, ZX; also on offset points), equal and less on explicit /
//     LPI / TPI operands in every position, most cases degenerate by construction: four
//     points on one plane, three on one line, one point built in two ways; then general
//     position;
//   - one point built several ways (LPI = TPI = explicit vertex, LPIs of different lines)
//     is one point for every predicate;
//   - the filter, incidence (zeros by construction, detail/incidence.h) and exact stages
//     are counted; each test asserts that its cases took the incidence shortcut, and each
//     zero rule of incidence.h is taken on a hand-made case.
//
// Scenes (support/implicit_scenes.h) mix integer-grid and random-double coordinates under
// exact per-axis scalings by 2^k (k in [-60, 60], 2^+-300, rarely 2^+-600, 2^+-900, 2^1000
// and subnormal 2^-1068) and translations. At TRITRI_TEST_SCALE=1 (default) these tests
// evaluate about 1.7 million cases; the sanitizer CI uses 0.1. TRITRI_TEST_SEED changes
// the seeds.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/implicit_recipes.h"
#include "support/implicit_scenes.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri::Plane;
using tritri::Sign;
using tritri_test::GroupKind;
using tritri_test::kPlanes;
using tritri_test::operands;
using tritri_test::Picker;
using tritri_test::Point;
using tritri_test::Rng;
using tritri_test::run_scenes;
using tritri_test::Scene;

constexpr int kMaxReports = 10;  // failures printed in full per test

const char* plane_name(Plane p) { return p == Plane::XY ? "XY" : (p == Plane::YZ ? "YZ" : "ZX"); }

int sign_of(Sign s) { return tritri::to_int(s); }

// ---------------------------------------------------------------------------------------
// Predicates against the reference.

// Zeros decided by an incidence known by construction (detail/incidence.h) since `before`.
std::uint64_t structural_since(std::uint64_t before) { return tritri::implicit_predicate_stats().structural - before; }

TEST(ImplicitPredicates, Orient3dMatchesExactReference) {
  long long cases = 0, zeros = 0, by_construction = 0, failures = 0;
  const std::uint64_t structural_before = tritri::implicit_predicate_stats().structural;
  const std::uint64_t wide_before = tritri::implicit_predicate_stats().wide;
  std::array<long long, 81> patterns{};  // operand kinds, base 3, position 0 most significant
  run_scenes(21, tritri_test::scaled_count(400000), [&](const Scene& s, Rng& rng, long long left) {
    Picker pick(s, rng);
    long long n = 0;
    for (; n < 200 && n < left; ++n) {
      int idx[4] = {pick.any(), pick.any(), pick.any(), pick.any()};  // a group may overwrite some
      bool degenerate = true;                                         // zero by construction
      switch (rng.uniform(0, 5)) {
        case 0:
        case 1:  // four points on one plane
          degenerate = pick.from_group(GroupKind::Coplanar, 4, 0, idx);
          break;
        case 2:  // three on one line, one anywhere
          degenerate = pick.from_group(GroupKind::Collinear, 3, 0, idx);
          break;
        case 3:  // one point twice (two ways), two anywhere
          degenerate = pick.from_group(GroupKind::Coincident, 2, 0, idx);
          break;
        case 4:  // three on a plane, one anywhere (often on it too)
          degenerate = false;
          pick.from_group(GroupKind::Coplanar, 3, 0, idx);
          break;
        default:
          degenerate = false;
          break;
      }
      if (!degenerate && rng.percent(50))
        for (int& i : idx) i = pick.any();
      tritri_test::shuffle(idx, 4, rng);
      const auto& P = s.points;
      const int expected = tritri_test::orient3d(P[idx[0]].z, P[idx[1]].z, P[idx[2]].z, P[idx[3]].z);
      const int got = sign_of(tritri::orient3d(P[idx[0]].point, P[idx[1]].point, P[idx[2]].point, P[idx[3]].point));
      zeros += expected == 0;
      by_construction += degenerate;
      int pattern = 0;
      for (int i : idx) pattern = pattern * 3 + tritri_test::kind_index(P[i].recipe.kind);
      ++patterns[pattern];
      if (degenerate && expected != 0)
        ADD_FAILURE() << "generator: a degenerate-by-construction case is not degenerate\n" << operands(s, idx, 4);
      if (got != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient3d(a, b, c, d): expected " << expected << ", got " << got << "\n"
                      << operands(s, idx, 4);
    }
    cases += n;
    return n;
  });
  const std::uint64_t structural = structural_since(structural_before);
  std::cout << "[ cases    ] orient3d: " << cases << " cases, " << by_construction << " degenerate by construction, "
            << zeros << " exact zeros, " << structural << " decided by incidence, "
            << tritri::implicit_predicate_stats().wide - wide_before << " by the long double filter\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(structural, 0u) << "the incidence shortcut was never taken: its answers went untested";
  // Scenes scaled to 2^-1068 or 2^+-900 underflow or overflow double's filter.
  if (tritri::detail::kWideFilterUseful) {  // false where long double is double
    EXPECT_GT(tritri::implicit_predicate_stats().wide, wide_before) << "the long double filter never decided";
  }
  EXPECT_GE(2 * by_construction, cases);
  for (int p = 0; p < 81; ++p) EXPECT_GT(patterns[p], 0) << "operand-kind pattern " << p << " never generated";
}

TEST(ImplicitPredicates, Orient2dMatchesExactReferenceInEveryProjection) {
  long long cases = 0, zeros = 0, by_construction = 0, failures = 0;
  const std::uint64_t structural_before = tritri::implicit_predicate_stats().structural;
  std::array<std::array<long long, 27>, 3> patterns{};
  run_scenes(22, tritri_test::scaled_count(360000), [&](const Scene& s, Rng& rng, long long left) {
    Picker pick(s, rng);
    long long n = 0;
    for (; n < 200 && n < left; ++n) {
      const int pl_index = rng.uniform(0, 2);
      const Plane pl = kPlanes[pl_index];
      const int dropped = pl == Plane::XY ? 2 : (pl == Plane::YZ ? 0 : 1);
      int idx[3] = {pick.any(), pick.any(), pick.any()};
      bool degenerate = true;
      switch (rng.uniform(0, 5)) {
        case 0:
        case 1:  // three on one line
          degenerate = pick.from_group(GroupKind::Collinear, 3, 0, idx);
          break;
        case 2:  // three on a plane containing the dropped axis: one line in this projection
          degenerate = pick.from_group(GroupKind::Coplanar, 3, 1 << dropped, idx) ||
                       pick.from_group(GroupKind::Collinear, 3, 0, idx);
          break;
        case 3:  // one point twice, one anywhere
          degenerate = pick.from_group(GroupKind::Coincident, 2, 0, idx);
          break;
        case 4:  // three on some plane
          degenerate = false;
          pick.from_group(GroupKind::Coplanar, 3, 0, idx);
          break;
        default:
          degenerate = false;
          break;
      }
      if (!degenerate && rng.percent(50))
        for (int& i : idx) i = pick.any();
      tritri_test::shuffle(idx, 3, rng);
      const auto& P = s.points;
      const int expected = tritri_test::orient2d(P[idx[0]].z, P[idx[1]].z, P[idx[2]].z, pl);
      const int got = sign_of(tritri::orient2d(P[idx[0]].point, P[idx[1]].point, P[idx[2]].point, pl));
      zeros += expected == 0;
      by_construction += degenerate;
      int pattern = 0;
      for (int i : idx) pattern = pattern * 3 + tritri_test::kind_index(P[i].recipe.kind);
      ++patterns[pl_index][pattern];
      if (degenerate && expected != 0)
        ADD_FAILURE() << "generator: a degenerate-by-construction case is not degenerate\n" << operands(s, idx, 3);
      if (got != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient2d(a, b, c, " << plane_name(pl) << "): expected " << expected << ", got " << got << "\n"
                      << operands(s, idx, 3);
      // The same with cached offset points, about the approximation of a scene point (any
      // explicit origin is valid; near ones make the filter decide more).
      const auto origin = P[pick.any()].point.approx();
      const int got_offset = sign_of(tritri::orient2d(tritri::offset_point(P[idx[0]].point, origin),
                                                      tritri::offset_point(P[idx[1]].point, origin),
                                                      tritri::offset_point(P[idx[2]].point, origin), pl));
      if (got_offset != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient2d(OffsetPoint a, b, c, " << plane_name(pl) << "): expected " << expected << ", got "
                      << got_offset << "\n"
                      << operands(s, idx, 3);
    }
    cases += n;
    return n;
  });
  const std::uint64_t structural = structural_since(structural_before);
  std::cout << "[ cases    ] orient2d: " << cases << " cases, " << by_construction << " degenerate by construction, "
            << zeros << " exact zeros, " << structural << " decided by incidence\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(structural, 0u) << "the incidence shortcut was never taken: its answers went untested";
  EXPECT_GE(2 * by_construction, cases);
  for (int pl = 0; pl < 3; ++pl)
    for (int p = 0; p < 27; ++p)
      EXPECT_GT(patterns[pl][p], 0) << "projection " << pl << ": operand-kind pattern " << p << " never generated";
}

TEST(ImplicitPredicates, EqualAndLessMatchExactReference) {
  long long pairs = 0, equal_pairs = 0, partial_ties = 0, failures = 0;
  const std::uint64_t structural_before = tritri::implicit_predicate_stats().structural;
  std::array<long long, 9> patterns{};
  run_scenes(23, tritri_test::scaled_count(150000), [&](const Scene& s, Rng& rng, long long left) {
    Picker pick(s, rng);
    long long n = 0;
    for (; n < 200 && n < left; ++n) {
      int idx[2] = {pick.any(), pick.any()};
      switch (rng.uniform(0, 5)) {  // a group member when there is one, else the random pair
        case 0:
        case 1:
          pick.from_group(GroupKind::Coincident, 2, 0, idx);
          break;
        case 2:
          pick.from_group(GroupKind::Coplanar, 2, 0, idx);
          break;  // ties on axis planes
        case 3:
          pick.from_group(GroupKind::Collinear, 2, 0, idx);
          break;  // ties on axis lines
        default:
          break;
      }
      const auto& a = s.points[idx[0]];
      const auto& b = s.points[idx[1]];
      const int expected = tritri_test::compare(a.exact, b.exact);
      equal_pairs += expected == 0;
      partial_ties += expected != 0 && (a.exact[0] == b.exact[0]);
      ++patterns[3 * tritri_test::kind_index(a.recipe.kind) + tritri_test::kind_index(b.recipe.kind)];
      const bool eq = tritri::equal(a.point, b.point), ab = tritri::less(a.point, b.point),
                 ba = tritri::less(b.point, a.point);
      if ((eq != (expected == 0) || ab != (expected < 0) || ba != (expected > 0)) && ++failures <= kMaxReports)
        ADD_FAILURE() << "exact comparison " << expected << ", got equal(a, b) = " << eq << ", less(a, b) = " << ab
                      << ", less(b, a) = " << ba << "\n"
                      << operands(s, idx, 2);
    }
    pairs += n;
    return n;
  });
  std::cout << "[ cases    ] equal/less: " << pairs << " pairs (" << 3 * pairs << " predicate calls), " << equal_pairs
            << " equal, " << partial_ties << " distinct with equal x, " << structural_since(structural_before)
            << " coordinates compared as known constants\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(structural_since(structural_before), 0u) << "known coordinates never compared: their answers went untested";
  EXPECT_GE(3 * equal_pairs, pairs);
  EXPECT_GT(partial_ties, 0);
  for (int p = 0; p < 9; ++p) EXPECT_GT(patterns[p], 0) << "operand-kind pattern " << p << " never generated";
}

// Every representation of one point (LPI, TPI, explicit vertex, LPIs of different lines)
// is equal to every other, neither is less, and every predicate gives the same sign (the
// reference's) whichever representation is used, in every position.
TEST(ImplicitPredicates, OnePointBuiltSeveralWaysIsOnePoint) {
  long long groups = 0, cases = 0, failures = 0;
  run_scenes(24, tritri_test::scaled_count(800), [&](const Scene& s, Rng& rng, long long) {
    Picker pick(s, rng);
    for (const auto& g : s.groups) {
      if (g.kind != GroupKind::Coincident) continue;
      ++groups;
      const auto& m = g.members;
      for (std::size_t i = 0; i < m.size(); ++i)
        for (std::size_t j = 0; j < m.size(); ++j) {
          if (i == j) continue;
          int pair[2] = {m[i], m[j]};
          const auto& p = s.points[m[i]];
          const auto& q = s.points[m[j]];
          if (p.exact != q.exact) {
            ADD_FAILURE() << "generator: representations differ\n" << operands(s, pair, 2);
            continue;
          }
          ++cases;
          if ((!tritri::equal(p.point, q.point) || tritri::less(p.point, q.point)) && ++failures <= kMaxReports)
            ADD_FAILURE() << "equal(a, b) = " << tritri::equal(p.point, q.point)
                          << ", less(a, b) = " << tritri::less(p.point, q.point) << " for one point\n"
                          << operands(s, pair, 2);
          // orient3d with three others, the point in a random position.
          int idx[4] = {pick.any(), pick.any(), pick.any(), 0};
          const int pos = rng.uniform(0, 3);
          std::swap(idx[pos], idx[3]);
          const auto& P = s.points;
          int kp[4], kq[4];
          for (int t = 0; t < 4; ++t) kp[t] = kq[t] = idx[t];
          kp[pos] = m[i];
          kq[pos] = m[j];
          const int expected = tritri_test::orient3d(P[kp[0]].z, P[kp[1]].z, P[kp[2]].z, P[kp[3]].z);
          const int sp = sign_of(tritri::orient3d(P[kp[0]].point, P[kp[1]].point, P[kp[2]].point, P[kp[3]].point));
          const int sq = sign_of(tritri::orient3d(P[kq[0]].point, P[kq[1]].point, P[kq[2]].point, P[kq[3]].point));
          ++cases;
          if ((sp != expected || sq != expected) && ++failures <= kMaxReports)
            ADD_FAILURE() << "orient3d with the point as operand " << pos << " in two ways: expected " << expected
                          << ", got " << sp << " and " << sq << "\n"
                          << operands(s, kp, 4) << "\n  other way: " << tritri_test::describe(q.recipe);
          // orient2d with two others, each projection.
          for (Plane pl : kPlanes) {
            int k2p[3] = {pick.any(), pick.any(), m[i]};
            const int pos2 = rng.uniform(0, 2);
            std::swap(k2p[pos2], k2p[2]);
            int k2q[3] = {k2p[0], k2p[1], k2p[2]};
            k2q[pos2] = m[j];
            const int e2 = tritri_test::orient2d(P[k2p[0]].z, P[k2p[1]].z, P[k2p[2]].z, pl);
            const int s2p = sign_of(tritri::orient2d(P[k2p[0]].point, P[k2p[1]].point, P[k2p[2]].point, pl));
            const int s2q = sign_of(tritri::orient2d(P[k2q[0]].point, P[k2q[1]].point, P[k2q[2]].point, pl));
            ++cases;
            if ((s2p != e2 || s2q != e2) && ++failures <= kMaxReports)
              ADD_FAILURE() << "orient2d(" << plane_name(pl) << ") with the point as operand " << pos2
                            << " in two ways: expected " << e2 << ", got " << s2p << " and " << s2q << "\n"
                            << operands(s, k2p, 3) << "\n  other way: " << tritri_test::describe(q.recipe);
          }
        }
    }
    return 1;
  });
  std::cout << "[ cases    ] " << groups << " points built several ways, " << cases << " predicate cases\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(groups, 0);
}

// The thread-local counters see the filter decide a clear case, the structural test
// decide a zero by construction (the LPI on its own plane), and the exact stage decide an
// exact zero that no floating-point filter can certify and no incidence explains.
TEST(ImplicitPredicates, StatsCountFilterStructuralAndExactStages) {
  const Point r{0, 0, 0}, s{1, 0, 0}, t{0, 1, 0};
  const auto on_plane = ImplicitPoint::lpi(Point{0.1, 0.2, -1}, Point{0.3, 0.1, 1}, r, s, t);
  const auto R = ImplicitPoint::explicit_point(r), S = ImplicitPoint::explicit_point(s),
             T = ImplicitPoint::explicit_point(t), U = ImplicitPoint::explicit_point(3, 5, 0);
  const auto far = ImplicitPoint::lpi(Point{0, 0, 5}, Point{1, 1, 6}, S.approx(), T.approx(), Point{0, 0, 3});
  auto& stats = tritri::implicit_predicate_stats();
  const auto before = stats;
  EXPECT_EQ(tritri::orient3d(R, S, T, on_plane), Sign::Zero);
  EXPECT_EQ(stats.structural, before.structural + 1);
  EXPECT_EQ(stats.exact, before.exact);
  // U is no corner of rst, but all four have z = 0 by construction (a common coordinate).
  EXPECT_EQ(tritri::orient3d(R, S, U, on_plane), Sign::Zero);
  EXPECT_EQ(stats.structural, before.structural + 2);
  EXPECT_EQ(tritri::orient3d(R, S, T, far), Sign::Positive);
  EXPECT_EQ(stats.filtered, before.filtered + 1);
  // On a slanted plane (z = x + y) a point that is no corner of it: only the exact stage
  // knows.
  const Point a{0, 0, 0}, b{1, 0, 1}, c{0, 1, 1};
  const auto on_slant = ImplicitPoint::lpi(Point{0.1, 0.2, -1}, Point{0.3, 0.1, 2}, a, b, c);
  const auto A = ImplicitPoint::explicit_point(a), B = ImplicitPoint::explicit_point(b),
             V = ImplicitPoint::explicit_point(2, 3, 5);
  EXPECT_EQ(tritri::orient3d(A, B, V, on_slant), Sign::Zero);
  EXPECT_EQ(stats.exact, before.exact + 1);
  EXPECT_EQ(stats.exact_zero, before.exact_zero + 1);
}

// Each zero rule of detail/incidence.h beyond a common defining plane or line, on one
// hand-made case: taken (counted as structural, no exact call) and right; and a nonzero
// case beside it that the rule must not claim.
TEST(ImplicitPredicates, EachIncidenceRuleIsTaken) {
  auto& stats = tritri::implicit_predicate_stats();
  auto structural_and_no_exact = [&](const tritri::ImplicitPredicateStats& before) {
    return stats.structural == before.structural + 1 && stats.exact == before.exact;
  };
  // Generic corners (no common coordinate, no axis-aligned plane).
  const Point a{0.1, 0.2, 0.3}, b{1.3, 0.4, 2.1}, c{0.7, 1.9, 0.2}, d{2.2, -0.7, 1.1};
  const Point r{5.1, 0.3, -2.2}, s{-1.7, 4.2, 3.3}, t{0.4, -3.1, 6.5};  // a plane crossing ab
  const auto A = ImplicitPoint::explicit_point(a), B = ImplicitPoint::explicit_point(b),
             C = ImplicitPoint::explicit_point(c), D = ImplicitPoint::explicit_point(d);
  const auto on_ab = ImplicitPoint::lpi(a, b, r, s, t);
  const auto on_ba = ImplicitPoint::lpi(b, a, s, t, r);  // the same point, built again
  {  // Corner union: A, B, C and a point of line ab lie on plane abc, which no operand has.
    const auto before = stats;
    EXPECT_EQ(tritri::orient3d(A, on_ab, B, C), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before));
    EXPECT_NE(tritri::orient3d(A, on_ab, C, D), Sign::Zero);  // four corners: not claimed
  }
  {  // A repeated point: on_ab and on_ba are one point.
    const auto before = stats;
    EXPECT_EQ(tritri::orient3d(on_ab, C, D, on_ba), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before));
    const auto before2 = stats;
    EXPECT_EQ(tritri::orient2d(on_ba, D, on_ab, Plane::ZX), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before2));
  }
  {  // A common plane that the projection flattens: the vertical plane through a, e, f
     // (it contains the z direction) is a line in XY, not in YZ.
    const Point e{1.5, 0.9, 0.3}, f{0.1, 0.2, 4.7};
    const auto p1 = ImplicitPoint::lpi(Point{0.3, -1.2, 0.5}, Point{1.9, 2.8, 1.7}, a, e, f);
    const auto p2 = ImplicitPoint::lpi(Point{-0.6, 0.4, 2.5}, Point{2.3, 0.7, -1.1}, e, f, a);
    const auto p3 = ImplicitPoint::lpi(Point{0.2, 2.2, 3.5}, Point{1.1, -1.3, 0.1}, f, a, e);
    const auto before = stats;
    EXPECT_EQ(tritri::orient2d(p1, p2, p3, Plane::XY), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before));
    const auto before2 = stats;
    EXPECT_NE(tritri::orient2d(p1, p2, p3, Plane::YZ), Sign::Zero);
    EXPECT_EQ(stats.structural, before2.structural);
  }
  {  // A coordinate all share on a projection axis: three points on the plane x = 2 (LPIs
     // of lines crossing it, on different planes), in XY: one line x = 2.
    const Point x0{2, 0, 0}, x1{2, 1, 0}, x2{2, 0, 1}, x3{2, 3, 5};
    const auto q1 = ImplicitPoint::lpi(Point{0.3, 0.2, 0.1}, Point{3.9, 1.8, 1.7}, x0, x1, x2);
    const auto q2 = ImplicitPoint::lpi(Point{-0.6, 0.4, 2.5}, Point{2.3, 0.7, -1.1}, x1, x3, x0);
    const auto Q3 = ImplicitPoint::explicit_point(x3);
    const auto before = stats;
    EXPECT_EQ(tritri::orient2d(q1, Q3, q2, Plane::XY), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before));
    const auto before2 = stats;
    EXPECT_EQ(tritri::orient3d(q1, Q3, q2, ImplicitPoint::explicit_point(x1)), Sign::Zero);
    EXPECT_TRUE(structural_and_no_exact(before2));
    EXPECT_NE(tritri::orient2d(q1, Q3, q2, Plane::YZ), Sign::Zero);
  }
}

}  // namespace
