// tritri/cgal_kernel.h
//
// CgalKernel<CK>: tritri's kernel concept over a CGAL kernel CK, with CK::Point_3 as the
// point type. Tested with CGAL::Epick (exact predicates on double input),
// CGAL::Epeck and CGAL::Simple_cartesian<CGAL::Gmpq> (exact rationals).
//
// Exactness: as exact as CK's predicates (exact for the three kernels above).
// orient2d uses CGAL's projection traits; our ZX plane is (z, x), the reverse of CGAL's
// Projection_traits_xz_3, hence the sign flip there.
#pragma once

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>

#include "tritri/kernel_concept.h"

namespace tritri {

template <class CK>
struct CgalKernel {
  using Point = typename CK::Point_3;

  static Sign from_cgal(CGAL::Orientation o) noexcept {
    return o == CGAL::POSITIVE ? Sign::Positive : (o == CGAL::NEGATIVE ? Sign::Negative : Sign::Zero);
  }
  static Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return from_cgal(CGAL::orientation(a, b, c, d));
  }
  static Sign orient2d(const Point& a, const Point& b, const Point& c, Plane plane) {
    switch (plane) {
      case Plane::XY:
        return from_cgal(CGAL::Projection_traits_xy_3<CK>().orientation_2_object()(a, b, c));
      case Plane::YZ:
        return from_cgal(CGAL::Projection_traits_yz_3<CK>().orientation_2_object()(a, b, c));
      default:
        return -from_cgal(CGAL::Projection_traits_xz_3<CK>().orientation_2_object()(a, b, c));
    }
  }
  static bool equal(const Point& a, const Point& b) { return a == b; }
  static bool less(const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; }
};

}  // namespace tritri
