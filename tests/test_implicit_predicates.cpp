// tests/test_implicit_predicates.cpp
//
// The implicit-point backend (implicit_point.h, implicit_predicates.h) against an exact
// reference computed in GMP rationals from the defining points (implicit_generators.h),
// independent of the library's homogeneous coordinates and of tritri::to_exact:
//
//   - orient3d, orient2d (XY, YZ, ZX), equal and less on explicit / LPI / TPI operands in
//     every position, most cases degenerate by construction: four points on one plane,
//     three on one line, one point built in two ways; then general position;
//   - one point built several ways (LPI = TPI = explicit vertex, LPIs of different lines)
//     is one point for every predicate;
//   - to_exact is the reference point, to_double its nearest double;
//   - undefined constructions (line parallel to the plane, p == q, collinear triples,
//     dependent planes) are refused exactly, non-finite and implicit arguments rejected.
//
// Scenes mix integer-grid and random-double coordinates under exact per-axis scalings by
// 2^k (k in [-60, 60], 2^+-300, rarely 2^+-600, 2^+-900, 2^1000 and subnormal 2^-1068) and
// translations. At TRITRI_TEST_SCALE=1 (default) the predicate tests evaluate about 1.7
// million cases; the sanitizer CI uses 0.1. TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <tritri/tritri.h>

#include "implicit_generators.h"

namespace {

using tritri::ImplicitPoint;
using tritri::Plane;
using tritri::Sign;
using tritri_test::GroupKind;
using tritri_test::Point;
using tritri_test::QPoint;
using tritri_test::Recipe;
using tritri_test::Rng;
using tritri_test::Scene;
using tritri_test::Triple;

constexpr int kMaxReports = 10;  // failures printed in full per test
constexpr Plane kPlanes[3] = {Plane::XY, Plane::YZ, Plane::ZX};

const char* plane_name(Plane p) { return p == Plane::XY ? "XY" : (p == Plane::YZ ? "YZ" : "ZX"); }

std::string transform_string(const tritri_test::Transform& t) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "(scene map: shift {%a, %a, %a}, scale 2^{%d, %d, %d})", t.shift[0], t.shift[1],
                t.shift[2], t.exponent[0], t.exponent[1], t.exponent[2]);
  return buf;
}

// The operands of a failing case, pasteable (hex) and with their exact coordinates.
std::string operands(const Scene& s, const int* idx, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) {
    const auto& p = s.points[idx[i]];
    out += std::string("  ") + char('a' + i) + " = " + tritri_test::describe(p.recipe) + "\n      exact " +
           tritri_test::q_string(p.exact) + "\n";
  }
  return out + "  " + transform_string(s.transform);
}

// Random operands: n distinct members of a random group of `kind` (with the axis bits
// `axes`), or any points.
class Picker {
 public:
  Picker(const Scene& s, Rng& rng) : s_(s), rng_(rng) {}

  int any() { return rng_.uniform(0, static_cast<int>(s_.points.size()) - 1); }

