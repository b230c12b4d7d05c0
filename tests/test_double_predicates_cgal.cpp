// tests/test_double_predicates_cgal.cpp
//
// tritri::orient3d / tritri::orient2d on doubles agree with CGAL::orientation on Epeck and
// Epick, and tritri::CgalKernel's orient2d over those kernels agrees with them on every
// projection, on a mixture of the generated families (support/orient_cases.h).
// Case counts scale with TRITRI_TEST_SCALE; TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include "tritri/cgal_kernel.h"

#include "support/exact_oracle.h"
#include "support/orient_cases.h"
#include "support/test_scale.h"

namespace {

using namespace tritri_test::orient;
using Epeck = tritri_test::ExactKernel;
using Epick = tritri_test::InputKernel;
using tritri_test::to_cgal;

// ---------------------------------------------------------------------------------------
// Agreement with CGAL.

int from_cgal(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0); }

TEST(Orient3dAgreesWithCgal, OrientationOnEpeckAndEpick) {
  Rng r(orient_seed(400));
  for (long i = 0, n = tritri_test::scaled_count(5000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    const int got = sign_of(tritri_sign(p));
    const int epeck = from_cgal(
        CGAL::orientation(to_cgal<Epeck>(p[0]), to_cgal<Epeck>(p[1]), to_cgal<Epeck>(p[2]), to_cgal<Epeck>(p[3])));
    const int epick = from_cgal(
        CGAL::orientation(to_cgal<Epick>(p[0]), to_cgal<Epick>(p[1]), to_cgal<Epick>(p[2]), to_cgal<Epick>(p[3])));
    ASSERT_EQ(got, epeck) << describe(p);
    ASSERT_EQ(got, epick) << describe(p);
  }
}

// The kernel adapters must agree with the double predicates on every projection.
TEST(Orient2dAgreesWithCgal, CgalKernelProjectionsOnEveryPlane) {
  Rng r(orient_seed(401));
  for (long i = 0, n = tritri_test::scaled_count(3000); i < n; ++i) {
    const Case<3> p = mixed_case<3>(r);
    for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
      const int got = sign_of(tritri::orient2d(p[0], p[1], p[2], plane));
      const int epeck = sign_of(
          tritri::CgalKernel<Epeck>::orient2d(to_cgal<Epeck>(p[0]), to_cgal<Epeck>(p[1]), to_cgal<Epeck>(p[2]), plane));
      const int epick = sign_of(
          tritri::CgalKernel<Epick>::orient2d(to_cgal<Epick>(p[0]), to_cgal<Epick>(p[1]), to_cgal<Epick>(p[2]), plane));
      ASSERT_EQ(got, epeck) << describe(p) << " plane " << static_cast<int>(plane);
      ASSERT_EQ(got, epick) << describe(p) << " plane " << static_cast<int>(plane);
    }
  }
}

}  // namespace
