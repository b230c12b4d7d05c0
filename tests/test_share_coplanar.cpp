// share_coplanar (stages/4_share_coplanar.h), the step of the intersection graph where
// coplanar partners share their points and segments, against a brute force written here
// from the step's definition. For every triangle t with coplanar partners, every id a
// partner lists (its corners and segment ends; its points inside and on its edges, the
// "points") is located in closed t with integer line equations on the id's exact rational
// coordinates (nothing of the library's predicates); a point inside t or strictly inside
// an edge of t is added there, and a partner's segment with both ends in closed t (its
// interior, open edges or t's own corners) is added to t's segments, all from the lists
// as they were before (the semantics of the brute force that the step replaced).
// The graph before the step comes from build_intersection_graph(..., share = false); the
// result must equal the reference list by list, and the pipeline's graph (step inside).
// Inputs: coplanar scenes that make the fast path's binary searches and segment look-up
// work (fans of long thin triangles, fans, sheets, three stacked layers) and its
// degenerate cases (collinear overlapping edges, T-junctions, shared corners, touching,
// nesting, near-common points), with triangles crossing the plane, each placed in five
// planes, scaled by 2^k and moved (all exact in doubles); DoubleModel, and ExactModel on
// the smaller scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/as_input.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/4_share_coplanar.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using tritri_test::Q;
using tritri_test::Q3;
using tritri_test::ZPoint;

// ---------------------------------------------------------------------------------------
// Scenes, in local coordinates (x, y, w): the common plane is w = 0. Every coordinate is
// a multiple of 2^-28 below 8 in magnitude, so that the plane maps, the offset by 2^20
// and the scalings by 2^k of place() are exact in doubles (coplanarity survives them).

constexpr int kGridBits = 28;
double snap(double v) { return std::ldexp(std::nearbyint(std::ldexp(v, kGridBits)), -kGridBits); }

using P2 = std::array<double, 2>;

struct Builder {
  TriangleSoup soup;
  Builder() { soup.label_sets = {{0}}; }
  int vertex(double x, double y, double w = 0) {
    soup.vertices.push_back({snap(x), snap(y), snap(w)});
    return static_cast<int>(soup.vertices.size()) - 1;
  }
  int vertex(const P2& p) { return vertex(p[0], p[1]); }
  void triangle(int a, int b, int c) {
    soup.triangles.push_back({a, b, c});
    soup.label_set.push_back(0);
    soup.source.push_back(static_cast<std::int64_t>(soup.triangles.size()) - 1);
  }
  // Separate vertices for each triangle: preprocess merges equal positions into one id.
  void triangle(const P2& a, const P2& b, const P2& c) { triangle(vertex(a), vertex(b), vertex(c)); }
};

P2 turn(const P2& p, double degrees, const P2& shift) {
  const double r = degrees * std::numbers::pi / 180, c = std::cos(r), s = std::sin(r);
  return {c * p[0] - s * p[1] + shift[0], s * p[0] + c * p[1] + shift[1]};
}

std::vector<P2> rim(const P2& centre, double radius, int n, double degrees) {
  std::vector<P2> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    out.push_back(turn({radius * std::cos(a), radius * std::sin(a)}, degrees, centre));
  }
  return out;
}

// A polygon's cap as a fan from its rim vertex 0 (QuickCSG's TwoCylinders): long thin
// triangles, each crossed by O(n) of the other fan's.
void strip_fan(Builder& b, const std::vector<P2>& r) {
  std::vector<int> id;
  for (const P2& p : r) id.push_back(b.vertex(p));
  for (std::size_t i = 1; i + 1 < r.size(); ++i) b.triangle(id[0], id[i + 1], id[i]);
}

void apex_fan(Builder& b, const P2& apex, const std::vector<P2>& r) {
  const int a = b.vertex(apex);
  std::vector<int> id;
  for (const P2& p : r) id.push_back(b.vertex(p));
  for (std::size_t i = 0; i < r.size(); ++i) b.triangle(a, id[i], id[(i + 1) % r.size()]);
}

