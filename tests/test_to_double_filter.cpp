// tests/test_to_double_filter.cpp
//
// tritri::certified_to_double, the long double fast path of to_double(ImplicitPoint),
// against the exact reference (support/exact_oracle.h: GMP rationals from the defining
// points, independent of the library's homogeneous coordinates):
//   - exact ties (a coordinate exactly halfway between two doubles) are never certified,
//     and to_double rounds them to even;
//   - quotients spread over the whole 2^-53 range between rounding boundaries, so that
//     thousands of them lie within 2^-57 (relative) of a boundary: whatever the filter
//     certifies is the nearest double, and it certifies nearly all the rest;
//   - small triangles at offsets up to 2^30 from the origin and long ones across it (LPIs
//     and TPIs): certified results are the nearest doubles; most are certified.
// Counts scale with TRITRI_TEST_SCALE; TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <random>

#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using Point = tritri_test::DoublePoint;
using tritri_test::Q;
using tritri_test::is_nearest_double;
using tritri_test::Q3;
using Triple = tritri_test::DoubleTriple;

// Distance from e to the nearest rounding boundary (midpoint between two doubles), relative
// to |e|, as a double (e a normal, nonzero value).
double relative_distance_to_boundary(const Q& e) {
  const double d = e.get_d();  // truncated: e lies between d and its neighbour away from 0
  const double n = std::nextafter(d, e > 0 ? INFINITY : -INFINITY);
  const Q mid = (Q(d) + Q(n)) / 2;
  return std::fabs(Q((e - mid) / e).get_d());
}

// The line from p to q meets the plane x = 1 (through (1,0,0), (1,1,0), (1,0,1)).
const Triple kPlaneX1{Point{1, 0, 0}, Point{1, 1, 0}, Point{1, 0, 1}};

// The filter is used only where long double has x87's 64-bit significand (elsewhere
// certified_to_double declines everything, and its rates below would not hold).
bool filter_here() { return tritri::detail::kCertifiedToDoubleRuns; }

TEST(CertifiedToDouble, ExactTiesAreLeftToTheExactPathAndRoundToEven) {
  if (!filter_here()) GTEST_SKIP() << "no 64-bit long double here";
  // p + (q - p) / 2 with q_y - p_y two ulps of 1: y is halfway between two doubles; x and
  // z are exact doubles (1, 1), so only the tie can make the filter decline. The control,
  // q_y - p_y = 2^-51, puts y on a double: certified.
  struct Case {
    double qy, nearest;
    bool tie;
  };
  for (const Case c :
       {Case{1 + 0x1p-52, 1.0, true}, Case{1 + 0x3p-52, 1 + 0x1p-51, true}, Case{1 + 0x1p-51, 1 + 0x1p-52, false}}) {
    const Point p{0, 1, 1}, q{2, c.qy, 1};
    const auto lpi = ImplicitPoint::lpi(p, q, kPlaneX1[0], kPlaneX1[1], kPlaneX1[2]);
    const Q3 e = *tritri_test::exact_lpi(p, q, kPlaneX1);
    ASSERT_EQ(e[1], (Q(1) + Q(c.qy)) / 2);
    ASSERT_EQ(e[0], Q(1));
    ASSERT_EQ(e[2], Q(1));
    EXPECT_EQ(tritri::certified_to_double(lpi).has_value(), !c.tie) << std::hexfloat << "q_y " << c.qy;
    EXPECT_EQ(tritri::to_double(lpi)[1], c.nearest) << std::hexfloat << "q_y " << c.qy;
  }
}

// The bound itself, on hand-made filtered values: q = 1 + 2^-53 - 2^-60 lies 2^-60 below
// the boundary between 1 and 1 + 2^-52. A filter error just above that distance declines,
// one well below it certifies 1; a denominator whose error bound reaches half of it declines.
TEST(CertifiedToDouble, BoundAgainstTheDistanceToTheBoundary) {
  if (!filter_here()) GTEST_SKIP() << "no 64-bit long double here";
  using tritri::detail::WideFilteredValue;
  using L = long double;
  const L r = L(0x1p-53) - L(0x1p-60);
  const WideFilteredValue exact_w(L(1), L(0));
  double out = 0;
  // ex = perm * depth * u (1 + 2^-20), u = 2^-64: perm 2^4 gives just over 2^-60.
  EXPECT_FALSE(tritri::detail::certified_nearest_double(1.0, WideFilteredValue(r, L(0x1p4)), 1, exact_w, 1, out));
  EXPECT_TRUE(tritri::detail::certified_nearest_double(1.0, WideFilteredValue(r, L(0x1p2)), 1, exact_w, 1, out));
  EXPECT_EQ(out, 1.0);
  // The same errors on the denominator's side: |x/w| ew / (|w| - ew) with x/w about 2^-53 is
  // tiny, so only aw <= 2 ew (perm 2^63: ew just over 1/2) makes it decline.
  const WideFilteredValue exact_x(r, L(0));
  EXPECT_TRUE(
      tritri::detail::certified_nearest_double(1.0, exact_x, 1, WideFilteredValue(L(1), L(0x1p40)), 1, out));
  EXPECT_FALSE(
      tritri::detail::certified_nearest_double(1.0, exact_x, 1, WideFilteredValue(L(1), L(0x1p63)), 1, out));
}

