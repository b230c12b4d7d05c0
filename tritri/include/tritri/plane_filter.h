// tritri/plane_filter.h
//
// PlaneFilter: a triangle's plane, cached once, so that "which side of plane(a, b, c) is
// d on" (the sign of orient3d(a, b, c, d)) costs a dot product instead of a determinant,
// and stays decisive for slivers and near-flat triangles, where the plain orient3d filter
// fails. Mesh-level callers (the arrangement pipeline's detection stage) test every
// corner of thousands of nearby triangles against one plane; this pays there.
//
//   PlaneFilter f = plane_filter(a, b, c);        // once per triangle
//   Sign s = side_of_plane(f, a, b, c, d);        // == orient3d(a, b, c, d), exactly
//   std::optional<Sign> s = f.certified_side(a, d);  // the filter alone (nullopt: undecided)
//
// What is cached: n, the normal (b - a) x (c - a), and err, a rigorous bound on
// |n_k - exact n_k| for every k: for well-shaped triangles n in double arithmetic and err a
// forward error bound; for slivers n computed exactly with expansions and rounded, err the
// absolute sum of the exact remainder's components, rounded up. Triangles with a coordinate outside
// the expansion-safe range (double_predicates.h: nonzero magnitudes in [2^-280, 2^280])
// get err = +inf: their filter never decides, and side_of_plane falls back to orient3d.
//
// Why certified_side is exact. det = sum_k n_k w_k with w = d - a exactly; the filter uses
// w^_k = fl(d_k - a_k) = w_k (1 + t), |t| <= u (u = 2^-53), and n^_k = n_k - r_k, |r_k| <=
// err. Then |det - sum n^_k w^_k| <= u/(1-u) sum |n^_k w^_k| + err sum |w^_k| / (1-u), and
// the three-term dot product rounds by at most gamma_3 sum |n^_k w^_k|: in all about
// 4u A + err W for A = sum |n^_k w^_k|, W = sum |w^_k|. The filter uses 8u A + (1 + 2^-40)
// err W, which also covers the rounding of A, W and the bound itself; it only decides when
// A >= 2^-900 (absolute underflow errors, at most a few 2^-1075, are then far below u A).
// Overflow gives inf or NaN in the value or the bound: the comparisons fail, undecided.
// The sign is certified when |fl(n^ . w^)| > bound. Compared with orient3d's semi-static
// bound (48u times the product of the largest coordinate differences), this one scales
// with |n|, so a sliver (|n| much smaller than its squared edge length) no longer spoils it.
//
// Cost: plane_filter ~10 ns (~100 ns with exact expansions, slivers only; once per
// triangle); certified_side a few ns. Memory: 32 bytes per triangle.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "tritri/detail/expansion.h"
#include "tritri/double_kernel.h"
#include "tritri/double_predicates.h"
#include "tritri/sign.h"

namespace tritri {

struct PlaneFilter {
  std::array<double, 3> n{};                             // rounded (b - a) x (c - a) of the triangle (a, b, c)
  double err = std::numeric_limits<double>::infinity();  // |n_k - exact n_k| <= err for each k

