// tests/test_implicit_point_construction.cpp
//
// Building implicit points (implicit_point.h) against the exact reference computed in GMP
// rationals from the defining points (support/exact_oracle.h), independent of the
// library's homogeneous coordinates:
//   - hand-made cases: one point as an LPI and as a TPI, a line through a point of the
//     plane, a subnormal coordinate rounded by to_double;
//   - generated points (support/implicit_scenes.h) are defined exactly when the reference
//     says so, to_exact is the reference point and to_double its nearest double.
// Counts scale with TRITRI_TEST_SCALE; TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/implicit_recipes.h"
#include "support/implicit_scenes.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri::Plane;
using tritri::Sign;
using tritri_test::kPlanes;
using tritri_test::Point;
using tritri_test::Q;
using tritri_test::is_nearest_double;
using tritri_test::Q3;
using tritri_test::Recipe;
using tritri_test::Rng;
using tritri_test::run_scenes;
using tritri_test::Scene;
using tritri_test::Triple;

constexpr int kMaxReports = 10;  // failures printed in full per test

// ---------------------------------------------------------------------------------------
// Hand-made cases: the specification in miniature.

// The diagonal of the unit cube meets the plane x + y + z = 1 at (1/3, 1/3, 1/3), which is
// also the meeting point of the planes x = y, y = z and x + y + z = 1.
TEST(ImplicitPoint, DiagonalMeetsPlaneAtOneThirdAsLpiAndAsTpi) {
  const Point o{0, 0, 0}, d{1, 1, 1}, ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  const auto lpi = ImplicitPoint::lpi(o, d, ex, ey, ez);
  const auto tpi = ImplicitPoint::tpi(o, Point{1, 1, 0}, ez, o, d, ex, ex, ey, ez);
  const Q third(1, 3);
  for (const auto& p : {lpi, tpi}) {
    const Q3 q = tritri_test::exact(p);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(q[k], third);
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

// to_double divides the exact integers once where the result is a normal double, and goes
// through the rational elsewhere. The line from the origin to (s, 0, 1) meets the plane
// through (0, 0, 1/2), (a, 0, 1/2 + b) and (0, 1, 1/2) at x = s / (2 (1 - s b / a)), here
// on both sides of each switch: 2^-1022 (1 +- 2^-75)^-1 (around the smallest normal);
// (2^-1022 - 2^-1075) (1 - (+-2^-75 - 2^-128))^-1 (around the midpoint between the largest
// subnormal and 2^-1022, where a first rounding to 53 bits would tie); 2^1024 (1 +- 2^-50)^-1
// (around the largest double and the overflow).
TEST(ImplicitPoint, ToDoubleIsTheNearestDoubleAroundTheEndsOfTheNormalRange) {
  struct Case {
    double s, a, b;
    double lo, hi;  // the exact x lies strictly between lo and hi (the case tests what it says)
  };
  const double tiny = 0x1p-1022, below_tiny = 0x1p-1022 - 0x1p-1074, max = std::numeric_limits<double>::max();
  const Case cases[] = {
      {0x1p-1021, 0x1p-946, 1, tiny, 0x1p-1021},    // just above 2^-1022
      {0x1p-1021, 0x1p-946, -1, below_tiny, tiny},  // just below
      {0x1p-1021 - 0x1p-1074, 0x1p-946, 1, below_tiny, tiny},  // just above the midpoint
      {0x1p-1021 - 0x1p-1074, 0x1p-946, -1, below_tiny, tiny},  // just below it
      {0x1p1023, 0x1p1023, 0.75 - 0x1p-52, 0x1p1023, max},  // a normal double below the largest
      {0x1p1023, 0x1p1023, 0.75 + 0x1p-52, max, INFINITY},  // beyond: overflows
  };
  for (const Case& c : cases) {
    const Point p{0, 0, 0}, q{c.s, 0, 1};
    const Triple plane{Point{0, 0, 0.5}, Point{c.a, 0, 0.5 + c.b}, Point{0, 1, 0.5}};
    const auto ref = tritri_test::exact_lpi(p, q, plane);
    ASSERT_TRUE(ref.has_value());
    const Q& x = (*ref)[0];
    std::ostringstream out;
    out << std::hexfloat << "s " << c.s << " b " << c.b << ": exact " << x.get_str();
    const std::string where = out.str();
    if (std::isfinite(c.hi)) {
      EXPECT_TRUE(Q(c.lo) < x && x < Q(c.hi)) << where;
    }
    const auto d = tritri::to_double(ImplicitPoint::lpi(p, q, plane[0], plane[1], plane[2]));
    if (std::isinf(c.hi)) {
      // Beyond the midpoint between the largest double and 2^1024: infinity.
      EXPECT_TRUE(x > Q(max) + Q(0x1p970)) << where;
      EXPECT_EQ(d[0], INFINITY) << where;
    } else {
      EXPECT_TRUE(is_nearest_double(d[0], x)) << where << std::hexfloat << ", to_double " << d[0];
    }
    EXPECT_EQ(d[1], 0.0) << where;
  }
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
                      << tritri_test::to_string(*tritri_test::exact_point(r));
    for (const Recipe& r : s.wrongly_accepted)
      if (++failures <= kMaxReports) ADD_FAILURE() << "undefined point accepted: " << tritri_test::describe(r);
    for (const auto& p : s.points)
      if (p.point.kind() != p.recipe.kind && ++failures <= kMaxReports)
        ADD_FAILURE() << "kind " << tritri_test::kind_name(p.point.kind()) << " for "
                      << tritri_test::describe(p.recipe);
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
      const Q3 e = tritri_test::exact(p.point);  // through tritri::to_exact
      const auto d = tritri::to_double(p.point);
      for (int k = 0; k < 3; ++k) {
        const bool exact_ok = e[k] == p.exact[k];
        const bool double_ok = is_nearest_double(d[k], p.exact[k]);
        if ((!exact_ok || !double_ok) && ++failures <= kMaxReports)
          ADD_FAILURE() << "coordinate " << k << " of " << tritri_test::describe(p.recipe) << "\n  reference "
                        << p.exact[k].get_str() << "\n  to_exact  " << e[k].get_str() << "\n  to_double "
                        << std::hexfloat << d[k] << (double_ok ? "" : " (not the nearest double)");
      }
    }
    return 1;
  });
  std::cout << "[ cases    ] " << points << " points\n";
  EXPECT_EQ(failures, 0);
}

}  // namespace
