// tritri/detail/offset.h
//
// Offset homogeneous coordinates of implicit points, for the first filter stage of the
// implicit predicates: (W (p - o), W) for an explicit origin o near the operands.
//
// Why: the cached homogeneous coordinates (X, Y, Z, W) are absolute, so a predicate on
// nearby points cancels terms of the size of the coordinates and the filter's error bound,
// proportional to that size, rarely certifies it (sub-triangles of an arrangement are
// tiny compared to their coordinates). Written from differences of the defining points
// and the origin, the same quantities only carry errors relative to the local size.
//
// Differences of two input doubles are leaves of the filtered expression
// (difference_leaf): one rounding, relative to the difference itself (the forward error
// analysis of Shewchuk's orient3d bound), so their bound term is |a - b|, not |a| + |b|;
// the same in the long double filter (WideFilteredValue), one rounding of u = 2^-64.
#pragma once

#include <array>
#include <span>

#include "tritri/detail/filtered_value.h"
#include "tritri/detail/homogeneous.h"

namespace tritri::detail {

template <class T>
T difference_leaf(double a, double b) {
  return T(a) - T(b);
}
template <>
inline FilteredValue difference_leaf<FilteredValue>(double a, double b) {
  const double d = a - b;
  return {d, d < 0 ? -d : d};
}
template <>
inline WideFilteredValue difference_leaf<WideFilteredValue>(double a, double b) {
  const long double d = static_cast<long double>(a) - static_cast<long double>(b);
  return {d, d < 0 ? -d : d};
}
template <>
inline RoundingDepth difference_leaf<RoundingDepth>(double, double) {
  return RoundingDepth(1, 0);
}

template <class T>
std::array<T, 3> difference_leaves(const Coords& a, const Coords& b) {
  return {difference_leaf<T>(a[0], b[0]), difference_leaf<T>(a[1], b[1]), difference_leaf<T>(a[2], b[2])};
}

// LPI of line (p, q) and plane (r, s, t): W = n . (q - p), lambda = n . (r - p),
// W (x - o) = W (p - o) + lambda (q - p).
template <class T>
Homogeneous<T> lpi_offset(const Coords& p, const Coords& q, const Coords& r, const Coords& s, const Coords& t,
                          const Coords& o) {
  const auto n = cross(difference_leaves<T>(s, r), difference_leaves<T>(t, r));
  const auto pq = difference_leaves<T>(q, p);
  const T w = dot(n, pq);
  const T lambda = dot(n, difference_leaves<T>(r, p));
  const auto po = difference_leaves<T>(p, o);
  return {po[0] * w + lambda * pq[0], po[1] * w + lambda * pq[1], po[2] * w + lambda * pq[2], w};
}

// TPI of three planes (v[3i], v[3i+1], v[3i+2]): with n_i the normals and
// d_i = n_i . (v[3i] - o), W (x - o) = d_0 n_1 x n_2 + d_1 n_2 x n_0 + d_2 n_0 x n_1,
// W = n_0 . (n_1 x n_2).
template <class T>
Homogeneous<T> tpi_offset(std::span<const Coords, 9> v, const Coords& o) {
  std::array<T, 3> n[3];
  T d[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = cross(difference_leaves<T>(v[3 * i + 1], v[3 * i]), difference_leaves<T>(v[3 * i + 2], v[3 * i]));
    d[i] = dot(n[i], difference_leaves<T>(v[3 * i], o));
  }
  const auto n23 = cross(n[1], n[2]), n31 = cross(n[2], n[0]), n12 = cross(n[0], n[1]);
  const T w = dot(n[0], n23);
  return {d[0] * n23[0] + d[1] * n31[0] + d[2] * n12[0], d[0] * n23[1] + d[1] * n31[1] + d[2] * n12[1],
          d[0] * n23[2] + d[1] * n31[2] + d[2] * n12[2], w};
}

}  // namespace tritri::detail
