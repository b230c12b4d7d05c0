// tritri/self_intersections.h
//
// self_intersections(V, F): every pair of triangles of one mesh that intersect beyond the
// mesh vertices they share, with the exact classification of each pair.
//
//   #include <tritri/self_intersections.h>
//   for (const tritri::IntersectingPair& p : tritri::self_intersections(V, F))
//     std::cout << p.i << " " << p.j << " " << p.result << "\n";
//
// Inputs:
//   V  #V by 3 matrix of vertex coordinates: any Eigen dense expression with a
//      floating-point scalar (e.g. Eigen::MatrixXd), finite; or with scalar CGAL::Gmpq
//      (exact rationals, e.g. an exact arrangement's vertices), |x| <= DBL_MAX
//   F  #F by 3 matrix of triangle corners, indices into the rows of V (any Eigen dense
//      expression with an integer scalar, e.g. Eigen::MatrixXi)
//   An empty matrix (V.size() == 0 or F.size() == 0) is an empty list, whatever its shape.
// Output:
//   a list of tritri::IntersectingPair {i, j, result} (intersecting_pair.h), one per
//   reported pair, i < j rows of F, result = tritri::classify<DoubleKernel> (RationalKernel
//   for CGAL::Gmpq coordinates, rational_kernel.h) of rows i and j
//   in the order of their columns; sorted by (i, j).
//
// Which pairs are reported. Vertices are shared by index: corner a of row i and corner b
// of row j are a shared mesh vertex when F(i, a) == F(j, b). A pair is reported when
// classify finds a point of the intersection that is not a shared vertex (any point other
// than VA_ON_VB(a, b) with F(i, a) == F(j, b)), or when the two rows have the same three
// indices (a duplicated face, in either orientation: the triangles coincide). So
//   - neighbours that meet only along their shared edge or at a shared vertex are not
//     reported; neighbours that also meet elsewhere (a fold, an overlap, a crossing) are,
//     and their result still lists the shared vertices as VA_ON_VB points;
//   - two corners at equal coordinates but different indices are not shared: the mesh
//     touches itself there and the pair is reported (merge duplicate vertices first to
//     treat them as shared);
//   - degenerate triangles (repeated index, coincident or collinear corners) are not
//     classified (classify's precondition) and never reported.
// This is the rule of the arrangement pipeline (arrangements/classify_tritri.h: a pair
// whose only points are VA_ON_VB is dropped), which merges duplicate vertices and removes
// degenerate and duplicated triangles before it classifies: on such a mesh both agree.
//
// Throws std::invalid_argument (naming the matrix, the entry and the problem) when V or F
// does not have 3 columns, a coordinate is NaN, infinite or (rationals) beyond the largest
// double, an index is out of range, or F has more than INT_MAX rows.
//
// Exactness: every decision is an exact predicate on the input coordinates (doubles:
// DoubleKernel; rationals: RationalKernel, filtered); the bounding boxes are the exact
// minima and maxima of the corners (rationals: of an interval of doubles around each) and
// closed (boxes that only touch are candidates), and box pairs are dropped only when their
// certified slabs along 10 diagonal directions are apart or (doubles) when they share a
// vertex whose star is embedded, an exact certificate that they meet only in what they
// share (candidate_triangle_pairs.h, embedded_stars.h), so no reported pair is missed. No tolerance anywhere.
// Determinism: the output does not depend on the number of threads.
// Complexity: O(n log^3 n + k) for the candidates (CGAL's box_self_intersection_d on n
// triangles, k overlapping boxes, sequential), then one classification per candidate left
// by the slabs (candidate_triangle_pairs.h), in parallel with
// oneTBB (tbb::parallel_for over chunks of 1024 pairs, in the calling thread's arena: run
// it inside a tbb::task_arena to limit the threads). Memory: O(#V + #F + k).
// Dependencies: Eigen, CGAL (headers), oneTBB (link TBB::tbb), and tritri's own (GMP).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "tritri/candidate_triangle_pairs.h"
#include "tritri/detail/mesh_pairs.h"
#include "tritri/intersecting_pair.h"

namespace tritri {

template <class DerivedV, class DerivedF>
std::vector<IntersectingPair> self_intersections(const Eigen::MatrixBase<DerivedV>& V,
                                                 const Eigen::MatrixBase<DerivedF>& F) {
  using Kernel = detail::MeshKernel<typename DerivedV::Scalar>;
  using Point = typename Kernel::Point;
  const detail::MeshVertices<Kernel> points = detail::mesh_vertices<Kernel>(V, "tritri::self_intersections: V");
  const std::vector<detail::MeshTriangle> tris =
      detail::checked_triangles(F, points.size(), "tritri::self_intersections: F");

  // Doubles: neighbours around a vertex whose star is embedded meet only in what they share
  // (never reported), so they are not candidates.
  std::vector<std::uint8_t> embedded;
  if constexpr (std::is_same_v<Kernel, DoubleKernel>) embedded = embedded_stars(points.points, tris);
  const std::vector<std::pair<int, int>> pairs =
      candidate_triangle_pairs(points.lower(), points.upper(), tris, 0, {}, embedded);

  auto corners = [&](const std::pair<int, int>& pair) {
    const detail::MeshTriangle &a = tris[pair.first], &b = tris[pair.second];
    const std::vector<Point>& p = points.points;
    return std::array<const Point*, 6>{&p[a[0]], &p[a[1]], &p[a[2]], &p[b[0]], &p[b[1]], &p[b[2]]};
  };
  auto beyond_shared = [&](std::size_t k, const Result& r) {
    const detail::MeshTriangle &a = tris[pairs[k].first], &b = tris[pairs[k].second];
    for (const IntersectionPoint& q : r.points)
      if (q.type != Type::VA_ON_VB || a[q.id0] != b[q.id1]) return true;
    // Only shared vertices: the same three indices means the same triangle twice.
    return r.points.size() == 3;
  };
  return detail::classify_candidates<Kernel>(pairs, corners, beyond_shared);
}

}  // namespace tritri
