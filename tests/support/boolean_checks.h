// tests/support/boolean_checks.h
//
// Independent checks of Boolean outputs, in exact rational arithmetic (CGAL::Gmpq):
//   volume(mesh)          the signed volume enclosed by a triangle mesh (sum of the
//                         tetrahedra to the origin), exactly; works on soups and meshes
//   unbalanced_edges(m)   edges whose uses in one direction and the other differ (0 for
//                         a closed, consistently oriented mesh), by exact vertex position
//   winding_at(soup, label, p)   the winding number of one operand (triangles with that
//                         label; kAllLabels: every triangle) at a rational point p by a ray cast with CGAL Epeck:
//                         std::nullopt when the ray meets an edge, a corner or a face in
//                         its plane (the caller picks another point)
// None of them uses the code under test.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"

namespace tritri_test {

using Q = CGAL::Gmpq;
using Q3 = std::array<Q, 3>;

inline Q3 exact_of(const arrangements::Vec3& p) { return {Q(p[0]), Q(p[1]), Q(p[2])}; }
inline Q3 exact_of(const arrangements::ExactVec3& p) { return p; }
inline Q3 exact_of(const tritri::ImplicitPoint& p) { return tritri::to_exact(p); }

template <class Mesh>
std::vector<Q3> exact_vertices(const Mesh& m) {
  std::vector<Q3> v;
  v.reserve(m.vertices.size());
  for (const auto& p : m.vertices) v.push_back(exact_of(p));
  return v;
}

inline Q det3(const Q3& a, const Q3& b, const Q3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

template <class Mesh>
Q volume(const Mesh& m) {
  const std::vector<Q3> v = exact_vertices(m);
  Q sum = 0;
  for (const auto& t : m.triangles) sum += det3(v[t[0]], v[t[1]], v[t[2]]);
  return sum / 6;
}

// Edges (by exact endpoint positions) used more often one way than the other.
template <class Mesh>
std::size_t unbalanced_edges(const Mesh& m) {
  const std::vector<Q3> v = exact_vertices(m);
  std::map<Q3, int> id;
  std::vector<int> ids(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) ids[i] = id.emplace(v[i], static_cast<int>(id.size())).first->second;
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = ids[t[k]], b = ids[t[(k + 1) % 3]];
      if (a < b) ++count[{a, b}];
      else --count[{b, a}];
    }
  std::size_t bad = 0;
  for (const auto& [e, c] : count) bad += c != 0;
  return bad;
}

// Winding number of the triangles carrying `label` at p, by a ray along a fixed generic
// direction; nullopt when the ray is degenerate for some triangle.
inline constexpr std::uint32_t kAllLabels = 0xffffffffu;

template <class Soup>
std::optional<int> winding_at(const Soup& soup, std::uint32_t label, const Q3& p) {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  const K::Point_3 o(p[0], p[1], p[2]);
  const K::Vector_3 d(Q(1000003), Q(1009), Q(917));
  const std::vector<Q3> v = exact_vertices(soup);
  int w = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& labels = soup.label_sets[soup.label_set[t]];
    if (label != kAllLabels && std::find(labels.begin(), labels.end(), label) == labels.end()) continue;
    const auto& tri = soup.triangles[t];
    const K::Point_3 a(v[tri[0]][0], v[tri[0]][1], v[tri[0]][2]);
    const K::Point_3 b(v[tri[1]][0], v[tri[1]][1], v[tri[1]][2]);
    const K::Point_3 c(v[tri[2]][0], v[tri[2]][1], v[tri[2]][2]);
    if (CGAL::collinear(a, b, c)) continue;
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
    const auto along = CGAL::sign(n * d);
    const auto side = CGAL::orientation(a, b, c, o);
    if (side == CGAL::COPLANAR) return std::nullopt;
    if (along == CGAL::ZERO) continue;  // parallel to the ray, off its plane
    // where the line meets the plane
    const K::FT s = (n * (a - o)) / (n * d);
    if (s <= 0) continue;
    const K::Point_3 x = o + s * d;
    const auto o1 = CGAL::orientation(a, b, x, a + n), o2 = CGAL::orientation(b, c, x, b + n),
               o3 = CGAL::orientation(c, a, x, c + n);
    if (o1 == CGAL::COPLANAR || o2 == CGAL::COPLANAR || o3 == CGAL::COPLANAR) {
      if ((o1 == o2 || o1 == CGAL::COPLANAR || o2 == CGAL::COPLANAR) &&
          (o2 == o3 || o2 == CGAL::COPLANAR || o3 == CGAL::COPLANAR) &&
          (o1 == o3 || o1 == CGAL::COPLANAR || o3 == CGAL::COPLANAR))
        return std::nullopt;  // on an edge or a corner
      continue;
    }
    if (o1 == o2 && o2 == o3) w += along == CGAL::POSITIVE ? 1 : -1;
  }
  return w;
}

}  // namespace tritri_test