// An m x m grid of side `side` centred at the origin, turned and moved; two triangles per
// cell, split along either diagonal.
void sheet(Builder& b, int m, double side, double degrees, const P2& shift, bool other_diagonal = false) {
  const int first = static_cast<int>(b.soup.vertices.size());
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) b.vertex(turn({-side / 2 + side * i / m, -side / 2 + side * j / m}, degrees, shift));
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int a = first + j * (m + 1) + i, c = a + m + 2;
      if (other_diagonal) {
        b.triangle(a, a + 1, a + m + 1);
        b.triangle(a + 1, c, a + m + 1);
      } else {
        b.triangle(a, a + 1, c);
        b.triangle(a, c, a + m + 1);
      }
    }
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * std::ldexp(static_cast<double>(rng() >> 11), -53);  // (platform independent)
}

// Triangles through the plane, so that coplanar triangles also hold points and segments
// of non-coplanar pairs: a generic one, one with an edge in the plane, one with a corner
// in it, and another generic one.
void crossing(Builder& b, std::mt19937_64& rng, double half) {
  const double w[4][3] = {{-0.75, 0.5, 0.625}, {0, 0, 0.5}, {0, -0.5, 0.5}, {0.375, -0.25, -0.5}};
  for (const auto& ws : w) {
    int id[3];
    for (int k = 0; k < 3; ++k) id[k] = b.vertex(uniform(rng, -half, half), uniform(rng, -half, half), ws[k]);
    b.triangle(id[0], id[1], id[2]);
  }
}