TEST(CertifiedToDouble, QuotientsNearRoundingBoundariesAreRightOrDeclined) {
  if (!filter_here()) GTEST_SKIP() << "no 64-bit long double here";
  std::mt19937_64 rng(tritri_test::seed_for(61));
  std::uniform_real_distribution<double> unit(1.0, 2.0);
  const long long n = tritri_test::scaled_count(60000);
  long long certified = 0, near = 0, near_certified = 0, failures = 0;
  for (long long i = 0; i < n; ++i) {
    // y = q_y / q_x and z = q_z / q_x: quotients of random doubles, their positions between
    // rounding boundaries spread evenly down to 2^-106.
    const int scale = static_cast<int>(i % 41) - 20;
    const Point p{0, 0, 0}, q{unit(rng), std::ldexp(unit(rng), scale), -unit(rng)};
    const auto lpi = ImplicitPoint::lpi(p, q, kPlaneX1[0], kPlaneX1[1], kPlaneX1[2]);
    const Q3 e = *tritri_test::exact_lpi(p, q, kPlaneX1);
    const auto fast = tritri::certified_to_double(lpi);
    const bool close = relative_distance_to_boundary(e[1]) < 0x1p-57;
    near += close;
    if (!fast) continue;
    ++certified;
    near_certified += close;
    for (int k = 0; k < 3; ++k)
      if (!is_nearest_double((*fast)[k], e[k]) && ++failures <= 10)
        ADD_FAILURE() << std::hexfloat << "q " << q[0] << " " << q[1] << " " << q[2] << ": coordinate " << k
                      << " certified " << (*fast)[k] << ", exact " << e[k].get_str();
  }
  std::cout << "[ cases    ] " << n << " quotients, " << certified << " certified, " << near
            << " within 2^-57 of a rounding boundary (" << near_certified << " of them certified)\n";
  EXPECT_EQ(failures, 0);
  EXPECT_GT(near, n / 100);         // the test reaches the boundaries (expected: n / 16)
  EXPECT_GT(near_certified, 0);     // and the filter decides some of those near them
  EXPECT_GT(certified, n - n / 20);  // and nearly everything else
}

// Random points in a cube of half-width `size` around a centre at distance up to `offset`.
struct Cloud {
  double size, offset;
  int min_percent_lpi, min_percent_tpi;  // of points certified (all coordinates)
};

TEST(CertifiedToDouble, GeneratedLpisAndTpisAreTheNearestDoubles) {
  if (!filter_here()) GTEST_SKIP() << "no 64-bit long double here";
  const Cloud clouds[] = {{1, 0, 50, 10}, {0x1p-10, 1, 90, 85}, {0x1p-7, 0x1p30, 90, 85}, {0x1p-20, 0x1p-10, 90, 85}};
  std::mt19937_64 rng(tritri_test::seed_for(62));
  std::uniform_real_distribution<double> sym(-1.0, 1.0);
  const long long per_cloud = tritri_test::scaled_count(3000);
  long long failures = 0;
  for (const Cloud& c : clouds) {
    long long count[2] = {0, 0}, certified[2] = {0, 0};
    for (long long i = 0; i < per_cloud; ++i) {
      const Point centre{c.offset * sym(rng), c.offset * sym(rng), c.offset * sym(rng)};
      auto point = [&] {
        return Point{centre[0] + c.size * sym(rng), centre[1] + c.size * sym(rng), centre[2] + c.size * sym(rng)};
      };
      for (int kind = 0; kind < 2; ++kind) {
        std::optional<ImplicitPoint> x;
        std::optional<Q3> e;
        if (kind == 0) {
          const Point p = point(), q = point();
          const Triple t{point(), point(), point()};
          x = ImplicitPoint::try_lpi(p, q, t[0], t[1], t[2]);
          if (x) e = tritri_test::exact_lpi(p, q, t);
        } else {
          const std::array<Triple, 3> t{Triple{point(), point(), point()}, Triple{point(), point(), point()},
                                        Triple{point(), point(), point()}};
          x = ImplicitPoint::try_tpi(t[0][0], t[0][1], t[0][2], t[1][0], t[1][1], t[1][2], t[2][0], t[2][1], t[2][2]);
          if (x) e = tritri_test::exact_tpi(t);
        }
        if (!x) continue;
        ASSERT_TRUE(e.has_value());
        ++count[kind];
        const auto fast = tritri::certified_to_double(*x);
        if (!fast) continue;
        ++certified[kind];
        for (int k = 0; k < 3; ++k)
          if (!is_nearest_double((*fast)[k], (*e)[k]) && ++failures <= 10)
            ADD_FAILURE() << (kind ? "TPI" : "LPI") << " size " << c.size << " offset " << c.offset << ": coordinate "
                          << k << " certified " << std::hexfloat << (*fast)[k] << ", exact " << (*e)[k].get_str();
      }
    }
    std::cout << "[ cases    ] size " << c.size << " offset " << c.offset << ": LPIs " << certified[0] << " of "
              << count[0] << " certified, TPIs " << certified[1] << " of " << count[1] << "\n";
    EXPECT_GE(100 * certified[0], c.min_percent_lpi * count[0]) << "size " << c.size << " offset " << c.offset;
    EXPECT_GE(100 * certified[1], c.min_percent_tpi * count[1]) << "size " << c.size << " offset " << c.offset;
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace
