// arrangements/src/booleans/point_orient.h (internal to the Boolean stage)
//
// orient3d on the points of a model's output mesh (M::Point: implicit points for
// DoubleModel, with tritri's filtered exact predicates; Epeck points for ExactModel), and
// on exact rational coordinates (ExactVec3), for the few tests made on converted points.
// Convention (tritri/kernel_concept.h): Positive when d lies on the side of plane abc that
// the normal (b - a) x (c - a) points to.
// Exact for every point; O(1).
#pragma once

#include <tritri/implicit_predicates.h>

#include "arrangements/triangle_soup.h"
#include "models/double_model.h"
#include "models/exact_model.h"

namespace arrangements {

inline tritri::Sign orient3d_points(const tritri::ImplicitPoint& a, const tritri::ImplicitPoint& b,
                                    const tritri::ImplicitPoint& c, const tritri::ImplicitPoint& d) {
  return tritri::orient3d(a, b, c, d);
}

inline tritri::Sign orient3d_points(const ExactModel::Point& a, const ExactModel::Point& b,
                                    const ExactModel::Point& c, const ExactModel::Point& d) {
  return ExactModel::orient3d(a, b, c, d);
}

inline tritri::Sign orient3d_points(const ExactVec3& a, const ExactVec3& b, const ExactVec3& c, const ExactVec3& d) {
  CGAL::Gmpq m[3][3];
  for (int k = 0; k < 3; ++k) {
    m[0][k] = b[k] - a[k];
    m[1][k] = c[k] - a[k];
    m[2][k] = d[k] - a[k];
  }
  const CGAL::Gmpq det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det > 0 ? tritri::Sign::Positive : det < 0 ? tritri::Sign::Negative : tritri::Sign::Zero;
}

}  // namespace arrangements
