// Specification of triangulate_polygon (arrangements/src/io/triangulate_polygon.h), checked
// exactly against an independent oracle (CGAL's exact-predicates kernel on the projection,
// rational areas from support/exact_oracle.h; nothing from the code under test):
//   1. always n - 2 triangles of the polygon's own corners;
//   2. when the projection along the normal's dominant axis is simple: the triangles
//      keep the polygon's orientation, meet only in shared corners and edges, and their
//      areas sum exactly to the polygon's area (so they tile it);
//   3. otherwise: the fan from the first corner.
// Generators: star-shaped polygons with integer radii (many collinear corners), combs,
// spirals, in the three axis planes and in tilted exact planes, scaled by 2^+-k and moved
// far from the origin; self-touching and self-crossing polygons; non-planar ones.
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "io/triangulate_polygon.h"
#include "support/exact_oracle.h"

namespace {

using namespace arrangements;
using K = tritri_test::InputKernel;
using P2 = K::Point_2;
using EK = tritri_test::ExactKernel;  // exact intersections
using tritri_test::exact;
using tritri_test::Q;

struct Polygon3 {
  std::vector<Vec3> V;
  std::vector<int> corners;
  int axis = 2;  // the axis the oracle projects along
};

P2 project(const Vec3& p, int axis) { return P2(p[(axis + 1) % 3], p[(axis + 2) % 3]); }

// Twice the signed area of the projection along the oracle's axis, exactly.
Q area2(const Polygon3& poly, const Vec3& a, const Vec3& b, const Vec3& c) {
  return tritri_test::area2(exact(a), exact(b), exact(c), poly.axis);
}

// Independent simplicity test: distinct positions, non-adjacent edges disjoint, adjacent
// edges meeting only in their common corner.
bool is_simple(const std::vector<P2>& p) {
  const std::size_t n = p.size();
  std::set<P2> distinct(p.begin(), p.end());
  if (distinct.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const K::Segment_2 a(p[i], p[(i + 1) % n]), b(p[j], p[(j + 1) % n]);
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent) {
        if (CGAL::do_intersect(a, b)) return false;
        continue;
      }
      // Adjacent: overlap iff the far corner of one lies on the other.
      const P2& common = j == i + 1 ? p[j] : p[i];
      const P2& far_a = j == i + 1 ? p[i] : p[(i + 1) % n];
      const P2& far_b = j == i + 1 ? p[(j + 1) % n] : p[j];
      if (CGAL::collinear(far_a, common, far_b) &&
          !CGAL::collinear_are_strictly_ordered_along_line(far_a, common, far_b))
        return false;
    }
  return true;
}

// "" if the triangles satisfy the specification for this polygon, else the problem.
std::string problem(const Polygon3& poly, const std::vector<Tri>& tris) {
  const std::size_t n = poly.corners.size();
  if (tris.size() != n - 2) return "wrong triangle count " + std::to_string(tris.size());
  std::set<int> own(poly.corners.begin(), poly.corners.end());
  for (const Tri& t : tris)
    for (int c : t)
      if (!own.count(c)) return "a triangle uses a vertex that is not a corner";
  std::vector<P2> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = project(poly.V[poly.corners[i]], poly.axis);
  if (!is_simple(p)) {
    for (std::size_t i = 1; i + 1 < n; ++i)
      if (tris[i - 1] != Tri{poly.corners[0], poly.corners[i], poly.corners[i + 1]}) return "not the fan";
    return "";
  }
  Q polygon_area = 0;
  for (std::size_t i = 0; i < n; ++i)
    polygon_area += area2(poly, Vec3{0, 0, 0}, poly.V[poly.corners[i]], poly.V[poly.corners[(i + 1) % n]]);
  std::vector<EK::Triangle_2> T;
  Q sum = 0;
  for (const Tri& t : tris) {
    const P2 a = project(poly.V[t[0]], poly.axis), b = project(poly.V[t[1]], poly.axis),
             c = project(poly.V[t[2]], poly.axis);
    const Q A = area2(poly, poly.V[t[0]], poly.V[t[1]], poly.V[t[2]]);
    if (sgn(A) != sgn(polygon_area)) return "a triangle is degenerate or oriented against the polygon";
    sum += A;
    auto e = [](const P2& q) { return EK::Point_2(q.x(), q.y()); };
    T.emplace_back(e(a), e(b), e(c));
  }
  if (sum != polygon_area) return "the areas do not sum to the polygon's area";
  // Areas add up and orientations agree; interiors must also be disjoint (else some part
  // of the polygon would be covered twice and another not at all).
  for (std::size_t i = 0; i < T.size(); ++i)
    for (std::size_t j = i + 1; j < T.size(); ++j) {
      if (!CGAL::do_intersect(T[i], T[j])) continue;
      const auto x = CGAL::intersection(T[i], T[j]);
      if (boost::get<EK::Triangle_2>(&*x) || boost::get<std::vector<EK::Point_2>>(&*x))
        return "triangles " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
    }
  return "";
}

// A polygon from 2D integer-ish corners, placed in a plane (`axis` constant, or tilted:
// the third coordinate an exact linear function), scaled by 2^k and offset.
Polygon3 place(const std::vector<std::array<double, 2>>& pts, int axis, bool tilted, int k, double offset) {
  Polygon3 poly;
  poly.axis = axis;
  for (const auto& q : pts) {
    Vec3 v;
    const double a = std::ldexp(q[0], k), b = std::ldexp(q[1], k);
    v[(axis + 1) % 3] = a + offset;
    v[(axis + 2) % 3] = b + offset;
    v[axis] = tilted ? std::ldexp(q[0] + q[1], k - 2) + offset : offset;  // slopes 1/4: axis stays dominant
    poly.corners.push_back(static_cast<int>(poly.V.size()));
    poly.V.push_back(v);
  }
  return poly;
}

