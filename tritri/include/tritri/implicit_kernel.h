// tritri/implicit_kernel.h
//
// ImplicitKernel: tritri's kernel concept over ImplicitPoint (explicit, LPI and TPI
// points), with the filtered exact predicates of implicit_predicates.h. This is what an
// arrangement's sub-triangles need: classify<ImplicitKernel> on triangles whose vertices
// are intersection points. Exact for every input.
#pragma once

#include "tritri/implicit_point.h"
#include "tritri/implicit_predicates.h"
#include "tritri/kernel_concept.h"

namespace tritri {

struct ImplicitKernel {
  using Point = ImplicitPoint;

  static Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return tritri::orient3d(a, b, c, d);
  }
  static Sign orient2d(const Point& a, const Point& b, const Point& c, Plane plane) {
    return tritri::orient2d(a, b, c, plane);
  }
  static bool equal(const Point& a, const Point& b) { return tritri::equal(a, b); }
  static bool less(const Point& a, const Point& b) { return tritri::less(a, b); }
};

static_assert(OrderedKernel<ImplicitKernel>);

}  // namespace tritri