// A vertical triangle over the segment (p, q): it cuts the plane along the middle half
// of (p, q), a constraint placed by hand.
void wall(Builder& b, const P2& p, const P2& q) {
  b.triangle(b.vertex(p[0], p[1], -1), b.vertex(q[0], q[1], -1), b.vertex((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, 1));
}

struct Scene {
  std::string name;
  TriangleSoup soup;
  bool large = false;  // fewer placements
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  std::mt19937_64 rng(tritri_test::seed_for(4417));
  auto add = [&](const std::string& name, Builder& b, bool large = false) {
    crossing(b, rng, 2.5);
    out.push_back({name, std::move(b.soup), large});
  };
  // 1. Strips: two rim fans, the second turned by 12 degrees and moved.
  for (int n : {10, 30, 60}) {
    if (n == 60 && tritri_test::scaled_down()) continue;
    Builder b;
    strip_fan(b, rim({0, 0}, 4, n, 0));
    strip_fan(b, rim({1.3125, 1.3125}, 4, n, 12));
    add("strips n=" + std::to_string(n), b, n == 60);
  }
  // 2. Fans around their own centres (spokes cross) and around one shared apex.
  {
    Builder b;
    apex_fan(b, {0, 0}, rim({0, 0}, 4, 24, 0));
    apex_fan(b, {1.3125, 1.3125}, rim({1.3125, 1.3125}, 4, 24, 12));
    add("fans, own apexes", b);
    Builder c;
    apex_fan(c, {0.625, 0.625}, rim({0, 0}, 4, 24, 0));
    apex_fan(c, {0.625, 0.625}, rim({1.3125, 1.3125}, 4, 24, 12));
    add("fans, shared apex", c);
  }
  // 3. Sheets: two grids, one turned and moved; three stacked layers (three-way overlaps).
  {
    Builder b;
    sheet(b, 8, 6, 0, {0, 0});
    sheet(b, 8, 6, 12, {0.37 * 0.75, 0.21 * 0.75});
    add("sheets", b, true);
    Builder c;
    sheet(c, 6, 6, 0, {0, 0});
    sheet(c, 6, 6, 12, {0.3, 0.2});
    sheet(c, 6, 6, -7, {-0.2, 0.35}, true);
    add("three layers", c, true);
  }
  // 4. Degenerate contacts.
  {
    Builder b;
    b.triangle({0, 0}, {4, 0}, {2, 3});           // t
    b.triangle({1, 0}, {6, 0}, {3, 2});           // overlaps t, bottom edges collinear on [1, 4]
    b.triangle({-1, 0}, {2, 0}, {1, -2});         // touches t along [0, 2] only
    b.triangle({4, 0}, {5, -1}, {6, -0.5});       // shares t's corner (4, 0) only
    b.triangle({3, 1.5}, {5, 1.5}, {4, 3.5});     // a corner on t's right edge, else outside
    b.triangle({0.5, 0.75}, {1.5, 2.25}, {-1, 2});  // along t's left edge, outside t
    b.triangle({0.5, 0.75}, {1.5, 2.25}, {2, 1});   // along t's left edge, inside t
    // Constraints from the common part of the bottom edges into t, ending on either side.
    wall(b, {2.5, -2}, {2.5, 4});
    wall(b, {1.5, -2}, {3.5, 4});
    wall(b, {3.5, -2}, {1.5, 4});
    add("collinear edges, touching", b);
  }
  {
    Builder b;  // T-junctions: the second grid's corners on the first's edges
    sheet(b, 6, 6, 0, {0, 0});
    sheet(b, 6, 6, 0, {0.5, 0});
    sheet(b, 6, 6, 0, {0.25, 0.5}, true);
    add("T-junctions", b, true);
  }
  {
    Builder b;  // the same corners split along the other diagonal; coarser cells through them
    sheet(b, 4, 4, 0, {0, 0});
    sheet(b, 4, 4, 0, {0, 0}, true);
    sheet(b, 2, 4, 0, {0, 0}, true);
    b.triangle({-2, -2}, {-1, -2}, {-1, -1});  // identical to a triangle of the first grid
    add("shared corners", b);
  }
  {
    Builder b;
    b.triangle({-4, -4}, {4, -4}, {0, 4});
    b.triangle({-1, -1}, {1, -1}, {0, 1});          // inside
    b.triangle({-0.5, -0.75}, {0.5, -0.75}, {0, 0.5});  // inside that one
    b.triangle({-1, -4}, {1, -4}, {0, -3});         // inside, an edge along the big one's
    b.triangle({0, -4}, {1, -2}, {-1, -2});         // inside, a corner on the big one's edge
    b.triangle({-1, -1}, {1, -1}, {0, -2});         // shares an edge with the second
    add("nested", b);
  }
  {
    Builder b;  // 10 thin wedges whose edges nearly meet in two points (write_wedges)
    const int n = 10;
    for (int i = 0; i < n; ++i) {
      const double y = -1 + 2 * (i + 0.5) / n, d = 0.5 / n;
      b.triangle({-1, y}, {1, -y + d}, {1, -y - d});
    }
    add("wedges", b);
  }
  for (int s = 0; s < 2; ++s) {
    Builder b;  // corners on a coarse lattice: collinear edges, T-junctions, shared corners
    for (int k = 0; k < 40; ++k) {
      P2 p[3];
      for (P2& q : p) q = {0.5 * static_cast<double>(rng() % 9) - 2, 0.5 * static_cast<double>(rng() % 9) - 2};
      b.triangle(p[0], p[1], p[2]);
    }
    add("lattice " + std::to_string(s), b, true);
  }
  return out;
}

// Placement: the plane w = 0 mapped to z = 0, y = 0, x = 0, z = x or z = x + y, moved by
// 2^20 along (1, 1, 1) or not, then scaled by 2^k.
struct Placement {
  int plane;
  int k;
  bool offset;
  std::string name() const {
    static const char* planes[] = {"z=0", "y=0", "x=0", "z=x", "z=x+y"};
    return std::string(planes[plane]) + " 2^" + std::to_string(k) + (offset ? " +2^20" : "");
  }
};

TriangleSoup place(TriangleSoup s, const Placement& p) {
  for (Vec3& v : s.vertices) {
    const double x = v[0], y = v[1], w = v[2];
    const Vec3 m = p.plane == 0 ? Vec3{x, y, w}
                   : p.plane == 1 ? Vec3{x, w, y}
                   : p.plane == 2 ? Vec3{w, x, y}
                   : p.plane == 3 ? Vec3{x, y, x + w}
                                  : Vec3{x, y, x + y + w};
    const Q3 want = p.plane == 3   ? Q3{Q(x), Q(y), Q(x) + Q(w)}
                    : p.plane == 4 ? Q3{Q(x), Q(y), Q(x) + Q(y) + Q(w)}
                                   : tritri_test::exact(m);
    const Q scale = p.k >= 0 ? Q(std::ldexp(1.0, p.k)) : Q(1) / Q(std::ldexp(1.0, -p.k));
    for (int c = 0; c < 3; ++c) {
      v[c] = std::ldexp(m[c] + (p.offset ? 0x1p20 : 0.0), p.k);
      // Exact, or the scene would not be coplanar any more.
      EXPECT_EQ(Q(v[c]), (want[c] + (p.offset ? Q(1 << 20) : Q(0))) * scale);
    }
  }
  return s;
}

// z = 0 first, then every plane at every scale, moved or not in turn; large scenes (and
// all in the sanitizer runs) one scale per plane.
std::vector<Placement> placements(std::size_t scene, bool large) {
  std::vector<Placement> out = {{0, 0, false}};
  if (tritri_test::scaled_down() && large) return out;
  const int ks[3] = {-60, 0, 40};
  for (int plane = 0; plane < 5; ++plane)
    for (int i = 0; i < 3; ++i) {
      const std::size_t turn = static_cast<std::size_t>(plane + i) + scene;
      if ((large || tritri_test::scaled_down()) && static_cast<std::size_t>(i) != (plane + scene) % 3) continue;
      if (plane == 0 && ks[i] == 0 && turn % 2 == 0) continue;  // the first one
      out.push_back({plane, ks[i], turn % 2 == 1});
    }
  return out;
}

// ---------------------------------------------------------------------------------------
// The reference.

// Closed triangle (A, B, C) in exact integers: in the projection dropping the axis of the
// normal's largest component (where the triangle is not degenerate), side k of a point X
// (over its common denominator D) is the sign of a_k X_i + b_k X_j + c_k D, positive inside
// (orient2d of edge k = (corner k, corner k + 1) and X, times the triangle's orientation).
struct ExactTriangle {
  static constexpr int kOutside = -1, kCorner = 4, kInterior = 3;  // else: strictly inside edge k
  int i = 0, j = 0;
  std::array<std::array<mpz_class, 3>, 3> line;

  ExactTriangle(const Q3& A, const Q3& B, const Q3& C) {
    const Q3 n = tritri_test::normal(A, B, C);
    int axis = 0;
    for (int c = 1; c < 3; ++c)
      if (abs(n[c]) > abs(n[axis])) axis = c;
    i = (axis + 1) % 3;
    j = (axis + 2) % 3;
    const int orientation = sgn(n[axis]);
    EXPECT_NE(orientation, 0) << "a degenerate triangle after preprocess";
    const Q3* corner[3] = {&A, &B, &C};
    for (int k = 0; k < 3; ++k) {
      const Q3 &p = *corner[k], &q = *corner[(k + 1) % 3];
      // (q_i - p_i)(X_j - p_j) - (q_j - p_j)(X_i - p_i) = a X_i + b X_j + c
      Q coef[3];
      coef[0] = -(q[j] - p[j]);
      coef[1] = q[i] - p[i];
      coef[2] = -(coef[0] * p[i] + coef[1] * p[j]);
      mpz_class d = 1;
      for (const Q& c : coef) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), c.get_den_mpz_t());
      for (int c = 0; c < 3; ++c) line[k][c] = orientation * coef[c].get_num() * (d / coef[c].get_den());
    }
  }

  int locate(const ZPoint& x) const {
    int zeros = 0, zero = -1;
    for (int k = 0; k < 3; ++k) {
      const mpz_class v = line[k][0] * x.num[i] + line[k][1] * x.num[j] + line[k][2] * x.den;
      const int s = sgn(v);
      if (s < 0) return kOutside;
      if (s == 0) ++zeros, zero = k;
    }
    return zeros == 0 ? kInterior : zeros == 1 ? zero : kCorner;
  }
};

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <class Point>
void reference_share(const std::vector<Tri>& F, BasicIntersectionGraph<Point>& g) {
  std::vector<Q3> q;
  std::vector<ZPoint> z;
  for (const Point& p : g.points) {
    q.push_back(tritri_test::exact(p));
    z.push_back(tritri_test::common_denominator(q.back()));
  }
  std::vector<std::vector<int>> inside(F.size());
  std::vector<std::array<int, 2>> on_edge;  // (edge, point)
  std::vector<std::vector<std::array<int, 2>>> segments(F.size());
  std::vector<int> stamp(g.points.size(), -1), where(g.points.size());
  std::vector<char> is_point(g.points.size());
  std::vector<int> ids;
  for (std::size_t t = 0; t < F.size(); ++t) {
    const auto& partners = g.coplanar_partners[t];
    if (partners.empty()) continue;
    const ExactTriangle tri(q[F[t][0]], q[F[t][1]], q[F[t][2]]);
    ids.clear();
    auto visit = [&](int x, bool point) {
      if (stamp[x] != static_cast<int>(t)) {
        stamp[x] = static_cast<int>(t);
        is_point[x] = 0;
        ids.push_back(x);
      }
      if (point) is_point[x] = 1;
    };
    for (int u : partners) {
      for (int k = 0; k < 3; ++k) {
        // The location is in t's plane: a partner must lie in it.
        EXPECT_EQ(tritri_test::orient3d(z[F[t][0]], z[F[t][1]], z[F[t][2]], z[F[u][k]]), 0) << t << ", " << u;
        visit(F[u][k], false);
      }
      for (int x : g.triangle_points[u]) visit(x, true);
      for (int k = 0; k < 3; ++k)
        for (int x : g.edge_points[g.triangle_edges[u][k]]) visit(x, true);
      for (const auto& s : g.triangle_segments[u]) visit(s[0], false), visit(s[1], false);
    }
    for (int k = 0; k < 3; ++k) {  // edge k of t runs from corner k to corner k + 1
      const auto& e = g.edges[g.triangle_edges[t][k]];
      EXPECT_EQ(e, (std::array<int, 2>{std::min(F[t][k], F[t][(k + 1) % 3]), std::max(F[t][k], F[t][(k + 1) % 3])}));
    }
    for (int x : ids) {
      // At a corner of t: in closed t when it is that corner (for the segments; t's
      // corners are not points to add); another id there would be a duplicate point.
      where[x] = tri.locate(z[x]);
      if (where[x] == ExactTriangle::kCorner) {
        EXPECT_TRUE(x == F[t][0] || x == F[t][1] || x == F[t][2]) << "point " << x << " at a corner of " << t;
        if (x != F[t][0] && x != F[t][1] && x != F[t][2]) where[x] = ExactTriangle::kOutside;
      }
      if (!is_point[x]) continue;
      if (where[x] == ExactTriangle::kInterior) inside[t].push_back(x);
      else if (where[x] >= 0 && where[x] < 3) on_edge.push_back({g.triangle_edges[t][where[x]], x});
    }
    for (int u : partners)
      for (const auto& s : g.triangle_segments[u])
        if (where[s[0]] != ExactTriangle::kOutside && where[s[1]] != ExactTriangle::kOutside)
          segments[t].push_back(s);
  }
  for (std::size_t t = 0; t < F.size(); ++t) {
    g.triangle_points[t].insert(g.triangle_points[t].end(), inside[t].begin(), inside[t].end());
    sort_unique(g.triangle_points[t]);
    g.triangle_segments[t].insert(g.triangle_segments[t].end(), segments[t].begin(), segments[t].end());
    sort_unique(g.triangle_segments[t]);
  }
  for (const auto& [e, x] : on_edge) g.edge_points[e].push_back(x);
  for (auto& list : g.edge_points) sort_unique(list);
}