std::vector<std::array<double, 2>> star(std::mt19937& rng, int n, int max_radius) {
  std::uniform_int_distribution<int> radius(1, max_radius);
  std::vector<std::array<double, 2>> pts;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n;
    const int r = radius(rng);
    pts.push_back({std::round(r * 64 * std::cos(angle)), std::round(r * 64 * std::sin(angle))});
  }
  return pts;
}

std::vector<std::array<double, 2>> comb(int teeth) {
  std::vector<std::array<double, 2>> pts = {{double(2 * teeth), -4}, {0, -4}};
  for (int i = 0; i < teeth; ++i) {
    pts.push_back({2.0 * i, 8});
    pts.push_back({2.0 * i + 1, 8});
    pts.push_back({2.0 * i + 1, 0});
    pts.push_back({2.0 * i + 2, 0});
  }
  return pts;
}

std::vector<std::array<double, 2>> spiral(int turns) {
  std::vector<std::array<double, 2>> out, in;
  for (int i = 0; i < 4 * turns; ++i) {
    const double r = 10 + 3 * i, angle = M_PI / 2 * i;
    out.push_back({std::round(r * std::cos(angle)), std::round(r * std::sin(angle))});
    in.push_back({std::round((r - 1.5) * std::cos(angle)), std::round((r - 1.5) * std::sin(angle))});
  }
  std::vector<std::array<double, 2>> pts(out.begin(), out.end());
  pts.insert(pts.end(), in.rbegin(), in.rend());
  return pts;
}

TEST(TriangulatePolygon, GeneratedPolygonsInAnyPlaneScaleAndOffsetAreTiledOrFanned) {
  std::mt19937 rng(7);
  int simple = 0, cases = 0;
  for (int rep = 0; rep < 40; ++rep) {
    std::vector<std::vector<std::array<double, 2>>> shapes = {
        star(rng, 4 + rep, 1 + rep % 4), star(rng, 3 + 3 * rep, 3), comb(1 + rep % 7), spiral(1 + rep % 4)};
    if (rep % 2) std::reverse(shapes[0].begin(), shapes[0].end());  // clockwise too
    for (const auto& shape : shapes)
      for (int axis = 0; axis < 3; ++axis)
        for (bool tilted : {false, true})
          for (int k : {-40, 0, 30})
            for (double offset : {0.0, 1e6, -1e15}) {
              const Polygon3 poly = place(shape, axis, tilted, k, offset);
              std::vector<Tri> tris;
              const bool certified = triangulate_polygon(poly.V, poly.corners, tris);
              const std::string p = problem(poly, tris);
              ASSERT_EQ(p, "") << "rep " << rep << " axis " << axis << " tilted " << tilted << " k " << k << " offset "
                               << offset << " n " << shape.size();
              std::vector<P2> q;
              for (int c : poly.corners) q.push_back(project(poly.V[c], axis));
              ASSERT_EQ(certified, shape.size() == 3 || is_simple(q));  // a triangle is always its own
              simple += is_simple(q);
              ++cases;
            }
  }
  EXPECT_GT(simple, cases / 3);  // the generators reach both branches
  EXPECT_LT(simple, cases);
}

TEST(TriangulatePolygon, SelfCrossingAndSelfTouchingPolygonsFallBackToTheFan) {
  const std::vector<std::vector<std::array<double, 2>>> shapes = {
      {{0, 0}, {2, 2}, {2, 0}, {0, 2}},                  // bow tie
      {{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}},          // a corner on another edge
      {{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}, {2, 2}},  // a repeated corner
      {{0, 0}, {4, 0}, {2, 0}, {2, 3}},                  // an edge folding back on the previous
  };
  for (const auto& shape : shapes) {
    const Polygon3 poly = place(shape, 2, false, 0, 0);
    std::vector<Tri> tris;
    EXPECT_FALSE(triangulate_polygon(poly.V, poly.corners, tris));
    ASSERT_EQ(tris.size(), shape.size() - 2);
    for (std::size_t i = 1; i + 1 < shape.size(); ++i) EXPECT_EQ(tris[i - 1], (Tri{0, int(i), int(i + 1)}));
  }
}

TEST(TriangulatePolygon, NonPlanarPolygonsWithASimpleProjectionAreLiftedFromIt) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> height(-0.25, 0.25);
  for (int rep = 0; rep < 50; ++rep) {
    Polygon3 poly = place(star(rng, 5 + rep, 2), 2, false, -6, 0);
    for (Vec3& v : poly.V) v[2] = height(rng);  // small against the extent: z stays non-dominant
    std::vector<Tri> tris;
    EXPECT_TRUE(triangulate_polygon(poly.V, poly.corners, tris));
    ASSERT_EQ(problem(poly, tris), "") << "rep " << rep;
  }
}

TEST(TriangulatePolygon, TrianglesAreAppendedUnchangedAndDegenerateCornersAreKept) {
  const std::vector<Vec3> V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  std::vector<Tri> out = {{9, 9, 9}};
  EXPECT_TRUE(triangulate_polygon(V, std::vector<int>{2, 0, 1}, out));
  EXPECT_EQ(out, (std::vector<Tri>{{9, 9, 9}, {2, 0, 1}}));
  out.clear();
  EXPECT_FALSE(triangulate_polygon(V, std::vector<int>{0, 1, 3, 1}, out));  // degenerate quad: the fan
  EXPECT_EQ(out, (std::vector<Tri>{{0, 1, 3}, {0, 3, 1}}));
}

}  // namespace
