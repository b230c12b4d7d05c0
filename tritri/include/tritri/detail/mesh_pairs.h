// tritri/detail/mesh_pairs.h
//
// The shared machinery of self_intersections.h and intersections.h: input checks that
// turn Eigen matrices into plain point / triangle lists (also used by the arrangement
// pipeline's Eigen and Python entry points: the one place these facts are checked), and
// the parallel classification of candidate pairs (oneTBB) found by box_pairs.h. Not a
// public API: use the two functions.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tritri/classify.h"
#include "tritri/detail/ordered_parallel.h"
#include "tritri/double_kernel.h"
#include "tritri/intersecting_pair.h"
#include "tritri/result.h"

namespace tritri::detail {

using MeshPoint = std::array<double, 3>;
using MeshTriangle = std::array<int, 3>;

// V (#V by 3, finite) as a point list; `where` names the function and the argument in
// messages ("tritri::self_intersections: V").
template <class DerivedV>
std::vector<MeshPoint> checked_vertices(const Eigen::MatrixBase<DerivedV>& V, const std::string& where) {
  static_assert(std::is_floating_point_v<typename DerivedV::Scalar>, "V must hold floating-point coordinates");
  if (V.size() == 0) return {};
  if (V.cols() != 3)
    throw std::invalid_argument(where + " must have 3 columns (x, y, z), got " + std::to_string(V.cols()));
  if (V.rows() > INT_MAX)  // triangles index vertices with int
    throw std::invalid_argument(where + " has more than " + std::to_string(INT_MAX) + " rows");
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
template <class Triangles, class Keep>
std::vector<IntersectingPair> classify_candidates(const std::vector<std::pair<int, int>>& pairs,
                                                  const Triangles& triangles, const Keep& keep) {
  return collect_in_order<IntersectingPair>(
      pairs.size(), 1024, [&](std::size_t, std::size_t begin, std::size_t end, std::vector<IntersectingPair>& out) {
        for (std::size_t k = begin; k < end; ++k) {
          const auto [a0, a1, a2, b0, b1, b2] = triangles(pairs[k]);
          Result r = classify<DoubleKernel>(*a0, *a1, *a2, *b0, *b1, *b2);
          if (keep(k, r)) out.push_back({pairs[k].first, pairs[k].second, r});
        }
      });
}

}  // namespace tritri::detail