// ---------------------------------------------------------------------------------------
// Comparison.

std::string str(int x) { return std::to_string(x); }
std::string str(const std::array<int, 2>& s) { return "(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ")"; }

// Lists equal index by index; the first difference is reported with its index, both sizes
// and one entry that only one side has.
template <class T, class Label>
void same_lists(const std::vector<std::vector<T>>& got, const std::vector<std::vector<T>>& want, const char* name,
                const Label& label, const std::string& what) {
  if (got.size() != want.size()) {
    ADD_FAILURE() << what << ": " << got.size() << " " << name << " lists, expected " << want.size();
    return;
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    std::vector<T> extra, missing;
    std::set_difference(got[i].begin(), got[i].end(), want[i].begin(), want[i].end(), std::back_inserter(extra));
    std::set_difference(want[i].begin(), want[i].end(), got[i].begin(), got[i].end(), std::back_inserter(missing));
    ADD_FAILURE() << what << ": " << name << "[" << i << "]" << label(i) << " has " << got[i].size()
                  << " entries, expected " << want[i].size()
                  << (extra.empty() ? "" : "; extra " + str(extra[0]))
                  << (missing.empty() ? "" : "; missing " + str(missing[0]))
                  << (extra.empty() && missing.empty() ? "; not sorted and unique" : "");
    return;
  }
}

