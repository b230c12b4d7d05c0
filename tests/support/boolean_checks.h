// tests/support/boolean_checks.h
//
// Independent checks of Boolean outputs, in exact rational arithmetic (CGAL::Gmpq):
//   volume(mesh)          the signed volume enclosed by a triangle mesh (sum of the
//                         tetrahedra to the origin), exactly; works on soups and meshes
//   unbalanced_edges(m)   edges whose uses in one direction and the other differ (0 for
//                         a closed, consistently oriented mesh), by exact vertex position
//   RayWinding(soup, label).at(p)   the winding number of one operand (triangles with
//                         that label; kAllLabels: every triangle) at a rational point p by
//                         a ray cast along +x in rationals: std::nullopt when the ray meets
//                         an edge, a corner or a face in its plane (the caller picks
//                         another point)
//   solid_corners(m)      the vertex positions where the closed mesh is not flat (below)
//   outside_source(out, input)   the output triangles with a corner outside the input
//                         triangle named by their `source` (not in its plane, or beyond one
//                         of its edges): 0 when every output triangle lies in its source
// None of them uses the code under test.
#pragma once

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

inline Q3 minus(const Q3& a, const Q3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Q3 cross(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q dot(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline int sign(const Q& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

inline constexpr std::uint32_t kAllLabels = 0xffffffffu;

// Winding number of the triangles carrying `label` at p, by a ray along +x: each
// triangle the ray crosses adds sign(n_x); nullopt when the ray is degenerate for some
// triangle (p in its plane, or the ray through an edge or a corner). The triangles'
// exact corners, normals and boxes are computed once.
class RayWinding {
 public:
  template <class Soup>
  RayWinding(const Soup& soup, std::uint32_t label) {
    const std::vector<Q3> v = exact_vertices(soup);
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
      const auto& labels = soup.label_sets[soup.label_set[t]];
      if (label != kAllLabels && std::find(labels.begin(), labels.end(), label) == labels.end()) continue;
      const auto& tri = soup.triangles[t];
      Face f{v[tri[0]], v[tri[1]], v[tri[2]], {}, {}, {}};
      f.n = cross(minus(f.b, f.a), minus(f.c, f.a));
      if (f.n[0] == 0 && f.n[1] == 0 && f.n[2] == 0) continue;  // degenerate: bounds nothing
      f.lo = f.hi = f.a;
      for (const Q3* q : {&f.b, &f.c})
        for (int k = 0; k < 3; ++k) {
          if ((*q)[k] < f.lo[k]) f.lo[k] = (*q)[k];
          if ((*q)[k] > f.hi[k]) f.hi[k] = (*q)[k];
        }
      faces_.push_back(std::move(f));
    }
  }

  std::optional<int> at(const Q3& p) const {
    int w = 0;
    for (const Face& f : faces_) {
      if (f.hi[0] < p[0] || p[1] < f.lo[1] || p[1] > f.hi[1] || p[2] < f.lo[2] || p[2] > f.hi[2]) continue;
      const int side = sign(dot(f.n, minus(p, f.a)));
      if (side == 0) return std::nullopt;
      const int along = sign(f.n[0]);
      if (along == 0 || side == along) continue;  // parallel, or the plane behind p
      // inside-ness in the YZ projection: p's projection against the three edges
      auto turn = [&](const Q3& u, const Q3& w2) {
        return sign((w2[1] - u[1]) * (p[2] - u[2]) - (w2[2] - u[2]) * (p[1] - u[1]));
      };
      const int s1 = turn(f.a, f.b) * along, s2 = turn(f.b, f.c) * along, s3 = turn(f.c, f.a) * along;
      if (s1 < 0 || s2 < 0 || s3 < 0) continue;                // outside
      if (s1 == 0 || s2 == 0 || s3 == 0) return std::nullopt;  // on an edge or a corner
      w += along;
    }
    return w;
  }

 private:
  struct Face {
    Q3 a, b, c, n, lo, hi;
  };
  std::vector<Face> faces_;
};

template <class Mesh, class Soup>
std::size_t outside_source(const Mesh& out, const Soup& input) {
  const std::vector<Q3> v = exact_vertices(out), in = exact_vertices(input);
  std::size_t bad = 0;
  for (std::size_t f = 0; f < out.triangles.size(); ++f) {
    const auto& s = input.triangles[out.source[f]];
    const Q3 &a = in[s[0]], &b = in[s[1]], &c = in[s[2]];
    const Q3 n = cross(minus(b, a), minus(c, a));
    bool ok = true;
    for (int p : out.triangles[f]) {
      const Q3& x = v[p];
      ok &= dot(n, minus(x, a)) == 0 && dot(n, cross(minus(b, a), minus(x, a))) >= 0 &&
            dot(n, cross(minus(c, b), minus(x, b))) >= 0 && dot(n, cross(minus(a, c), minus(x, c))) >= 0;
    }
    bad += !ok;
  }
  return bad;
}

// The corners of a closed mesh's solid: the vertex positions where the surface is not
// flat (the triangles around them lie in three or more planes, or in two planes whose
// crease bends there), sorted. Extra vertices that a triangulation puts inside a flat
// region or along a straight crease are not corners, so two meshes of one solid have the
// same corners however they are triangulated.
template <class Mesh>
std::vector<Q3> solid_corners(const Mesh& m) {
  const std::vector<Q3> v = exact_vertices(m);
  std::map<Q3, std::vector<std::size_t>> around;  // position -> triangles
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) around[v[m.triangles[t][k]]].push_back(t);
  auto normal = [&](std::size_t t) {
    const auto& x = m.triangles[t];
    return cross(minus(v[x[1]], v[x[0]]), minus(v[x[2]], v[x[0]]));
  };
  auto parallel = [](const Q3& a, const Q3& b) {
    const Q3 c = cross(a, b);
    return c[0] == 0 && c[1] == 0 && c[2] == 0 && dot(a, b) > 0;
  };
  std::vector<Q3> corners;
  for (const auto& [p, ts] : around) {
    std::vector<Q3> planes;
    for (std::size_t t : ts) {
      const Q3 n = normal(t);
      if (std::none_of(planes.begin(), planes.end(), [&](const Q3& q) { return parallel(q, n); }))
        planes.push_back(n);
    }
    if (planes.size() == 1) continue;
    if (planes.size() > 2) {
      corners.push_back(p);
      continue;
    }
    // two planes: the crease edges at p (edges of a triangle of each plane) must run
    // straight through p
    std::vector<Q3> crease;
    for (std::size_t t : ts)
      for (int k = 0; k < 3; ++k) {
        const Q3& q = v[m.triangles[t][k]];
        if (q == p) continue;
        const Q3 d = minus(q, p);
        if (dot(planes[0], d) == 0 && dot(planes[1], d) == 0) crease.push_back(d);
      }
    bool straight = !crease.empty();
    for (const Q3& d : crease)
      for (const Q3& e : crease) {
        const Q3 c = cross(d, e);
        straight &= c[0] == 0 && c[1] == 0 && c[2] == 0;
      }
    bool both_ways = false;
    for (const Q3& d : crease)
      for (const Q3& e : crease) both_ways |= dot(d, e) < 0;
    if (!(straight && both_ways)) corners.push_back(p);
  }
  return corners;  // sorted: std::map order
}

}  // namespace tritri_test
