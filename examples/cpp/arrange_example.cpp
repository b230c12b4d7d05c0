// Two crossing cubes: which triangles intersect, and exactly how (tritri::intersections),
// and the self-intersections of their union as one mesh (tritri::self_intersections);
// then their exact arrangement (arrangements::arrange over Eigen matrices, from the
// installed tritri::arrangements library).
#include <arrangements/arrange_eigen.h>
#include <tritri/intersections.h>
#include <tritri/self_intersections.h>

#include <Eigen/Core>

#include <cstdio>
#include <iostream>

namespace {

// A closed axis-aligned box: 8 vertices (index 4x + 2y + z), 12 outward triangles.
void cube(double lo, double hi, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  V.resize(8, 3);
  for (int i = 0; i < 8; ++i) V.row(i) << (i & 4 ? hi : lo), (i & 2 ? hi : lo), (i & 1 ? hi : lo);
  F.resize(12, 3);
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  for (int q = 0; q < 6; ++q) {
    F.row(2 * q) << quads[q][0], quads[q][1], quads[q][2];
    F.row(2 * q + 1) << quads[q][0], quads[q][2], quads[q][3];
  }
}

}  // namespace

int main() {
  Eigen::MatrixXd V1, V2;
  Eigen::MatrixXi F1, F2;
  cube(0, 2, V1, F1);
  cube(1, 3, V2, F2);

  const auto pairs = tritri::intersections(V1, F1, V2, F2);
  std::printf("%zu intersecting pairs (triangle of cube 1, triangle of cube 2):\n", pairs.size());
  for (const tritri::IntersectingPair& p : pairs) std::cout << "  " << p.i << " " << p.j << " " << p.result << "\n";

  // The same as one mesh: cube 2's indices follow cube 1's vertices.
  Eigen::MatrixXd V(16, 3);
  Eigen::MatrixXi F(24, 3);
  V << V1, V2;
  F << F1, (F2.array() + 8).matrix();
  const auto self = tritri::self_intersections(V, F);
  std::printf("%zu self-intersecting pairs in the union; each cube alone: %zu and %zu\n", self.size(),
              tritri::self_intersections(V1, F1).size(), tritri::self_intersections(V2, F2).size());
  if (pairs.empty() || self.size() != pairs.size()) return 1;

  // The arrangement of the union, labelled by cube.
  Eigen::VectorXi labels(24);
  labels << Eigen::VectorXi::Zero(12), Eigen::VectorXi::Ones(12);
  const arrangements::EigenArrangement a = arrangements::arrange(V, F, arrangements::ArrangeOptions{}, &labels);
  std::printf("arrangement: %d vertices, %d triangles, Euler characteristic %lld, %zu new points\n",
              static_cast<int>(a.V.rows()), static_cast<int>(a.F.rows()), a.stats.euler,
              a.stats.intersection_points + a.stats.tpi);
  // Two closed surfaces cut along a common curve: their union has Euler characteristic
  // 2 + 2 = 4 (the curve's vertices and edges are shared, it adds V - E = 0).
  return a.stats.euler == 4 && tritri::self_intersections(a.V, a.F).empty() ? 0 : 1;
}