  bool from_group(GroupKind kind, int n, int axes, int* out) {
    std::vector<const tritri_test::Group*> fit;
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

int sign_of(Sign s) { return tritri::to_int(s); }

// Drives scenes until `target` cases have run; `body(scene, rng)` returns the number of
// cases it ran on one scene.
template <class Body>
void run_scenes(std::uint64_t salt, long long target, Body body) {
  Rng rng(tritri_test::seed_for(salt));
  for (long long done = 0; done < target;) {
    const Scene s = tritri_test::random_scene(rng);
    if (s.points.size() < 4) continue;
    done += body(s, rng, target - done);
  }
}

// ---------------------------------------------------------------------------------------
// Hand-made cases: the specification in miniature.

// The diagonal of the unit cube meets the plane x + y + z = 1 at (1/3, 1/3, 1/3), which is
// also the meeting point of the planes x = y, y = z and x + y + z = 1.
TEST(ImplicitPoint, DiagonalMeetsPlaneAtOneThirdAsLpiAndAsTpi) {
  const Point o{0, 0, 0}, d{1, 1, 1}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  const auto lpi = ImplicitPoint::lpi(o, d, ex, ey, ez);
  const auto tpi = ImplicitPoint::tpi(o, Point{1, 1, 0}, ez, o, d, ex, ex, ey, ez);
  const mpq_class third(1, 3);
  for (const auto& p : {lpi, tpi}) {
    const auto q = tritri::to_exact(p);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mpq_class(q[k].mpq()), third);
    EXPECT_EQ(tritri::to_double(p), (Point{0x1.5555555555555p-2, 0x1.5555555555555p-2, 0x1.5555555555555p-2}));
  }
  EXPECT_EQ(lpi.kind(), ImplicitPoint::Kind::LPI);
  EXPECT_EQ(tpi.kind(), ImplicitPoint::Kind::TPI);
  EXPECT_TRUE(tritri::equal(lpi, tpi));
  EXPECT_FALSE(tritri::less(lpi, tpi));
  EXPECT_FALSE(tritri::less(tpi, lpi));
  const auto X = ImplicitPoint::explicit_point(ex), Y = ImplicitPoint::explicit_point(ey);
  const auto Z = ImplicitPoint::explicit_point(ez), O = ImplicitPoint::explicit_point(o);
  EXPECT_EQ(tritri::orient3d(X, Y, Z, lpi), Sign::Zero);
  EXPECT_EQ(tritri::orient3d(tpi, X, Y, Z), Sign::Zero);
  EXPECT_EQ(tritri::orient3d(X, Y, Z, O), Sign::Negative);  // the origin is below the plane
  EXPECT_EQ(tritri::orient3d(X, Y, lpi, Z), Sign::Zero);    // X, Y, lpi span the plane again
  for (Plane pl : kPlanes) EXPECT_EQ(tritri::orient2d(O, ImplicitPoint::explicit_point(d), tpi, pl), Sign::Zero);
  EXPECT_TRUE(tritri::less(O, lpi));
  EXPECT_TRUE(tritri::less(tpi, X));
  EXPECT_TRUE(tritri::less(Y, lpi));
}

// An LPI whose line passes through a point of the plane is that (explicit) point.
TEST(ImplicitPoint, LineThroughAPointOfThePlaneMeetsItThere) {
  const Point v{0.75, -2, 3}, m{5, 1, -1};
  const Triple plane{v, Point{1, 1, 1}, Point{-3, 0.5, 2}};
  const auto lpi = ImplicitPoint::lpi(m, v, plane[1], plane[2], plane[0]);
  EXPECT_TRUE(tritri::equal(lpi, ImplicitPoint::explicit_point(v)));
  EXPECT_EQ(tritri::to_double(lpi), v);
}

// |e - d| <= |e - d'| for both neighbours d' of d, ties to even: d is e correctly rounded.
bool is_nearest_double(double d, const mpq_class& e) {
  if (!std::isfinite(d)) return false;
  const mpq_class err = abs(e - mpq_class(d));
  for (double n : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)}) {
    if (!std::isfinite(n)) continue;
    const mpq_class en = abs(e - mpq_class(n));
    if (en < err) return false;
    if (en == err && (std::bit_cast<std::uint64_t>(std::fabs(d)) & 1) != 0) return false;  // tie: d must be even
  }
  return true;
}

// The x coordinate is 2^-1075 / (1 - 2^-75): just above half the smallest subnormal, so it
// rounds up to 2^-1074 (rounding first to 53 bits gives 2^-1075, a tie, which rounds to 0).
TEST(ImplicitPoint, ToDoubleRoundsSubnormalCoordinatesCorrectly) {
  const Point p{0, 0, 0}, q{0x1p-1074, 0, 1};
  const Triple plane{Point{0, 0, 0.5}, Point{0x1p-1000, 0, 1}, Point{0, 1, 0.5}};  // z = 1/2 + 2^999 x
  const auto ref = tritri_test::exact_lpi(p, q, plane);
  ASSERT_TRUE(ref.has_value());
  ASSERT_EQ((*ref)[0], mpq_class(1) / (mpz_class(1) << 1075) / (1 - mpq_class(1) / (mpz_class(1) << 75)));
  const auto lpi = ImplicitPoint::lpi(p, q, plane[0], plane[1], plane[2]);
  const auto d = tritri::to_double(lpi);
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(is_nearest_double(d[k], (*ref)[k]))
        << "coordinate " << k << ": to_double gives " << std::hexfloat << d[k] << ", exact " << (*ref)[k].get_str();
  EXPECT_EQ(d[0], 0x1p-1074);
}

// ---------------------------------------------------------------------------------------
// Construction, to_exact, to_double on generated points.

