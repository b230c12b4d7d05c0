// tritri/detail/mesh_pairs.h
//
// The shared machinery of self_intersections.h and intersections.h: input checks that
// turn Eigen matrices into plain point / triangle lists, bounding-box candidate pairs
// (CGAL's box_self_intersection_d) and their parallel classification (oneTBB). Not a
// public API: use the two functions.
#pragma once

#include <CGAL/box_intersection_d.h>
#include <Eigen/Core>
#include <tbb/parallel_for.h>

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
  std::vector<MeshPoint> points(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index r = 0; r < V.rows(); ++r)
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double x = static_cast<double>(V(r, c));
      if (!std::isfinite(x))
        throw std::invalid_argument(where + "(" + std::to_string(r) + ", " + std::to_string(c) + ") = " +
                                    std::to_string(x) + " is not a finite coordinate");
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
    throw std::invalid_argument(where + " must have 3 columns (one triangle per row), got " +
                                std::to_string(F.cols()));
  if (F.rows() > INT_MAX)
    throw std::invalid_argument(where + " has more than " + std::to_string(INT_MAX) + " rows");
  std::vector<MeshTriangle> triangles(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index r = 0; r < F.rows(); ++r)
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto v = F(r, c);
      bool negative = false;
      if constexpr (std::is_signed_v<typename DerivedF::Scalar>) negative = v < 0;
      if (negative || static_cast<unsigned long long>(v) >= vertex_count)
        throw std::invalid_argument(where + "(" + std::to_string(r) + ", " + std::to_string(c) + ") = " +
                                    std::to_string(v) + " is out of range (the vertex list has " +
                                    std::to_string(vertex_count) + " rows)");
      triangles[r][c] = static_cast<int>(v);
    }
  return triangles;
}

// A triangle's closed axis-aligned bounding box; its id is the triangle's index in the
// concatenation of the meshes (a stable id, unlike CGAL's global counter).
class TriangleBox {
 public:
  using NT = double;
  using ID = std::size_t;

  TriangleBox(const MeshPoint& a, const MeshPoint& b, const MeshPoint& c, std::size_t id) : id_(id) {
    for (int k = 0; k < 3; ++k) {
      lo_[k] = std::min({a[k], b[k], c[k]});
      hi_[k] = std::max({a[k], b[k], c[k]});
    }
  }
  static int dimension() noexcept { return 3; }
  double min_coord(int k) const noexcept { return lo_[k]; }
  double max_coord(int k) const noexcept { return hi_[k]; }
  std::size_t id() const noexcept { return id_; }

 private:
  std::array<double, 3> lo_, hi_;
  std::size_t id_;
};

inline void append_boxes(const std::vector<MeshPoint>& V, const std::vector<MeshTriangle>& F,
                         std::vector<TriangleBox>& boxes) {
  const std::size_t first = boxes.size();
  for (std::size_t t = 0; t < F.size(); ++t)
    boxes.emplace_back(V[F[t][0]], V[F[t][1]], V[F[t][2]], first + t);
}

// Every pair of ids (a < b) of boxes that overlap or touch, sorted, each once.
inline std::vector<std::pair<std::size_t, std::size_t>> overlapping_boxes(std::vector<TriangleBox>& boxes) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (boxes.size() < 2) return pairs;
  auto report = [&pairs](const TriangleBox& a, const TriangleBox& b) {
    if (a.id() != b.id()) pairs.emplace_back(std::min(a.id(), b.id()), std::max(a.id(), b.id()));
  };
  const CGAL::Box_intersection_d::Box_traits_d<TriangleBox> traits;
  CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), report, traits,
                                                      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Classifies candidate pairs in parallel: fixed chunks, each filling its own list, joined
// in order, so the output keeps the order of `pairs` for any number of threads.
// keep(index into pairs, Result) decides what is reported.
template <class Triangles, class Keep>
std::vector<IntersectingPair> classify_candidates(const std::vector<std::pair<int, int>>& pairs,
                                                  const Triangles& triangles, const Keep& keep) {
  constexpr std::size_t chunk = 1024;
  const std::size_t chunks = (pairs.size() + chunk - 1) / chunk;
  std::vector<std::vector<IntersectingPair>> found(chunks);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    const std::size_t end = std::min(pairs.size(), (c + 1) * chunk);
    for (std::size_t k = c * chunk; k < end; ++k) {
      const auto [a0, a1, a2, b0, b1, b2] = triangles(pairs[k]);
      Result r = classify<DoubleKernel>(*a0, *a1, *a2, *b0, *b1, *b2);
      if (keep(k, r)) found[c].push_back({pairs[k].first, pairs[k].second, r});
    }
  });
  std::size_t total = 0;
  for (const auto& f : found) total += f.size();
  std::vector<IntersectingPair> out;
  out.reserve(total);
  for (const auto& f : found) out.insert(out.end(), f.begin(), f.end());
  return out;
}

}  // namespace tritri::detail