template <class Point>
void expect_same_graph(const BasicIntersectionGraph<Point>& got, const BasicIntersectionGraph<Point>& want,
                       const std::string& what) {
  auto none = [](std::size_t) { return std::string(); };
  auto edge = [&](std::size_t e) { return " (edge " + str(want.edges[e]) + ")"; };
  same_lists(got.triangle_points, want.triangle_points, "triangle_points", none, what);
  same_lists(got.edge_points, want.edge_points, "edge_points", edge, what);
  same_lists(got.triangle_segments, want.triangle_segments, "triangle_segments", none, what);
  EXPECT_EQ(got.points.size(), want.points.size()) << what;
  EXPECT_EQ(got.coplanar_partners, want.coplanar_partners) << what;
}

struct Counts {
  std::size_t coplanar_pairs = 0, inside = 0, on_edge = 0, segments = 0;
  std::size_t added() const { return inside + on_edge + segments; }
};

std::string str(const Counts& c) {
  return std::to_string(c.coplanar_pairs) + " coplanar pairs, added " + std::to_string(c.inside) + " inside, " +
         std::to_string(c.on_edge) + " on edges, " + std::to_string(c.segments) + " segments";
}

template <class Point>
std::size_t total(const std::vector<std::vector<Point>>& lists) {
  std::size_t n = 0;
  for (const auto& l : lists) n += l.size();
  return n;
}

