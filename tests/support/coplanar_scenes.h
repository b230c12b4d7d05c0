// tests/support/coplanar_scenes.h
//
// The coplanar scenes of the stage 4 and 5 tests (test_share_coplanar, test_partner_covers)
// and the exact geometry their oracles locate points with, in one place:
//   snap, P2, turn        local coordinates (x, y, w) on the 2^-28 grid, the common plane
//                         w = 0; turn rotates and moves a point of the plane
//   Builder               a soup written vertex by vertex (label set 0, source = index)
//   rim, strip_fan, apex_fan, sheet, crossing, wall   the pieces of the scenes
//   strips, fans, two_sheets, three_sheets, contacts, t_junctions, shared_corners,
//   nested, lattice       the scenes the two tests share, each made by a Builder
//   Scene, SceneList      a named soup (`large` ones get fewer placements); a test's list
//                         of them, each given crossing triangles as it is added
//   Placement, place      w = 0 mapped exactly into one of five planes, moved by 2^20 and
//                         scaled by 2^k; for_each_exact_run, the ExactModel runs
//   Q, Q3, ZPoint         (from exact_oracle.h, for the users of the ones below)
//   Projection, EdgeLines the projection dropping the normal's largest axis and a
//                         triangle's edge lines there, rational and in integers
//   seconds_since         the timing of the summary lines
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/as_input.h"
#include "arrangements/triangle_soup.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "exact_oracle.h"
#include "test_scale.h"

namespace tritri_test::coplanar {

using namespace ::arrangements;
// The exact types of exact_oracle.h, which the oracles on these scenes are written in.
using ::tritri_test::Q;
using ::tritri_test::Q3;
using ::tritri_test::ZPoint;

// ---------------------------------------------------------------------------------------
// Scenes, in local coordinates (x, y, w): the common plane is w = 0. Every coordinate is
// a multiple of 2^-28 below 8 in magnitude, so that the plane maps, the offset by 2^20
// and the scalings by 2^k of place() are exact in doubles (coplanarity survives them).

inline constexpr int kGridBits = 28;
inline double snap(double v) { return std::ldexp(std::nearbyint(std::ldexp(v, kGridBits)), -kGridBits); }

using P2 = std::array<double, 2>;

struct Builder {
  TriangleSoup soup;
  Builder() { soup.label_sets = {{0}}; }
  int vertex(double x, double y, double w = 0) {
    soup.vertices.push_back({snap(x), snap(y), snap(w)});
    return static_cast<int>(soup.vertices.size()) - 1;
  }
  int vertex(const P2& p, double w = 0) { return vertex(p[0], p[1], w); }
  void triangle(int a, int b, int c) {
    soup.triangles.push_back({a, b, c});
    soup.label_set.push_back(0);
    soup.source.push_back(static_cast<std::int64_t>(soup.triangles.size()) - 1);
  }
  // Separate vertices for each triangle: preprocess merges equal positions into one id.
  // They are made c, b, a: the order in which g++ evaluated triangle(vertex(a), vertex(b),
  // vertex(c)) when the scenes were written (spelled out, so that no compiler changes it).
  void triangle(const P2& a, const P2& b, const P2& c) {
    const int ic = vertex(c), ib = vertex(b), ia = vertex(a);
    triangle(ia, ib, ic);
  }
};

// p turned by `degrees` about the origin, then moved by `shift`.
inline P2 turn(const P2& p, double degrees, const P2& shift) {
  const double r = degrees * std::numbers::pi / 180, c = std::cos(r), s = std::sin(r);
  return {c * p[0] - s * p[1] + shift[0], s * p[0] + c * p[1] + shift[1]};
}

// The corners of a regular n-gon of `radius` around `centre`, turned by `degrees`.
inline std::vector<P2> rim(const P2& centre, double radius, int n, double degrees) {
  std::vector<P2> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    out.push_back(turn({radius * std::cos(a), radius * std::sin(a)}, degrees, centre));
  }
  return out;
}

// A polygon's cap as a fan from its rim vertex 0 (QuickCSG's TwoCylinders): long thin
// triangles, each crossed by O(n) of another such fan's.
inline void strip_fan(Builder& b, const std::vector<P2>& r) {
  std::vector<int> id;
  for (const P2& p : r) id.push_back(b.vertex(p));
  for (std::size_t i = 1; i + 1 < r.size(); ++i) b.triangle(id[0], id[i + 1], id[i]);
}

// Where a fan's apex vertex stands among its vertices: each test wrote its fans one way,
// and the vertex ids of its scenes stay as they were.
enum class Apex { kFirst, kLast };

