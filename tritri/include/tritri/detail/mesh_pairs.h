// tritri/detail/mesh_pairs.h
//
// The shared machinery of self_intersections.h and intersections.h: input checks that
// turn Eigen matrices into plain point / triangle lists (also used by the arrangement
// pipeline's Eigen and Python entry points: the one place these facts are checked), the
// vertices in the kernel their scalar calls for (floating point: DoubleKernel; CGAL::Gmpq:
// RationalKernel, with double bounds for the boxes), and the parallel classification of
// candidate pairs (oneTBB) found by box_pairs.h. Not a public API: use the two functions.
#pragma once

#include <CGAL/Gmpq.h>  // before Eigen is used with it: Eigen::NumTraits<CGAL::Gmpq>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "tritri/classify.h"
#include "tritri/detail/ordered_parallel.h"
#include "tritri/double_kernel.h"
#include "tritri/intersecting_pair.h"
#include "tritri/rational_kernel.h"
#include "tritri/result.h"

namespace tritri::detail {

using MeshPoint = std::array<double, 3>;
using MeshTriangle = std::array<int, 3>;

// V's shape: 3 columns, at most INT_MAX rows (triangles index vertices with int).
template <class DerivedV>
void check_vertex_shape(const Eigen::MatrixBase<DerivedV>& V, const std::string& where) {
  if (V.cols() != 3)
    throw std::invalid_argument(where + " must have 3 columns (x, y, z), got " + std::to_string(V.cols()));
  if (V.rows() > INT_MAX)
    throw std::invalid_argument(where + " has more than " + std::to_string(INT_MAX) + " rows");
}

// V (#V by 3, finite) as a point list; `where` names the function and the argument in
// messages ("tritri::self_intersections: V").
template <class DerivedV>
std::vector<MeshPoint> checked_vertices(const Eigen::MatrixBase<DerivedV>& V, const std::string& where) {
  static_assert(std::is_floating_point_v<typename DerivedV::Scalar>, "V must hold floating-point coordinates");
  if (V.size() == 0) return {};
  check_vertex_shape(V, where);
  std::vector<MeshPoint> points(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index r = 0; r < V.rows(); ++r)
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double x = static_cast<double>(V(r, c));
      if (!std::isfinite(x))
        throw std::invalid_argument(where + "(" + std::to_string(r) + ", " + std::to_string(c) +
                                    ") = " + std::to_string(x) + " is not a finite coordinate");
      points[r][c] = x;
    }
  return points;
}

// V (#V by 3 CGAL::Gmpq) as a list of rational points, every |coordinate| <= DBL_MAX (so
// that bounding boxes are finite doubles; the rule of the mesh loaders too).
template <class DerivedV>
std::vector<std::array<CGAL::Gmpq, 3>> checked_rational_vertices(const Eigen::MatrixBase<DerivedV>& V,
                                                                 const std::string& where) {
  static_assert(std::is_same_v<typename DerivedV::Scalar, CGAL::Gmpq>, "V must hold CGAL::Gmpq coordinates");
  if (V.size() == 0) return {};
  check_vertex_shape(V, where);
  const CGAL::Gmpq largest(DBL_MAX);  // exactly: a double is a rational
  std::vector<std::array<CGAL::Gmpq, 3>> points(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index r = 0; r < V.rows(); ++r)
    for (Eigen::Index c = 0; c < 3; ++c) {
      const CGAL::Gmpq& x = V(r, c);
      if (x > largest || x < -largest)
        throw std::invalid_argument(where + "(" + std::to_string(r) + ", " + std::to_string(c) +
                                    ") is beyond the largest finite double");
      points[r][c] = x;
    }
  return points;
}

// The kernel for coordinate scalars: all floating point (converted to double) ->
// DoubleKernel; any CGAL::Gmpq -> RationalKernel (doubles are rationals too, exactly).
template <class... Scalars>
using MeshKernel = std::conditional_t<(std::is_floating_point_v<Scalars> && ...), DoubleKernel, RationalKernel>;