// The step against the reference and against the pipeline's graph; the additions counted.
template <class M>
Counts check_share(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F, const PairRecords& records,
                   const std::string& what) {
  const auto before = build_intersection_graph<M>(V, F, records, false);
  auto got = before;
  share_coplanar<M>(V, F, got);
  auto want = before;
  reference_share(F, want);
  expect_same_graph(got, want, what + ": share_coplanar against the reference");
  expect_same_graph(got, build_intersection_graph<M>(V, F, records), what + ": share_coplanar against the pipeline");
  return {before.coplanar_pairs, total(want.triangle_points) - total(before.triangle_points),
          total(want.edge_points) - total(before.edge_points),
          total(want.triangle_segments) - total(before.triangle_segments)};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Every fourth record dropped: a graph as valid for the step as a full one (each
// triangle's lists are consistent), where t misses points that its partners hold on t's
// edges. With every pair classified t's own pairs find those, so only here do the edge
// additions have work.
PairRecords thinned(const PairRecords& records) {
  PairRecordChunk kept;
  std::size_t i = 0;
  for (const PairIntersection& r : records)
    if (i++ % 4 != 1) kept.push_back(r);
  return PairRecords(std::vector<PairRecordChunk>{kept});
}

// The step on all records and on thinned ones.
template <class M>
std::array<Counts, 2> check_both(const std::vector<typename M::Vertex>& V, const std::vector<Tri>& F,
                                 const PairRecords& records, const std::string& what) {
  return {check_share<M>(V, F, records, what), check_share<M>(V, F, thinned(records), what + " (thinned)")};
}

std::array<Counts, 2> run_double(const TriangleSoup& input, Classifier classifier, const std::string& what) {
  PreprocessStats stats;
  const TriangleSoup soup = preprocess(input, PreprocessOptions{}, stats);
  const auto& V = soup.vertices;
  const auto& F = soup.triangles;
  return check_both<DoubleModel>(V, F, classify_pairs(V, F, candidate_pairs(V, F), classifier), what);
}

TEST(ShareCoplanar, DoubleModelMatchesBruteForce) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> all = scenes();
  std::array<Counts, 2> sum;
  std::size_t runs = 0;
  for (std::size_t s = 0; s < all.size(); ++s) {
    const Scene& scene = all[s];
    const auto scene_start = std::chrono::steady_clock::now();
    std::array<Counts, 2> first;
    const std::vector<Placement> where = placements(s, scene.large);
    for (std::size_t p = 0; p < where.size(); ++p) {
      const std::string what = scene.name + ", " + where[p].name();
      // Both classifiers (their records should make the same graph).
      const auto c = run_double(place(scene.soup, where[p]), p % 2 == 0 ? Classifier::Native : Classifier::Tritri, what);
      ++runs;
      for (int h = 0; h < 2; ++h)
        sum[h].coplanar_pairs += c[h].coplanar_pairs, sum[h].inside += c[h].inside, sum[h].on_edge += c[h].on_edge,
            sum[h].segments += c[h].segments;
      if (p == 0) {
        first = c;
        // Not vacuous: coplanar pairs, and something to share.
        EXPECT_GT(c[0].coplanar_pairs, 0u) << what;
        EXPECT_GT(c[0].added(), 0u) << what;
      } else {
        // Exact maps of the plane change no incidence, so neither what is shared.
        EXPECT_EQ(str(c[0]), str(first[0])) << what;
        EXPECT_EQ(str(c[1]), str(first[1])) << what << " (thinned)";
      }
    }
    std::printf("%-25s %s; thinned: %s; %zu placements, %.2f s\n", scene.name.c_str(), str(first[0]).c_str(),
                str(first[1]).c_str(), where.size(), seconds_since(scene_start));
  }
  std::printf("%zu scenes, %zu placements; all records: %s; thinned: %s; %.2f s\n", all.size(), runs,
              str(sum[0]).c_str(), str(sum[1]).c_str(), seconds_since(start));
  // Every kind of addition happened somewhere.
  EXPECT_GT(sum[0].inside, 0u);
  EXPECT_GT(sum[0].segments, 0u);
  EXPECT_GT(sum[1].on_edge, 0u);
}

// The exact path on the scenes without the large ones: z = 0, and z = x + y moved and
// scaled by 2^-60. Its additions are those of the double path (the same geometry).
TEST(ShareCoplanar, ExactModelMatchesBruteForce) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> all = scenes();
  std::size_t runs = 0;
  for (std::size_t s = 0; s < all.size(); ++s) {
    if (all[s].large) continue;
    for (const Placement& p : {Placement{0, 0, false}, Placement{4, -60, true}}) {
      if (tritri_test::scaled_down() && p.plane != 0) continue;
      const std::string what = all[s].name + ", " + p.name() + " (exact)";
      const TriangleSoup input = place(all[s].soup, p);
      PreprocessStats stats;
      const auto soup = preprocess<ExactModel>(to_exact(input), PreprocessOptions{}, stats);
      const auto& V = soup.vertices;
      const auto& F = soup.triangles;
      const auto pairs = detect_pairs<ExactModel>(V, F, 0).pairs;
      const auto c = check_both<ExactModel>(V, F, classify_pairs<ExactModel>(V, F, pairs, Classifier::Native), what);
      ++runs;
      EXPECT_GT(c[0].added(), 0u) << what;
      const auto d = run_double(input, Classifier::Native, what);
      EXPECT_EQ(str(c[0]), str(d[0])) << what;
      EXPECT_EQ(str(c[1]), str(d[1])) << what << " (thinned)";
    }
  }
  EXPECT_GT(runs, 0u);
  std::printf("%zu exact placements; %.2f s\n", runs, seconds_since(start));
}

}  // namespace
