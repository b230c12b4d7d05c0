// tritri/double_kernel.h
//
// DoubleKernel: points with double coordinates and the exact predicates of
// double_predicates.h. Models tritri::OrderedKernel, with the optional orient3d_each.
//
// Preconditions: finite coordinates. Exactness: every predicate exact for finite input.
#pragma once

#include <array>

#include "tritri/double_predicates.h"
#include "tritri/kernel_concept.h"

namespace tritri {

struct DoubleKernel {
  using Point = std::array<double, 3>;

  static Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return tritri::orient3d(a, b, c, d);
  }
  static void orient3d_each(const Point& a, const Point& b, const Point& c, const Point& d0, const Point& d1,
                            const Point& d2, Sign (&s)[3]) {
    const double* const d[3] = {d0.data(), d1.data(), d2.data()};
    tritri::orient3d_each(a.data(), b.data(), c.data(), d, s);
  }
  static Sign orient2d(const Point& a, const Point& b, const Point& c, Plane plane) {
    return tritri::orient2d(a, b, c, plane);
  }
  static bool equal(const Point& a, const Point& b) noexcept { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
  static bool less(const Point& a, const Point& b) noexcept { return a < b; }
};

static_assert(OrderedKernel<DoubleKernel>);
// classify finds orient3d_each only if its signature matches the concept's exactly.
static_assert(requires(const DoubleKernel::Point& p, Sign (&s)[3]) {
  DoubleKernel::orient3d_each(p, p, p, p, p, p, s);
});

}  // namespace tritri
