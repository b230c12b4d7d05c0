// tests/support/brute_force_mesh_pairs.h
//
// The references of the batch-API tests (test_self_intersections, test_rational_batch):
// the documented rules of tritri::self_intersections and tritri::intersections written out
// directly, over all pairs of triangles.
//   brute_force_self(m, classify_rows)    pairs i < j of m's rows that meet beyond the
//                                         vertices they share by index, or have the same
//                                         three indices
//   brute_force_two(a, b, classify_rows)  pairs (row of a, row of b) with a common point
// A mesh is anything with an Eigen matrix F of vertex indices; classify_rows(a, i, b, j)
// classifies row i of a against row j of b (the test picks the kernel). Cost: O(#F^2).
#pragma once

#include <tritri/intersecting_pair.h>
#include <tritri/result.h>

#include <vector>

namespace tritri_test {

template <class Mesh, class ClassifyRows>
std::vector<tritri::IntersectingPair> brute_force_self(const Mesh& m, const ClassifyRows& classify_rows) {
  std::vector<tritri::IntersectingPair> out;
  for (int i = 0; i < m.F.rows(); ++i)
    for (int j = i + 1; j < m.F.rows(); ++j) {
      const tritri::Result r = classify_rows(m, i, m, j);
      int shared = 0;
      for (const auto& p : r.points) shared += p.type == tritri::Type::VA_ON_VB && m.F(i, p.id0) == m.F(j, p.id1);
      const bool same_indices = shared == 3;
      if (int(r.points.size()) > shared || same_indices) out.push_back({i, j, r});
    }
  return out;
}

template <class Mesh, class ClassifyRows>
std::vector<tritri::IntersectingPair> brute_force_two(const Mesh& a, const Mesh& b, const ClassifyRows& classify_rows) {
  std::vector<tritri::IntersectingPair> out;
  for (int i = 0; i < a.F.rows(); ++i)
    for (int j = 0; j < b.F.rows(); ++j)
      if (const tritri::Result r = classify_rows(a, i, b, j); r.intersects()) out.push_back({i, j, r});
  return out;
}

}  // namespace tritri_test