TEST(ImplicitPoint, GeneratedPointsAreDefinedExactlyWhenTheReferenceSaysSo) {
  long long points = 0, refused = 0, failures = 0;
  run_scenes(11, tritri_test::scaled_count(400), [&](const Scene& s, Rng&, long long) {
    points += static_cast<long long>(s.points.size());
    refused += static_cast<long long>(s.refused.size());
    for (const Recipe& r : s.wrongly_refused)
      if (++failures <= kMaxReports)
        ADD_FAILURE() << "defined point refused: " << tritri_test::describe(r) << "\n  exact "
                      << tritri_test::q_string(*tritri_test::exact_point(r));
    for (const Recipe& r : s.wrongly_accepted)
      if (++failures <= kMaxReports) ADD_FAILURE() << "undefined point accepted: " << tritri_test::describe(r);
    for (const auto& p : s.points)
      if (p.point.kind() != p.recipe.kind && ++failures <= kMaxReports)
        ADD_FAILURE() << "kind " << tritri_test::kind_name(p.point.kind()) << " for " << tritri_test::describe(p.recipe);
    return 1;
  });
  std::cout << "[ cases    ] " << points << " defined points built, " << refused << " undefined refused\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(refused, 0);  // the generators do produce undefined recipes
}

TEST(ImplicitPoint, ToExactIsTheExactPointAndToDoubleItsNearestDouble) {
  long long points = 0, failures = 0;
  run_scenes(12, tritri_test::scaled_count(500), [&](const Scene& s, Rng&, long long) {
    for (const auto& p : s.points) {
      ++points;
      const auto e = tritri::to_exact(p.point);
      const auto d = tritri::to_double(p.point);
      for (int k = 0; k < 3; ++k) {
        const bool exact_ok = mpq_class(e[k].mpq()) == p.exact[k];
        const bool double_ok = is_nearest_double(d[k], p.exact[k]);
        if ((!exact_ok || !double_ok) && ++failures <= kMaxReports)
          ADD_FAILURE() << "coordinate " << k << " of " << tritri_test::describe(p.recipe) << "\n  reference "
                        << p.exact[k].get_str() << "\n  to_exact  " << mpq_class(e[k].mpq()).get_str()
                        << "\n  to_double " << std::hexfloat << d[k] << (double_ok ? "" : " (not the nearest double)");
      }
    }
    return 1;
  });
  std::cout << "[ cases    ] " << points << " points\n";
  EXPECT_EQ(failures, 0);
}

// ---------------------------------------------------------------------------------------
// Predicates against the reference.

TEST(ImplicitPredicates, Orient3dMatchesExactReference) {
  long long cases = 0, zeros = 0, by_construction = 0, failures = 0;
  std::array<long long, 81> patterns{};  // operand kinds, base 3, position 0 most significant
  run_scenes(21, tritri_test::scaled_count(400000), [&](const Scene& s, Rng& rng, long long left) {
    Picker pick(s, rng);
    long long n = 0;
    for (; n < 200 && n < left; ++n) {
      int idx[4] = {pick.any(), pick.any(), pick.any(), pick.any()};  // a group may overwrite some
      bool degenerate = true;  // zero by construction
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
        default: degenerate = false; break;
      }
      if (!degenerate && rng.percent(50))
        for (int& i : idx) i = pick.any();
      tritri_test::shuffle(idx, 4, rng);
      const auto& P = s.points;
      const int expected = tritri_test::exact_orient3d(P[idx[0]].z, P[idx[1]].z, P[idx[2]].z, P[idx[3]].z);
      const int got = sign_of(tritri::orient3d(P[idx[0]].point, P[idx[1]].point, P[idx[2]].point, P[idx[3]].point));
      zeros += expected == 0;
      by_construction += degenerate;
      int pattern = 0;
      for (int i : idx) pattern = pattern * 3 + tritri_test::kind_index(P[i].recipe.kind);
      ++patterns[pattern];
      if (degenerate && expected != 0)
        ADD_FAILURE() << "generator: a degenerate-by-construction case is not degenerate\n" << operands(s, idx, 4);
      if (got != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient3d(a, b, c, d): expected " << expected << ", got " << got << "\n" << operands(s, idx, 4);
    }
    cases += n;
    return n;
  });
  std::cout << "[ cases    ] orient3d: " << cases << " cases, " << by_construction << " degenerate by construction, "
            << zeros << " exact zeros\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GE(2 * by_construction, cases);
  for (int p = 0; p < 81; ++p) EXPECT_GT(patterns[p], 0) << "operand-kind pattern " << p << " never generated";
}

