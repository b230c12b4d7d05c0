// tritri/intersections.h
//
// intersections(V1, F1, V2, F2): every pair (triangle of mesh 1, triangle of mesh 2) that
// intersects, with the exact classification of each pair.
//
//   #include <tritri/intersections.h>
//   for (const tritri::IntersectingPair& p : tritri::intersections(V1, F1, V2, F2))
//     std::cout << "F1 row " << p.i << " meets F2 row " << p.j << ": " << p.result << "\n";
//
// Inputs:
//   V1  #V1 by 3 matrix of vertex coordinates of mesh 1: any Eigen dense expression with a
//       floating-point scalar (e.g. Eigen::MatrixXd), finite; or with scalar CGAL::Gmpq
//       (exact rationals, e.g. an exact arrangement's vertices), |x| <= DBL_MAX
//   F1  #F1 by 3 matrix of triangle corners, indices into the rows of V1 (any Eigen dense
//       expression with an integer scalar, e.g. Eigen::MatrixXi)
//   V2, F2  mesh 2, likewise (when one of V1, V2 holds CGAL::Gmpq, the other's doubles are
//           taken as rationals, exactly)
//   An empty matrix (size() == 0) is an empty list, whatever its shape.
// Output:
//   a list of tritri::IntersectingPair {i, j, result} (intersecting_pair.h), one per pair
//   whose closed triangles have a common point: i a row of F1 (triangle A), j a row of F2
//   (triangle B), result = tritri::classify<DoubleKernel>(A, B) (RationalKernel for
//   CGAL::Gmpq coordinates, rational_kernel.h) with the corners in the
//   order of the columns; sorted by (i, j).
//
// The two meshes share no vertices: every contact counts, a single common point too (a
// corner of one at a corner of the other is VA_ON_VB). Degenerate triangles (repeated
// index, coincident or collinear corners) are not classified (classify's precondition)
// and never reported. Passing the same mesh twice lists every pair (i, j) of touching
// triangles, neighbours and i == j included: for one mesh use self_intersections.h.
//
// Throws std::invalid_argument (naming the matrix, the entry and the problem) when a
// matrix does not have 3 columns, a coordinate is NaN, infinite or (rationals) beyond the
// largest double, an index is out of range, or F1 or F2 has more than INT_MAX rows.
//
// Exactness: every decision is an exact predicate on the input coordinates (doubles:
// DoubleKernel; rationals: RationalKernel, filtered); the bounding boxes are exact and
// closed (rationals: an interval of doubles around each coordinate), and box pairs are
// dropped only when their certified slabs along 10 diagonal directions are apart
// (candidate_triangle_pairs.h), so no intersecting pair is missed. No tolerance.
// Determinism: the output does not depend on the number of threads.
// Complexity: candidates by CGAL's box_self_intersection_d on the n = #F1 + #F2 boxes of
// both meshes, keeping the pairs across them (O(n log^3 n + k) for k overlapping boxes,
// pairs within one mesh included; sequential), then one classification per candidate
// the slabs leave (candidate_triangle_pairs.h)
// across the meshes in parallel with oneTBB (tbb::parallel_for over chunks of 1024 pairs,
// in the calling thread's arena: run it inside a tbb::task_arena to limit the threads).
// Memory: O(#V1 + #V2 + n + k).
// Dependencies: Eigen, CGAL (headers), oneTBB (link TBB::tbb), and tritri's own (GMP).
#pragma once

#include <Eigen/Core>

#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "tritri/candidate_triangle_pairs.h"
#include "tritri/detail/mesh_pairs.h"
#include "tritri/intersecting_pair.h"

namespace tritri {

template <class DerivedV1, class DerivedF1, class DerivedV2, class DerivedF2>
std::vector<IntersectingPair> intersections(const Eigen::MatrixBase<DerivedV1>& V1,
                                            const Eigen::MatrixBase<DerivedF1>& F1,
                                            const Eigen::MatrixBase<DerivedV2>& V2,
                                            const Eigen::MatrixBase<DerivedF2>& F2) {
  using Kernel = detail::MeshKernel<typename DerivedV1::Scalar, typename DerivedV2::Scalar>;
  using Point = typename Kernel::Point;
  const detail::MeshVertices<Kernel> points1 = detail::mesh_vertices<Kernel>(V1, "tritri::intersections: V1");
  const std::vector<detail::MeshTriangle> tris1 =
      detail::checked_triangles(F1, points1.size(), "tritri::intersections: F1");
  const detail::MeshVertices<Kernel> points2 = detail::mesh_vertices<Kernel>(V2, "tritri::intersections: V2");
  const std::vector<detail::MeshTriangle> tris2 =
      detail::checked_triangles(F2, points2.size(), "tritri::intersections: F2");

  // One search over both meshes, each mesh one group (so pairs within a mesh are never
  // enumerated): triangle ids below #F1 are mesh 1, the rest mesh 2.
  constexpr bool doubles = std::is_same_v<Kernel, DoubleKernel>;
  auto joined = [](std::span<const detail::MeshPoint> a, std::span<const detail::MeshPoint> b) {
    std::vector<detail::MeshPoint> out(a.begin(), a.end());
    out.insert(out.end(), b.begin(), b.end());
    return out;
  };
  std::vector<detail::MeshPoint> lo = joined(points1.lower(), points2.lower());
  std::vector<detail::MeshPoint> hi =
      doubles ? std::vector<detail::MeshPoint>{} : joined(points1.upper(), points2.upper());
  std::vector<detail::MeshTriangle> tris(tris1);
  const int offset = static_cast<int>(points1.size());
  for (detail::MeshTriangle t : tris2) tris.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  std::vector<std::int64_t> group(tris1.size(), 0);
  group.resize(tris.size(), 1);
  const int n1 = static_cast<int>(tris1.size());
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : candidate_triangle_pairs(lo, doubles ? lo : hi, tris, 0, group))
    pairs.emplace_back(a, b - n1);
  lo = {};
  hi = {};
  tris = {};

  auto corners = [&](const std::pair<int, int>& pair) {
    const detail::MeshTriangle &a = tris1[pair.first], &b = tris2[pair.second];
    const std::vector<Point>&p1 = points1.points, &p2 = points2.points;
    return std::array<const Point*, 6>{&p1[a[0]], &p1[a[1]], &p1[a[2]], &p2[b[0]], &p2[b[1]], &p2[b[2]]};
  };
  auto intersect = [](std::size_t, const Result& r) { return r.intersects(); };
  return detail::classify_candidates<Kernel>(pairs, corners, intersect);
}

}  // namespace tritri