  // The sign of orient3d(a, b, c, d) when the filter can certify it, else nullopt. `a` must
  // be the first corner the filter was built with.
  std::optional<Sign> certified_side(const std::array<double, 3>& a, const std::array<double, 3>& d) const noexcept {
    constexpr double u = 0x1p-53;
    const double w0 = d[0] - a[0], w1 = d[1] - a[1], w2 = d[2] - a[2];
    const double p0 = n[0] * w0, p1 = n[1] * w1, p2 = n[2] * w2;
    const double det = p0 + p1 + p2;
    const double A = std::fabs(p0) + std::fabs(p1) + std::fabs(p2);
    const double W = std::fabs(w0) + std::fabs(w1) + std::fabs(w2);
    const double bound = 8 * u * A + (1 + 0x1p-40) * err * W;
    if (!(A >= 0x1p-900)) return std::nullopt;  // also false for NaN
    if (det > bound) return Sign::Positive;
    if (det < -bound) return Sign::Negative;
    return std::nullopt;
  }
};

namespace detail {

// A nonoverlapping expansion summed from its smallest component up (any rounding is
// fine: the caller measures the error of the result exactly).
template <std::size_t N>
double approximate(const Expansion<N>& e) noexcept {
  double s = 0;
  for (std::size_t i = 0; i < e.n; ++i) s += e.v[i];
  return s;
}

}  // namespace detail

inline PlaneFilter plane_filter(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                const std::array<double, 3>& c) noexcept {
  using namespace detail;
  PlaneFilter f;
  for (int k = 0; k < 3; ++k)
    if (!expansion_safe(a[k]) || !expansion_safe(b[k]) || !expansion_safe(c[k])) return f;  // err = inf
  // Well-shaped triangles: the normal in double, with a forward error bound. n_k =
  // fl(fl(u_i v_j) - fl(u_j v_i)) from rounded differences: four roundings on each exact
  // product, so |n_k - exact n_k| <= gamma_4 (|U_i V_j| + |U_j V_i|) <= 5u (|p1| + |p2|)
  // for the computed products p1, p2 (u = 2^-53; the 5 covers gamma_4 / (1 - u)^3), times
  // 1 + 2^-40 for rounding the bound. In the expansion-safe range nonzero differences
  // exceed 2^-332 and products stay far from underflow and overflow. Kept when that bound
  // is below 2^-40 of the largest component (edges not within ~2^-10 of parallel), where
  // it is as decisive as the exact one; slivers take the exact normal below.
  {
    double uf[3], vf[3], big = 0, bound = 0;
    for (int k = 0; k < 3; ++k) {
      uf[k] = b[k] - a[k];
      vf[k] = c[k] - a[k];
    }
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double p1 = uf[i] * vf[j], p2 = uf[j] * vf[i];
      f.n[k] = p1 - p2;
      big = std::max(big, std::fabs(f.n[k]));
      bound = std::max(bound, 5 * 0x1p-53 * (std::fabs(p1) + std::fabs(p2)) * (1 + 0x1p-40));
    }
    if (bound <= big * 0x1p-40) {
      f.err = bound;
      return f;
    }
  }
  Expansion<2> u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = diff(b[k], a[k]);
    v[k] = diff(c[k], a[k]);
  }
  double err = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const auto exact = sum(product(u[i], v[j]), negate(product(u[j], v[i])));  // exact n_k
    f.n[k] = approximate(exact);
    Expansion<1> rounded;
    if (f.n[k] != 0) rounded.push(-f.n[k]);
    const auto remainder = sum(exact, rounded);  // exact n_k - n^_k
    double bound = 0;
    for (std::size_t q = 0; q < remainder.n; ++q) bound += std::fabs(remainder.v[q]);
    // Rounding up: the sum of at most 34 nonnegative terms is within (1 + 34u) of exact.
    bound *= 1 + 0x1p-40;
    err = bound > err ? bound : err;
  }
  f.err = err;
  return f;
}

// The sign of orient3d(a, b, c, d), exactly: the cached plane first, orient3d when it
// cannot decide. f must be plane_filter(a, b, c).
inline Sign side_of_plane(const PlaneFilter& f, const std::array<double, 3>& a, const std::array<double, 3>& b,
                          const std::array<double, 3>& c, const std::array<double, 3>& d) {
  if (const auto s = f.certified_side(a, d)) return *s;
  return orient3d(a, b, c, d);
}

// PlaneCachedKernel: DoubleKernel plus the cached planes of (up to) two triangles, for
// classifying one pair whose planes a mesh caller already has (tritri::classify tests
// every corner of each triangle against the other's plane first). orient3d(a, b, c, d)
// whose a, b, c are the very objects (same addresses, same order) a triangle was
// registered with uses that triangle's PlaneFilter; any other call is DoubleKernel's. The
// same for orient3d_each. The answers are DoubleKernel's in every case (exact); only the
// cost differs. Models OrderedKernel. The registered points and filters must outlive the
// kernel.
class PlaneCachedKernel : public DoubleKernel {
 public:
  PlaneCachedKernel(const Point* const (&a)[3], const PlaneFilter& pa, const Point* const (&b)[3],
                    const PlaneFilter& pb) noexcept
      : tri_{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}}, plane_{&pa, &pb} {}

  Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d) const {
    if (const PlaneFilter* f = registered(a, b, c)) return side_of_plane(*f, a, b, c, d);
    return DoubleKernel::orient3d(a, b, c, d);
  }
  // Overrides DoubleKernel's, which would bypass the cached planes.
  void orient3d_each(const Point& a, const Point& b, const Point& c, const Point& d0, const Point& d1,
                     const Point& d2, Sign (&s)[3]) const {
    if (const PlaneFilter* f = registered(a, b, c)) {
      s[0] = side_of_plane(*f, a, b, c, d0);
      s[1] = side_of_plane(*f, a, b, c, d1);
      s[2] = side_of_plane(*f, a, b, c, d2);
      return;
    }
    DoubleKernel::orient3d_each(a, b, c, d0, d1, d2, s);
  }

 private:
  const PlaneFilter* registered(const Point& a, const Point& b, const Point& c) const noexcept {
    for (int t = 0; t < 2; ++t)
      if (&a == tri_[t][0] && &b == tri_[t][1] && &c == tri_[t][2]) return plane_[t];
    return nullptr;
  }

  const Point* tri_[2][3];
  const PlaneFilter* plane_[2];
};
static_assert(OrderedKernel<PlaneCachedKernel>);

}  // namespace tritri