TEST(ImplicitPredicates, Orient2dMatchesExactReferenceInEveryProjection) {
  long long cases = 0, zeros = 0, by_construction = 0, failures = 0;
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
        default: degenerate = false; break;
      }
      if (!degenerate && rng.percent(50))
        for (int& i : idx) i = pick.any();
      tritri_test::shuffle(idx, 3, rng);
      const auto& P = s.points;
      const int expected = tritri_test::exact_orient2d(P[idx[0]].z, P[idx[1]].z, P[idx[2]].z, pl);
      const int got = sign_of(tritri::orient2d(P[idx[0]].point, P[idx[1]].point, P[idx[2]].point, pl));
      zeros += expected == 0;
      by_construction += degenerate;
      int pattern = 0;
      for (int i : idx) pattern = pattern * 3 + tritri_test::kind_index(P[i].recipe.kind);
      ++patterns[pl_index][pattern];
      if (degenerate && expected != 0)
        ADD_FAILURE() << "generator: a degenerate-by-construction case is not degenerate\n" << operands(s, idx, 3);
      if (got != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient2d(a, b, c, " << plane_name(pl) << "): expected " << expected << ", got " << got
                      << "\n" << operands(s, idx, 3);
      // The same with cached offset points, about the approximation of a scene point (any
      // explicit origin is valid; near ones make the filter decide more).
      const auto origin = P[pick.any()].point.approx();
      const int got_offset =
          sign_of(tritri::orient2d(tritri::offset_point(P[idx[0]].point, origin),
                                   tritri::offset_point(P[idx[1]].point, origin),
                                   tritri::offset_point(P[idx[2]].point, origin), pl));
      if (got_offset != expected && ++failures <= kMaxReports)
        ADD_FAILURE() << "orient2d(OffsetPoint a, b, c, " << plane_name(pl) << "): expected " << expected << ", got "
                      << got_offset << "\n" << operands(s, idx, 3);
    }
    cases += n;
    return n;
  });
  std::cout << "[ cases    ] orient2d: " << cases << " cases, " << by_construction << " degenerate by construction, "
            << zeros << " exact zeros\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GE(2 * by_construction, cases);
  for (int pl = 0; pl < 3; ++pl)
    for (int p = 0; p < 27; ++p)
      EXPECT_GT(patterns[pl][p], 0) << "projection " << pl << ": operand-kind pattern " << p << " never generated";
}

TEST(ImplicitPredicates, EqualAndLessMatchExactReference) {
  long long pairs = 0, equal_pairs = 0, partial_ties = 0, failures = 0;
  std::array<long long, 9> patterns{};
  run_scenes(23, tritri_test::scaled_count(150000), [&](const Scene& s, Rng& rng, long long left) {
    Picker pick(s, rng);
    long long n = 0;
    for (; n < 200 && n < left; ++n) {
      int idx[2] = {pick.any(), pick.any()};
      switch (rng.uniform(0, 5)) {  // a group member when there is one, else the random pair
        case 0:
        case 1: pick.from_group(GroupKind::Coincident, 2, 0, idx); break;
        case 2: pick.from_group(GroupKind::Coplanar, 2, 0, idx); break;  // ties on axis planes
        case 3: pick.from_group(GroupKind::Collinear, 2, 0, idx); break;  // ties on axis lines
        default: break;
      }
      const auto& a = s.points[idx[0]];
      const auto& b = s.points[idx[1]];
      const int expected = tritri_test::exact_compare(a.exact, b.exact);
      equal_pairs += expected == 0;
      partial_ties += expected != 0 && (a.exact[0] == b.exact[0]);
      ++patterns[3 * tritri_test::kind_index(a.recipe.kind) + tritri_test::kind_index(b.recipe.kind)];
      const bool eq = tritri::equal(a.point, b.point), ab = tritri::less(a.point, b.point),
                 ba = tritri::less(b.point, a.point);
      if ((eq != (expected == 0) || ab != (expected < 0) || ba != (expected > 0)) && ++failures <= kMaxReports)
        ADD_FAILURE() << "exact comparison " << expected << ", got equal(a, b) = " << eq << ", less(a, b) = " << ab
                      << ", less(b, a) = " << ba << "\n" << operands(s, idx, 2);
    }
    pairs += n;
    return n;
  });
  std::cout << "[ cases    ] equal/less: " << pairs << " pairs (" << 3 * pairs << " predicate calls), " << equal_pairs
            << " equal, " << partial_ties << " distinct with equal x\n";
  EXPECT_EQ(failures, 0);
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
          const int expected = tritri_test::exact_orient3d(P[kp[0]].z, P[kp[1]].z, P[kp[2]].z, P[kp[3]].z);
          const int sp = sign_of(tritri::orient3d(P[kp[0]].point, P[kp[1]].point, P[kp[2]].point, P[kp[3]].point));
          const int sq = sign_of(tritri::orient3d(P[kq[0]].point, P[kq[1]].point, P[kq[2]].point, P[kq[3]].point));
          ++cases;
          if ((sp != expected || sq != expected) && ++failures <= kMaxReports)
            ADD_FAILURE() << "orient3d with the point as operand " << pos << " in two ways: expected " << expected
                          << ", got " << sp << " and " << sq << "\n" << operands(s, kp, 4) << "\n  other way: "
                          << tritri_test::describe(q.recipe);
          // orient2d with two others, each projection.
          for (Plane pl : kPlanes) {
            int k2p[3] = {pick.any(), pick.any(), m[i]};
            const int pos2 = rng.uniform(0, 2);
            std::swap(k2p[pos2], k2p[2]);
            int k2q[3] = {k2p[0], k2p[1], k2p[2]};
            k2q[pos2] = m[j];
            const int e2 = tritri_test::exact_orient2d(P[k2p[0]].z, P[k2p[1]].z, P[k2p[2]].z, pl);
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

// The thread-local counters see the filter decide a clear case and the exact stage decide
// an exact zero (which no floating-point filter can certify).
TEST(ImplicitPredicates, StatsCountFilterAndExactStages) {
  const Point r{0, 0, 0}, s{1, 0, 0}, t{0, 1, 0};
  const auto on_plane = ImplicitPoint::lpi(Point{0.1, 0.2, -1}, Point{0.3, 0.1, 1}, r, s, t);
  const auto R = ImplicitPoint::explicit_point(r), S = ImplicitPoint::explicit_point(s),
             T = ImplicitPoint::explicit_point(t);
  const auto far = ImplicitPoint::lpi(Point{0, 0, 5}, Point{1, 1, 6}, S.approx(), T.approx(), Point{0, 0, 3});
  auto& stats = tritri::implicit_predicate_stats();
  const auto before = stats;
  EXPECT_EQ(tritri::orient3d(R, S, T, on_plane), Sign::Zero);
  EXPECT_EQ(stats.exact, before.exact + 1);
  EXPECT_EQ(tritri::orient3d(R, S, T, far), Sign::Positive);
  EXPECT_EQ(stats.filtered, before.filtered + 1);
}

// ---------------------------------------------------------------------------------------
// Undefined and invalid constructions.

// Inputs of one undefined LPI, mapped by a random exact transform.
struct LpiInputs {
  Point p, q, r, s, t;
  const char* why;
};

Point grid_point(Rng& rng) {
  return {double(rng.uniform(-4, 4)), double(rng.uniform(-4, 4)), double(rng.uniform(-4, 4))};
}
Point combo(const Point& o, const Point& u, double a, const Point& v, double b) {
  return {o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]};
}
Point diff(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Maps all points by t, or none of them if some image is not exact.
void map_all(const tritri_test::Transform& t, std::initializer_list<Point*> pts) {
  std::vector<Point> out;
  for (Point* p : pts) {
    Point q;
    if (!tritri_test::apply(t, *p, q)) return;
    out.push_back(q);
  }
  std::size_t i = 0;
  for (Point* p : pts) *p = out[i++];
}

template <class F>
void expect_refused(F make, const std::string& what, long long& failures) {
  bool threw_domain = false;
  try {
    (void)make(false);
  } catch (const std::domain_error&) {
    threw_domain = true;
  } catch (...) {
  }
  bool threw_domain_points = false;
  try {
    (void)make(true);
  } catch (const std::domain_error&) {
    threw_domain_points = true;
  } catch (...) {
  }
  if ((!threw_domain || !threw_domain_points) && ++failures <= kMaxReports)
    ADD_FAILURE() << "no std::domain_error for " << what;
}

TEST(ImplicitPoint, UndefinedLpiIsRefused) {
  Rng rng(tritri_test::seed_for(31));
  long long cases = 0, failures = 0;
  for (long long n = tritri_test::scaled_count(20000); n > 0; --n) {
    Point r = grid_point(rng), s = grid_point(rng), t = grid_point(rng);
    const Point u = diff(s, r), v = diff(t, r);
    if (tritri_test::is_zero(tritri_test::cross_d(u, v))) continue;
    LpiInputs in{grid_point(rng), {}, r, s, t, ""};
    const double a = rng.uniform(-2, 2), b = rng.uniform(-2, 2) + (a == 0 ? 1 : 0);
    switch (rng.uniform(0, 3)) {
      case 0:  // the line is parallel to the plane
        in.q = combo(in.p, u, a, v, b);
        in.why = "line parallel to the plane";
        break;
      case 1:  // the line lies in the plane
        in.p = combo(r, u, rng.uniform(-2, 2), v, rng.uniform(-2, 2));
        in.q = combo(in.p, u, a, v, b);
        in.why = "line in the plane";
        break;
      case 2:
        in.q = in.p;
        in.why = "p == q";
        break;
      default:  // collinear r, s, t
        in.q = grid_point(rng);
        in.t = combo(r, u, rng.uniform(-3, 3), v, 0);
        in.why = "collinear r, s, t";
        break;
    }
    const tritri_test::Transform tf = tritri_test::random_transform(rng, true);
    map_all(tf, {&in.p, &in.q, &in.r, &in.s, &in.t});
    const Recipe rec = tritri_test::lpi_recipe(in.p, in.q, {in.r, in.s, in.t});
    if (tritri_test::exact_point(rec)) {
      ADD_FAILURE() << "generator: defined " << tritri_test::describe(rec);
      continue;
    }
    ++cases;
    const std::string what = std::string(in.why) + ": " + tritri_test::describe(rec);
    if ((tritri_test::build(rec, false) || tritri_test::build(rec, true)) && ++failures <= kMaxReports)
      ADD_FAILURE() << "try_lpi built " << what;
    expect_refused(
        [&](bool as_points) {
          if (!as_points) return ImplicitPoint::lpi(in.p, in.q, in.r, in.s, in.t);
          auto e = [](const Point& x) { return ImplicitPoint::explicit_point(x); };
          return ImplicitPoint::lpi(e(in.p), e(in.q), e(in.r), e(in.s), e(in.t));
        },
        what, failures);
  }
  std::cout << "[ cases    ] " << cases << " undefined LPIs\n";
  EXPECT_EQ(failures, 0);
}

TEST(ImplicitPoint, UndefinedTpiIsRefused) {
  Rng rng(tritri_test::seed_for(32));
  long long cases = 0, failures = 0;
  auto plane = [&] {
    for (;;) {
      Triple t{grid_point(rng), grid_point(rng), grid_point(rng)};
      if (!tritri_test::is_zero(tritri_test::cross_d(diff(t[1], t[0]), diff(t[2], t[0])))) return t;
    }
  };
  for (long long n = tritri_test::scaled_count(20000); n > 0; --n) {
    std::array<Triple, 3> planes = {plane(), plane(), plane()};
    const char* why = "";
    switch (rng.uniform(0, 4)) {
      case 0: {  // two parallel planes
        const Point d = grid_point(rng);
        for (int i = 0; i < 3; ++i) planes[1][i] = combo(planes[0][i], d, 1, d, 0);
        planes[1] = tritri_test::reordered(planes[1], rng);
        why = "two parallel planes";
        break;
      }
      case 1:  // one plane twice
        planes[1] = tritri_test::reordered(planes[0], rng);
        why = "one plane twice";
        break;
      case 2: {  // three planes through one line
        const Point a = grid_point(rng), b = grid_point(rng);
        if (a == b) continue;
        for (Triple& t : planes) t = tritri_test::reordered({a, b, grid_point(rng)}, rng);
        why = "three planes through one line";
        break;
      }
      case 3: {  // three planes parallel to one direction (a prism)
        const Point d = grid_point(rng);
        if (tritri_test::is_zero(d)) continue;
        for (Triple& t : planes) {
          const Point x = grid_point(rng);
          t = tritri_test::reordered({x, combo(x, d, rng.uniform(1, 2), d, 0), grid_point(rng)}, rng);
        }
        why = "three planes parallel to one direction";
        break;
      }
      default: {  // a collinear triple
        const Point a = grid_point(rng), d = grid_point(rng);
        planes[0] = {a, combo(a, d, 1, d, 0), combo(a, d, -2, d, 0)};
        why = "a collinear triple";
        break;
      }
    }
    tritri_test::shuffle(planes.data(), 3, rng);
    const tritri_test::Transform tf = tritri_test::random_transform(rng, true);
    map_all(tf, {&planes[0][0], &planes[0][1], &planes[0][2], &planes[1][0], &planes[1][1], &planes[1][2],
                 &planes[2][0], &planes[2][1], &planes[2][2]});
    const Recipe rec = tritri_test::tpi_recipe(planes);
    if (tritri_test::exact_point(rec)) {
      ADD_FAILURE() << "generator: defined " << tritri_test::describe(rec);
      continue;
    }
    ++cases;
    const std::string what = std::string(why) + ": " + tritri_test::describe(rec);
    if ((tritri_test::build(rec, false) || tritri_test::build(rec, true)) && ++failures <= kMaxReports)
      ADD_FAILURE() << "try_tpi built " << what;
    expect_refused(
        [&](bool as_points) {
          const auto& v = rec.in;
          if (!as_points) return ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
          std::array<ImplicitPoint, 9> e;
          for (int i = 0; i < 9; ++i) e[i] = ImplicitPoint::explicit_point(v[i]);
          return ImplicitPoint::tpi(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]);
        },
        what, failures);
  }
  std::cout << "[ cases    ] " << cases << " undefined TPIs\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(cases, tritri_test::scaled_count(20000) / 2);
}

TEST(ImplicitPoint, NonFiniteCoordinatesThrowInvalidArgument) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY};
  const std::array<Point, 9> good = {Point{0, 0, 0}, Point{1, 2, 3}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1},
                                     Point{0, 0, 0}, Point{0, 1, 1}, Point{2, 0, 1}, Point{1, 1, 5}};
  for (double x : bad)
    for (int k = 0; k < 3; ++k) {
      Point p{0.5, 0.5, 0.5};
      p[k] = x;
      EXPECT_THROW(ImplicitPoint::explicit_point(p), std::invalid_argument);
      EXPECT_THROW(ImplicitPoint::explicit_point(p[0], p[1], p[2]), std::invalid_argument);
      for (int pos = 0; pos < 9; ++pos) {
        std::array<Point, 9> v = good;
        v[pos] = p;
        if (pos < 5) {
          EXPECT_THROW(ImplicitPoint::lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
          EXPECT_THROW(ImplicitPoint::try_lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument)
              << "position " << pos;
        }
        EXPECT_THROW(ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
            << "position " << pos;
        EXPECT_THROW(ImplicitPoint::try_tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]),
                     std::invalid_argument)
            << "position " << pos;
      }
    }
  // The good inputs themselves are fine (so the throws above come from the bad value).
  EXPECT_TRUE(ImplicitPoint::try_lpi(good[0], good[1], good[2], good[3], good[4]).has_value());
  EXPECT_TRUE(ImplicitPoint::try_tpi(good[0], good[1], good[2], good[3], good[4], good[5], good[6], good[7], good[8])
                  .has_value());
}

