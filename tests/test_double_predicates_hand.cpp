// tests/test_double_predicates_hand.cpp
//
// tritri::orient3d / tritri::orient2d on doubles, by hand: the sign conventions (as
// CGAL's), and hard cases where naive double evaluation is wrong (Shewchuk's nearly
// collinear grid and its 3D analogue), tiny and huge tetrahedra whose products underflow
// or whose differences overflow, and mixed magnitudes across the whole exponent range;
// each against the exact oracle.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <vector>

#include "support/orient_cases.h"

namespace {

using namespace tritri_test::orient;

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
      ASSERT_EQ(sign_of(tritri::orient2d(Pt<3>{p[0][0], p[0][1], 1}, Pt<3>{12, 12, 2}, Pt<3>{24, 24, 3}, Plane::XY)),
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
      const Case<3> p = {Pt<3>{0.5 + i * u, 0.5 + j * u, 0.5 + (i ^ j) * u}, Pt<3>{12, 12, 0}, Pt<3>{24, 24, 0},
                         Pt<3>{13, 13, 7}};
      const int want = exact_sign(p);
      naive_wrong += naive_sign(naive_det(p)) != want;
      ASSERT_EQ(want == 0, i == j) << describe(p);
      ASSERT_EQ(sign_of(tritri_sign(p)), want) << describe(p);
    }
  EXPECT_GT(naive_wrong, 100);
}

// Products that underflow to zero in double, and differences that overflow.
TEST(PredicateRegressions, TinyAndHugeTetrahedraHaveTheirExactSign) {
  for (double m : {DBL_TRUE_MIN, 0x1p-1070, DBL_MIN, 0x1p-400, 0x1p-300, 0x1p-281, 0x1p-251, 0x1p251, 0x1p281, 0x1p400,
                   0x1p700, DBL_MAX}) {
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
      {Pt<3>{0x1p-280, 0x1p280, 0}, Pt<3>{0x1p-281, 0x1p280, 0x1p-290}, Pt<3>{0, 0x1p281, 1},
       Pt<3>{0x1p-279, 0, 0x1p279}},
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