// A fan from `apex` to every rim edge.
inline void apex_fan(Builder& b, const P2& apex, const std::vector<P2>& r, Apex order) {
  const int first = order == Apex::kFirst ? b.vertex(apex) : -1;
  std::vector<int> id;
  for (const P2& p : r) id.push_back(b.vertex(p));
  const int a = order == Apex::kFirst ? first : b.vertex(apex);
  for (std::size_t i = 0; i < r.size(); ++i) b.triangle(a, id[i], id[(i + 1) % r.size()]);
}

// An m x m grid of side `side` centred at the origin, turned and moved; two triangles per
// cell, split along either diagonal.
inline void sheet(Builder& b, int m, double side, double degrees, const P2& shift, bool other_diagonal = false) {
  const int first = static_cast<int>(b.soup.vertices.size());
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) b.vertex(turn({-side / 2 + side * i / m, -side / 2 + side * j / m}, degrees, shift));
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int a = first + j * (m + 1) + i, c = a + m + 2, d = a + m + 1;
      if (other_diagonal) {
        b.triangle(a, a + 1, d);
        b.triangle(a + 1, c, d);
      } else {
        b.triangle(a, a + 1, c);
        b.triangle(a, c, d);
      }
    }
}

// A double in [0, 1) from the top 53 bits of one draw (platform independent, unlike the
// standard distributions).
inline double unit(std::mt19937_64& rng) { return std::ldexp(static_cast<double>(rng() >> 11), -53); }

// Triangles through the plane, so that coplanar triangles also hold points and segments
// of non-coplanar pairs: a generic one, one with an edge in the plane, one with a corner
// in it, and another generic one. corner() gives the (x, y) of each corner in turn: each
// test draws its own random numbers.
template <class Corner>
void crossing(Builder& b, Corner&& corner) {
  const double w[4][3] = {{-0.75, 0.5, 0.625}, {0, 0, 0.5}, {0, -0.5, 0.5}, {0.375, -0.25, -0.5}};
  for (const auto& ws : w) {
    int id[3];
    for (int k = 0; k < 3; ++k) id[k] = b.vertex(corner(), ws[k]);
    b.triangle(id[0], id[1], id[2]);
  }
}