TEST(ImplicitPoint, ImplicitArgumentsThrowInvalidArgument) {
  const std::array<Point, 9> good = {Point{0, 0, 0}, Point{1, 2, 3}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1},
                                     Point{0, 0, 0}, Point{0, 1, 1}, Point{2, 0, 1}, Point{1, 1, 5}};
  std::array<ImplicitPoint, 9> e;
  for (int i = 0; i < 9; ++i) e[i] = ImplicitPoint::explicit_point(good[i]);
  const ImplicitPoint lpi = ImplicitPoint::lpi(e[0], e[1], e[2], e[3], e[4]);
  const ImplicitPoint tpi = ImplicitPoint::tpi(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8]);
  for (const ImplicitPoint& x : {lpi, tpi})
    for (int pos = 0; pos < 9; ++pos) {
      std::array<ImplicitPoint, 9> v = e;
      v[pos] = x;
      if (pos < 5) {
        EXPECT_THROW(ImplicitPoint::lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
        EXPECT_THROW(ImplicitPoint::try_lpi(v[0], v[1], v[2], v[3], v[4]), std::invalid_argument) << "position " << pos;
      }
      EXPECT_THROW(ImplicitPoint::tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
          << "position " << pos;
      EXPECT_THROW(ImplicitPoint::try_tpi(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]), std::invalid_argument)
          << "position " << pos;
    }
}

}  // namespace
