// tritri/detail/homogeneous.h
//
// Homogeneous coordinates (X, Y, Z, W) of implicit points, written once over a number
// type T that supports +, - and * and construction from the defining points' coordinates
// (FilteredValue for the filter, CGAL::Mpzf or CGAL::Gmpq for exact evaluation of double
// points; an exact rational type for points with rational coordinates, the pipeline's
// exact path). A defining point is anything indexable by 0, 1, 2 (std::array<double, 3>,
// a CGAL Point_3). The point is (X/W, Y/W, Z/W).
//
//   LPI(p, q; r, s, t): the line through p, q meets the plane through r, s, t.
//     n = (s-r) x (t-r),  W = n.(q-p),  (X,Y,Z) = p W + (n.(r-p)) (q-p).
//     Degrees in the input coordinates: W 3, X 4.
//   TPI(planes i = 1..3 through a_i, b_i, c_i):
//     n_i = (b_i-a_i) x (c_i-a_i),  d_i = n_i.a_i,
//     W = n_1.(n_2 x n_3),  (X,Y,Z) = d_1 (n_2 x n_3) + d_2 (n_3 x n_1) + d_3 (n_1 x n_2)
//     (Cramer's rule). Degrees: W 6, X 7.
#pragma once

#include <array>
#include <span>

namespace tritri::detail {

using Coords = std::array<double, 3>;

template <class T>
struct Homogeneous {
  T x, y, z, w;
};

template <class T, class P>
std::array<T, 3> difference(const P& a, const P& b) {
  return {T(a[0]) - T(b[0]), T(a[1]) - T(b[1]), T(a[2]) - T(b[2])};
}

template <class T>
std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
T dot(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T, class P>
Homogeneous<T> lpi_homogeneous(const P& p, const P& q, const P& r, const P& s, const P& t) {
  const auto n = cross(difference<T>(s, r), difference<T>(t, r));
  const auto pq = difference<T>(q, p);
  const T w = dot(n, pq);
  const T lambda = dot(n, difference<T>(r, p));
  return {T(p[0]) * w + lambda * pq[0], T(p[1]) * w + lambda * pq[1], T(p[2]) * w + lambda * pq[2], w};
}

template <class T, class P>
Homogeneous<T> tpi_homogeneous(std::span<const P, 9> v) {
  std::array<T, 3> n[3];
  T d[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = cross(difference<T>(v[3 * i + 1], v[3 * i]), difference<T>(v[3 * i + 2], v[3 * i]));
    d[i] = dot(n[i], {T(v[3 * i][0]), T(v[3 * i][1]), T(v[3 * i][2])});
  }
  const auto n23 = cross(n[1], n[2]), n31 = cross(n[2], n[0]), n12 = cross(n[0], n[1]);
  const T w = dot(n[0], n23);
  return {d[0] * n23[0] + d[1] * n31[0] + d[2] * n12[0], d[0] * n23[1] + d[1] * n31[1] + d[2] * n12[1],
          d[0] * n23[2] + d[1] * n31[2] + d[2] * n12[2], w};
}

}  // namespace tritri::detail
