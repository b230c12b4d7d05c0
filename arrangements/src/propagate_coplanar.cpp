#include "arrangements/propagate_coplanar.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include <tritri/implicit_predicates.h>

namespace arrangements {
namespace {

// Where point x (in t's plane) lies in closed triangle t: -2 outside, -1 inside,
// 0..2 on that open edge, 3..5 at vertex (k - 3).
int locate(const std::vector<tritri::ImplicitPoint>& P, const Tri& t, tritri::Plane plane, int orientation,
           int x) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == x) return 3 + k;
  int zeros = 0, edge = -1;
  for (int k = 0; k < 3; ++k) {
    const int s = tritri::to_int(tritri::orient2d(P[t[k]], P[t[(k + 1) % 3]], P[x], plane)) * orientation;
    if (s < 0) return -2;
    if (s == 0) {
      ++zeros;
      edge = k;
    }
  }
  if (zeros == 0) return -1;
  if (zeros == 1) return edge;
  return -2;  // on two edge lines: a vertex, but vertices were matched by id above
}

struct Additions {
  std::vector<int> inside;
  std::vector<std::array<int, 2>> on_edge;  // (edge id, point)
  std::vector<std::array<int, 2>> segments;
};

}  // namespace

void propagate_coplanar(const std::vector<Vec3>& V, const std::vector<Tri>& F, IntersectionGraph& g) {
  std::vector<Additions> add(F.size());
  tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
    if (g.coplanar_partners[t].empty()) return;
    const Tri& tri = F[t];
    tritri::Plane plane = tritri::Plane::XY;
    int orientation = 0;
    for (tritri::Plane p : {tritri::Plane::XY, tritri::Plane::YZ, tritri::Plane::ZX}) {
      orientation = tritri::to_int(tritri::orient2d(V[tri[0]], V[tri[1]], V[tri[2]], p));
      if (orientation != 0) {
        plane = p;
        break;
      }
    }
    Additions& a = add[t];
    auto place = [&](int x) {
      const int where = locate(g.points, tri, plane, orientation, x);
      if (where == -1) a.inside.push_back(x);
      else if (where >= 0 && where <= 2) a.on_edge.push_back({g.triangle_edges[t][where], x});
      return where != -2;
    };
    for (int u : g.coplanar_partners[t]) {
      for (int x : g.triangle_points[u]) place(x);
      for (int k = 0; k < 3; ++k)
        for (int x : g.edge_points[g.triangle_edges[u][k]]) place(x);
      for (const auto& s : g.triangle_segments[u])
        if (locate(g.points, tri, plane, orientation, s[0]) != -2 &&
            locate(g.points, tri, plane, orientation, s[1]) != -2)
          a.segments.push_back(s);
    }
  });
  for (std::size_t t = 0; t < F.size(); ++t) {
    for (int x : add[t].inside) g.triangle_points[t].push_back(x);
    for (const auto& e : add[t].on_edge) g.edge_points[e[0]].push_back(e[1]);
    for (const auto& s : add[t].segments) g.triangle_segments[t].push_back(s);
  }
  auto sort_unique = [](auto& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  tbb::parallel_for(std::size_t{0}, F.size(), [&](std::size_t t) {
    sort_unique(g.triangle_points[t]);
    sort_unique(g.triangle_segments[t]);
  });
  tbb::parallel_for(std::size_t{0}, g.edges.size(), [&](std::size_t e) { sort_unique(g.edge_points[e]); });
}

}  // namespace arrangements