// A vertical triangle over the segment (p, q): it cuts the plane along the middle half
// of (p, q), a constraint placed by hand. (Vertices made top first, as Builder::triangle.)
inline void wall(Builder& b, const P2& p, const P2& q) {
  const int top = b.vertex((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, 1), below_q = b.vertex(q[0], q[1], -1);
  b.triangle(b.vertex(p[0], p[1], -1), below_q, top);
}

// ---------------------------------------------------------------------------------------
// The scenes both tests build (each lists them under its own names).

// Strips: two caps of n-gons of radius 4, the second turned by 12 degrees and moved by
// (1.3125, 1.3125): long chains on the edges, many regions, many partners.
inline Builder strips(int n) {
  Builder b;
  strip_fan(b, rim({0, 0}, 4, n, 0));
  strip_fan(b, rim({1.3125, 1.3125}, 4, n, 12));
  return b;
}

// Fans of 24 placed as the strips, around their own centres (spokes cross) or around one
// shared apex (0.625, 0.625).
inline Builder fans(bool shared_apex, Apex order) {
  Builder b;
  const P2 o = {0, 0}, p = {1.3125, 1.3125}, shared = {0.625, 0.625};
  apex_fan(b, shared_apex ? shared : o, rim(o, 4, 24, 0), order);
  apex_fan(b, shared_apex ? shared : p, rim(p, 4, 24, 12), order);
  return b;
}

// Two 8 x 8 grids, the second turned by 12 degrees and moved by `shift` (the tests write
// it differently in the last bit; snapped, the scenes are what they were).
inline Builder two_sheets(const P2& shift) {
  Builder b;
  sheet(b, 8, 6, 0, {0, 0});
  sheet(b, 8, 6, 12, shift);
  return b;
}

// Three stacked 6 x 6 grids, turned and moved: overlaps of three.
inline Builder three_sheets() {
  Builder b;
  sheet(b, 6, 6, 0, {0, 0});
  sheet(b, 6, 6, 12, {0.3, 0.2});
  sheet(b, 6, 6, -7, {-0.2, 0.35}, true);
  return b;
}

// Degenerate contacts with t, the first triangle; with `edge_sharers`, four more that
// share t's bottom edge or its apex. Then constraints from the common part of the bottom
// edges into t, ending on either side.
inline Builder contacts(bool edge_sharers) {
  Builder b;
  b.triangle({0, 0}, {4, 0}, {2, 3});             // t
  b.triangle({1, 0}, {6, 0}, {3, 2});             // overlaps t, bottom edges collinear on [1, 4]
  b.triangle({-1, 0}, {2, 0}, {1, -2});           // touches t along [0, 2] only
  b.triangle({4, 0}, {5, -1}, {6, -0.5});         // shares t's corner (4, 0) only
  b.triangle({3, 1.5}, {5, 1.5}, {4, 3.5});       // a corner on t's right edge, else outside
  b.triangle({0.5, 0.75}, {1.5, 2.25}, {-1, 2});  // along t's left edge, outside t
  b.triangle({0.5, 0.75}, {1.5, 2.25}, {2, 1});   // along t's left edge, inside t
  if (edge_sharers) {
    b.triangle({0, 0}, {4, 0}, {2, -3});    // t's edge, outside
    b.triangle({0, 0}, {4, 0}, {2, 3.25});  // t's edge, contains t
    b.triangle({4, 0}, {0, 0}, {2.25, 3});  // t's edge, turned the other way
    b.triangle({2, 3}, {1, 4}, {3, 4});     // t's apex only
  }
  wall(b, {2.5, -2}, {2.5, 4});
  wall(b, {1.5, -2}, {3.5, 4});
  wall(b, {3.5, -2}, {1.5, 4});
  return b;
}

// T-junctions: each grid's corners on the other grids' edges.
inline Builder t_junctions() {
  Builder b;
  sheet(b, 6, 6, 0, {0, 0});
  sheet(b, 6, 6, 0, {0.5, 0});
  sheet(b, 6, 6, 0, {0.25, 0.5}, true);
  return b;
}

// The same corners split along both diagonals; coarser cells through them.
inline Builder shared_corners() {
  Builder b;
  sheet(b, 4, 4, 0, {0, 0});
  sheet(b, 4, 4, 0, {0, 0}, true);
  sheet(b, 2, 4, 0, {0, 0}, true);
  return b;
}

inline Builder nested() {
  Builder b;
  b.triangle({-4, -4}, {4, -4}, {0, 4});
  b.triangle({-1, -1}, {1, -1}, {0, 1});              // inside
  b.triangle({-0.5, -0.75}, {0.5, -0.75}, {0, 0.5});  // inside that one
  b.triangle({-1, -4}, {1, -4}, {0, -3});             // inside, an edge along the big one's
  b.triangle({0, -4}, {1, -2}, {-1, -2});             // inside, a corner on the big one's edge
  b.triangle({-1, -1}, {1, -1}, {0, -2});             // shares an edge with the second
  return b;
}

// 40 triangles with corners drawn on a coarse lattice (x before y, corner by corner):
// collinear edges, T-junctions, shared corners, both orientations. Vertices made in
// corner order, or c, b, a as Builder::triangle makes them (as each test wrote it).
inline Builder lattice(std::mt19937_64& rng, bool vertices_in_order) {
  Builder b;
  auto at = [&] { return P2{0.5 * static_cast<double>(rng() % 9) - 2, 0.5 * static_cast<double>(rng() % 9) - 2}; };
  for (int k = 0; k < 40; ++k) {
    const P2 p[3] = {at(), at(), at()};  // (a braced list: in order)
    if (!vertices_in_order) {
      b.triangle(p[0], p[1], p[2]);
      continue;
    }
    const int c0 = b.vertex(p[0]), c1 = b.vertex(p[1]), c2 = b.vertex(p[2]);
    b.triangle(c0, c1, c2);
  }
  return b;
}

struct Scene {
  std::string name;
  TriangleSoup soup;
  bool large = false;  // fewer placements, no exact run
};

// A test's scenes in the order it adds them. add() gives each one the crossing triangles,
// their corners drawn by corner(rng): each test draws its own random numbers (from rng,
// which its lattices share).
struct SceneList {
  std::mt19937_64 rng;
  P2 (*corner)(std::mt19937_64&);
  std::vector<Scene> scenes;

  void add(std::string name, Builder b, bool large = false) {
    crossing(b, [&] { return corner(rng); });
    scenes.push_back({std::move(name), std::move(b.soup), large});
  }
};

// ---------------------------------------------------------------------------------------
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

inline TriangleSoup place(TriangleSoup s, const Placement& p) {
  for (Vec3& v : s.vertices) {
    const double x = v[0], y = v[1], w = v[2];
    const Vec3 m = p.plane == 0 ? Vec3{x, y, w}
                   : p.plane == 1 ? Vec3{x, w, y}
                   : p.plane == 2 ? Vec3{w, x, y}
                   : p.plane == 3 ? Vec3{x, y, x + w}
                                  : Vec3{x, y, x + y + w};
    const Q3 want = p.plane == 3   ? Q3{Q(x), Q(y), Q(x) + Q(w)}
                    : p.plane == 4 ? Q3{Q(x), Q(y), Q(x) + Q(y) + Q(w)}
                                   : exact(m);
    const Q scale = p.k >= 0 ? Q(std::ldexp(1.0, p.k)) : Q(1) / Q(std::ldexp(1.0, -p.k));
    for (int c = 0; c < 3; ++c) {
      v[c] = std::ldexp(m[c] + (p.offset ? 0x1p20 : 0.0), p.k);
      // Exact, or the scene would not be coplanar any more.
      EXPECT_EQ(Q(v[c]), (want[c] + (p.offset ? Q(1 << 20) : Q(0))) * scale);
    }
  }
  return s;
}

// The ExactModel runs (slower than the double ones): every scene but the large ones, at
// z = 0 and at z = x + y moved and scaled by 2^-60 (z = 0 only in the sanitizer runs);
// run(what, input, soup) gets the placed double soup and its exact preprocess.
template <class Run>
void for_each_exact_run(const std::vector<Scene>& scenes, Run&& run) {
  for (const Scene& scene : scenes) {
    if (scene.large) continue;
    for (const Placement& p : {Placement{0, 0, false}, Placement{4, -60, true}}) {
      if (scaled_down() && p.plane != 0) continue;
      const TriangleSoup input = place(scene.soup, p);
      PreprocessStats stats;
      run(scene.name + ", " + p.name() + " (exact)", input,
          preprocess<ExactModel>(to_exact(input), PreprocessOptions{}, stats));
    }
  }
}

// ---------------------------------------------------------------------------------------
// Exact location in the projection (i, j) that drops the axis of the normal's largest
// component (the first of equal ones), where a non-degenerate triangle stays one.

struct Projection {
  int axis, i, j;
};

inline Projection projection_of(const Q3& a, const Q3& b, const Q3& c) {
  const Q3 n = normal(a, b, c);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (abs(n[k]) > abs(n[axis])) axis = k;
  return {axis, (axis + 1) % 3, (axis + 2) % 3};
}

// The edge lines of the triangle (A, B, C) in a projection, each >= 0 on the closed
// triangle's side: line e, through corners e and e + 1, is q[e] = (a, b, c) for
// a X_i + b X_j + c (rational), and z[e] the same times a positive integer (for points
// over a common denominator); orientation is the sign of the normal along the dropped
// axis.
struct EdgeLines {
  std::array<std::array<Q, 3>, 3> q;
  std::array<std::array<mpz_class, 3>, 3> z;
  int orientation = 0;

  // Line e at x, times a positive integer (x.den > 0): its sign is x's side.
  mpz_class at(int e, const ZPoint& x, const Projection& pr) const {
    return z[e][0] * x.num[pr.i] + z[e][1] * x.num[pr.j] + z[e][2] * x.den;
  }
};

inline EdgeLines edge_lines(const Q3& A, const Q3& B, const Q3& C, const Projection& pr) {
  EdgeLines L;
  L.orientation = sgn(normal(A, B, C)[pr.axis]);
  EXPECT_NE(L.orientation, 0) << "a triangle degenerate in the projection";
  const Q3* corner[3] = {&A, &B, &C};
  for (int e = 0; e < 3; ++e) {
    const Q3 &p = *corner[e], &q = *corner[(e + 1) % 3];
    // (q_i - p_i)(X_j - p_j) - (q_j - p_j)(X_i - p_i), times the orientation
    auto& h = L.q[e];
    h = {-(q[pr.j] - p[pr.j]) * L.orientation, (q[pr.i] - p[pr.i]) * L.orientation, 0};
    h[2] = -(h[0] * p[pr.i] + h[1] * p[pr.j]);
    mpz_class d = 1;
    for (const Q& x : h) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), x.get_den_mpz_t());
    for (int k = 0; k < 3; ++k) L.z[e][k] = h[k].get_num() * (d / h[k].get_den());
  }
  return L;
}

// ---------------------------------------------------------------------------------------
// The time of a scene's runs, for the summary lines.

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tritri_test::coplanar
