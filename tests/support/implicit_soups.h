// tests/support/implicit_soups.h
//
// Soups for the implicit classify tests: triangles, the LPIs where their edges cross the
// other triangles' planes, and several representations of every point (explicit when it
// is a double point, LPIs of the edge either way, TPIs of planes through it), so that
// sub-triangle pairs share vertices, have vertices on each other's edges, are coplanar,
// ... and name one point in different ways (random_soup). All tests are exact
// (rationals), in the mapped coordinates.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "exact_oracle.h"
#include "implicit_recipes.h"
#include "pair_generators.h"

namespace tritri_test {

struct SoupPoint {
  Q3 exact;
  std::vector<Recipe> reps;
};

struct Soup {
  std::vector<Triple> triangles;
  std::vector<SoupPoint> points;
  std::vector<std::vector<int>> on;  // on[t]: the points in the plane of triangle t
  std::vector<Recipe> rejected;      // representations whose exact point differed (generator bug)
};

class SoupBuilder {
 public:
  SoupBuilder(Rng& rng, bool grid, const Transform& t) : rng_(rng), grid_(grid), t_(t) {}

  Point any_point() {
    Point p;
    for (double& x : p) x = grid_ ? rng_.uniform(-3, 3) : rng_.symmetric_unit();
    return mapped(p);
  }

  Soup build(int n_triangles) {
    for (int i = 0; i < n_triangles; ++i) add_triangle();
    const int n = static_cast<int>(soup_.triangles.size());
    soup_.on.resize(n);
    for (int i = 0; i < n; ++i)
      for (const Point& v : soup_.triangles[i]) {
        const int id = point_id(explicit_recipe(v));
        soup_.on[i].push_back(id);
        // The line from v to a point off the plane meets the plane at v.
        const Point m = any_point();
        if (sign_against(soup_.triangles[i], m) != 0)
          add_rep(id, lpi_recipe(v, m, reordered(soup_.triangles[i], rng_)));
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) cross_edges(i, j);
    for (auto& on : soup_.on) {
      std::sort(on.begin(), on.end());
      on.erase(std::unique(on.begin(), on.end()), on.end());
    }
    return std::move(soup_);
  }

 private:
  Point mapped(const Point& p) {
    Point q;
    return apply(t_, p, q) ? q : p;
  }

  static int sign_against(const Triple& t, const Point& p) {
    return orient3d(exact(t[0]), exact(t[1]), exact(t[2]), exact(p));
  }

  // Triangles on the grid (or random), some sharing an edge or a vertex with an earlier
  // one, some coplanar with an earlier one (affine combinations of its vertices).
  void add_triangle() {
    for (;;) {
      Triple t{any_point(), any_point(), any_point()};
      if (!soup_.triangles.empty()) {
        const Triple& o = soup_.triangles[rng_.uniform(0, static_cast<int>(soup_.triangles.size()) - 1)];
        const int mode = rng_.uniform(0, 9);
        if (mode < 2) {
          t[0] = o[rng_.uniform(0, 2)];
        } else if (mode < 4) {
          const int e = rng_.uniform(0, 2);
          t[0] = o[e];
          t[1] = o[(e + 1) % 3];
        } else if (mode < 6 && grid_) {  // coplanar: affine combinations (w0 o0 + w1 o1 + w2 o2) / 4
          for (Point& v : t) {
            const int w0 = rng_.uniform(-2, 5), w1 = rng_.uniform(-2, 5);
            const int w2 = 4 - w0 - w1;
            for (int k = 0; k < 3; ++k) v[k] = (w0 * o[0][k] + w1 * o[1][k] + w2 * o[2][k]) * 0.25;
          }
        }
      }
      if (!collinear(exact(t[0]), exact(t[1]), exact(t[2]))) {
        soup_.triangles.push_back(t);
        return;
      }
    }
  }

  // The id of the point of r (a new point if none has its exact coordinates).
  int point_id(const Recipe& r) {
    const auto q = exact_point(r);
    for (std::size_t i = 0; i < soup_.points.size(); ++i)
      if (soup_.points[i].exact == *q) {
        add_rep(static_cast<int>(i), r);
        return static_cast<int>(i);
      }
    soup_.points.push_back({*q, {r}});
    Point e;  // a point that is a double point also gets its explicit representation
    if (r.kind != PointKind::Explicit && representable((*q)[0], e[0]) && representable((*q)[1], e[1]) &&
        representable((*q)[2], e[2]))
      soup_.points.back().reps.push_back(explicit_recipe(e));
    return static_cast<int>(soup_.points.size()) - 1;
  }

  void add_rep(int id, const Recipe& r) {
    const auto q = exact_point(r);
    if (!q) return;  // undefined alternative (e.g. a random plane through the line)
    if (*q != soup_.points[id].exact) {
      soup_.rejected.push_back(r);
      return;
    }
    for (const Recipe& o : soup_.points[id].reps)
      if (o.kind == r.kind && o.in == r.in) return;
    soup_.points[id].reps.push_back(r);
  }

  // Edges of triangle i crossing (or touching) the plane of triangle j.
  void cross_edges(int i, int j) {
    const Triple& T = soup_.triangles[i];
    const Triple& U = soup_.triangles[j];
    int s[3];
    for (int k = 0; k < 3; ++k) s[k] = sign_against(U, T[k]);
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      if (s[k] == 0) {  // vertex k of T lies in U's plane
        soup_.on[j].push_back(soup_.on[i][k]);
        // The line of an edge that leaves U's plane meets it at the vertex.
        if (s[l] != 0) add_rep(soup_.on[i][k], lpi_recipe(T[k], T[l], reordered(U, rng_)));
        continue;
      }
      if (s[k] * s[l] >= 0) continue;
      const Point a = T[k], b = T[l];
      const int id = point_id(lpi_recipe(a, b, reordered(U, rng_)));
      soup_.on[i].push_back(id);
      soup_.on[j].push_back(id);
      add_rep(id, lpi_recipe(b, a, reordered(U, rng_)));
      std::array<Triple, 3> planes = {reordered(U, rng_), reordered(T, rng_), reordered({a, b, any_point()}, rng_)};
      shuffle(planes.data(), 3, rng_);
      add_rep(id, tpi_recipe(planes));
      planes = {reordered(U, rng_), reordered({a, b, any_point()}, rng_), reordered({b, a, any_point()}, rng_)};
      shuffle(planes.data(), 3, rng_);
      add_rep(id, tpi_recipe(planes));
    }
  }

  Rng& rng_;
  bool grid_;
  Transform t_;
  Soup soup_;
};

// 4 to 6 triangles, 75% on the integer grid [-3, 3]^3, under a random exact transform.
inline Soup random_soup(Rng& rng) {
  const bool grid = rng.percent(75);
  const Transform t = random_transform(rng, grid);
  return SoupBuilder(rng, grid, t).build(rng.uniform(4, 6));
}
}  // namespace tritri_test