// Checked vertices as Kernel points, with each coordinate's double bounds for the boxes
// (for doubles the points themselves).
template <class Kernel>
struct MeshVertices {
  std::vector<typename Kernel::Point> points;
  std::vector<MeshPoint> lo, hi;  // RationalKernel only
  std::span<const MeshPoint> lower() const {
    if constexpr (std::is_same_v<Kernel, DoubleKernel>) return points; else return lo;
  }
  std::span<const MeshPoint> upper() const {
    if constexpr (std::is_same_v<Kernel, DoubleKernel>) return points; else return hi;
  }
  std::size_t size() const { return points.size(); }
};

// V's rows as Kernel points: DoubleKernel for floating-point V; RationalKernel for V of
// CGAL::Gmpq, or of doubles converted exactly (a mesh met with a rational one).
template <class Kernel, class DerivedV>
MeshVertices<Kernel> mesh_vertices(const Eigen::MatrixBase<DerivedV>& V, const std::string& where) {
  using Scalar = typename DerivedV::Scalar;
  static_assert(std::is_floating_point_v<Scalar> || std::is_same_v<Scalar, CGAL::Gmpq>,
                "V must hold floating-point or CGAL::Gmpq coordinates");
  if constexpr (std::is_same_v<Kernel, DoubleKernel>) {
    return {checked_vertices(V, where), {}, {}};
  } else {
    std::vector<std::array<CGAL::Gmpq, 3>> rational;
    if constexpr (std::is_floating_point_v<Scalar>) {
      for (const MeshPoint& p : checked_vertices(V, where)) rational.push_back({p[0], p[1], p[2]});
    } else {
      rational = checked_rational_vertices(V, where);
    }
    MeshVertices<RationalKernel> out;
    out.points.reserve(rational.size());
    out.lo.resize(rational.size());
    out.hi.resize(rational.size());
    for (std::size_t v = 0; v < rational.size(); ++v) {
      out.points.emplace_back(rational[v][0], rational[v][1], rational[v][2]);
      for (int c = 0; c < 3; ++c)  // an interval that contains the rational (to_interval)
        std::tie(out.lo[v][c], out.hi[v][c]) = CGAL::to_interval(rational[v][c]);
    }
    return out;
  }
}

// F (#F by 3, indices into a vertex list of `vertex_count` rows) as a triangle list.
template <class DerivedF>
std::vector<MeshTriangle> checked_triangles(const Eigen::MatrixBase<DerivedF>& F, std::size_t vertex_count,
                                            const std::string& where) {
  static_assert(std::is_integral_v<typename DerivedF::Scalar>, "F must hold integer vertex indices");
  if (F.size() == 0) return {};
  if (F.cols() != 3)
    throw std::invalid_argument(where + " must have 3 columns (one triangle per row), got " + std::to_string(F.cols()));
  if (F.rows() > INT_MAX) throw std::invalid_argument(where + " has more than " + std::to_string(INT_MAX) + " rows");
  std::vector<MeshTriangle> triangles(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index r = 0; r < F.rows(); ++r)
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto v = F(r, c);
      bool negative = false;
      if constexpr (std::is_signed_v<typename DerivedF::Scalar>) negative = v < 0;
      if (negative || static_cast<unsigned long long>(v) >= vertex_count)
        throw std::invalid_argument(where + "(" + std::to_string(r) + ", " + std::to_string(c) +
                                    ") = " + std::to_string(v) + " is out of range (the vertex list has " +
                                    std::to_string(vertex_count) + " rows)");
      triangles[r][c] = static_cast<int>(v);
    }
  return triangles;
}

// Classifies candidate pairs in parallel (collect_in_order: the output keeps the order of
// `pairs` for any number of threads). keep(index into pairs, Result) decides what is
// reported.
template <class Kernel, class Triangles, class Keep>
std::vector<IntersectingPair> classify_candidates(const std::vector<std::pair<int, int>>& pairs,
                                                  const Triangles& triangles, const Keep& keep) {
  return collect_in_order<IntersectingPair>(
      pairs.size(), 1024, [&](std::size_t, std::size_t begin, std::size_t end, std::vector<IntersectingPair>& out) {
        for (std::size_t k = begin; k < end; ++k) {
          const auto [a0, a1, a2, b0, b1, b2] = triangles(pairs[k]);
          Result r = classify<Kernel>(*a0, *a1, *a2, *b0, *b1, *b2);
          if (keep(k, r)) out.push_back({pairs[k].first, pairs[k].second, r});
        }
      });
}

}  // namespace tritri::detail
