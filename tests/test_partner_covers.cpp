// Stage 5's coplanar covers (split_triangle_of, stages/5_triangulate_triangle.h) against an
// exact oracle written from the rule. For each triangle t with coplanar partners and each
// local triangle it emits, S = the partners whose closed triangle holds its centroid (and
// "all corners in closed q" must agree: no local triangle straddles a partner's boundary):
// emitted only if S is empty or min(S) > t; covered_by -1 iff S is empty, else
// covers[covered_by] == {t} + S ascending. Per t also: positive area in t's orientation,
// corners in closed t, no directed edge twice, emitted area == area of t minus its partners
// q < t (rational clipping), emitted count == local Euler count iff nothing was skipped;
// partner lists against a brute force. All exact (integer line equations on rational
// coordinates in the projection dropping the normal's largest axis, behind a double filter
// with a proved bound); none of the library's predicates. Scenes: coplanar fans of long thin
// triangles (flood fill, binary-searched seeds), fans, stacked turned sheets (covers of 2+
// partners), degenerate contacts, with crossing triangles, placed exactly in five planes,
// scaled by 2^k, moved by 2^20 (as in test_share_coplanar.cpp); DoubleModel, and ExactModel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "arrangements/as_input.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate_triangle.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using tritri_test::Q;
using tritri_test::Q3;
using tritri_test::ZPoint;

// Scenes in local coordinates (x, y, w), the common plane w = 0; every coordinate a
// multiple of 2^-28 below 8 in magnitude, so that place() is exact in doubles.
double snap(double v) { return std::ldexp(std::nearbyint(std::ldexp(v, 28)), -28); }
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
  void triangle(const P2& a, const P2& b, const P2& c) { triangle(vertex(a), vertex(b), vertex(c)); }
};

P2 turn(const P2& p, double degrees, const P2& shift) {
  const double r = degrees * std::numbers::pi / 180, c = std::cos(r), s = std::sin(r);
  return {c * p[0] - s * p[1] + shift[0], s * p[0] + c * p[1] + shift[1]};
}

// A fan over a regular n-gon of radius 4 around `centre`, turned: from an apex, or without
// one from the n-gon's vertex 0 (a polygon's cap: long thin triangles, each crossed by O(n)
// of another such fan's: long chains on its edges, many regions, many partners).
void fan(Builder& b, const P2& centre, int n, double degrees, const P2* apex = nullptr) {
  std::vector<int> id;
  for (double i = 0; i < n; ++i)
    id.push_back(b.vertex(turn({4 * std::cos(2 * std::numbers::pi * i / n), 4 * std::sin(2 * std::numbers::pi * i / n)},
                               degrees, centre)));
  const int a = apex ? b.vertex(*apex) : -1;
  for (int i = apex ? 0 : 1; i < (apex ? n : n - 1); ++i)
    apex ? b.triangle(a, id[i], id[(i + 1) % n]) : b.triangle(id[0], id[i + 1], id[i]);
}

// An m x m grid of side `side`, turned and moved; two triangles per cell.
void sheet(Builder& b, int m, double side, double degrees, const P2& shift, bool other_diagonal = false) {
  const int first = static_cast<int>(b.soup.vertices.size());
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) b.vertex(turn({-side / 2 + side * i / m, -side / 2 + side * j / m}, degrees, shift));
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int a = first + j * (m + 1) + i, c = a + m + 2, d = a + m + 1;
      other_diagonal ? (b.triangle(a, a + 1, d), b.triangle(a + 1, c, d))
                     : (b.triangle(a, a + 1, c), b.triangle(a, c, d));
    }
}

// Triangles through the plane (points and segments of non-coplanar pairs in the coplanar
// ones): generic, an edge in the plane, a corner in it, generic.
void crossing(Builder& b, std::mt19937_64& rng, double half) {
  const double w[4][3] = {{-0.75, 0.5, 0.625}, {0, 0, 0.5}, {0, -0.5, 0.5}, {0.375, -0.25, -0.5}};
  auto uniform = [&] { return half * (2 * std::ldexp(static_cast<double>(rng() >> 11), -53) - 1); };
  for (const auto& ws : w) {
    int id[3];
    for (int k = 0; k < 3; ++k) id[k] = b.vertex(P2{uniform(), uniform()}, ws[k]);  // (a braced list: in order)
    b.triangle(id[0], id[1], id[2]);
  }
}

// A vertical triangle over (p, q): it cuts the plane along the middle half of (p, q).
void wall(Builder& b, const P2& p, const P2& q) {
  b.triangle(b.vertex(p[0], p[1], -1), b.vertex(q[0], q[1], -1), b.vertex((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, 1));
}

struct Scene {
  std::string name;
  TriangleSoup soup;
  bool large;  // fewer placements, no exact run
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  std::mt19937_64 rng(tritri_test::seed_for(5113));
  auto add = [&](const std::string& name, Builder& b, bool large = false) {
    crossing(b, rng, 2.5);
    out.push_back({name, std::move(b.soup), large});
  };
  for (int n : {20, 40, 80}) {
    Builder b;
    fan(b, {0, 0}, n, 0), fan(b, {1.3125, 1.3125}, n, 12);
    add("strips n=" + std::to_string(n), b, n > 20);
    if (n == 80 && tritri_test::scaled_down()) out.pop_back();  // (after add: the same random numbers)
  }
  Builder fans, apex, sheets, layers, contacts, tj, corners, nested;
  const P2 o = {0, 0}, p = {1.3125, 1.3125}, shared = {0.625, 0.625};
  fan(fans, o, 24, 0, &o), fan(fans, p, 24, 12, &p);
  add("fans, own apexes", fans);
  fan(apex, o, 24, 0, &shared), fan(apex, p, 24, 12, &shared);
  add("fans, shared apex", apex);
  sheet(sheets, 8, 6, 0, {0, 0}), sheet(sheets, 8, 6, 12, {0.2775, 0.1575});
  add("two sheets", sheets, true);
  sheet(layers, 6, 6, 0, {0, 0}), sheet(layers, 6, 6, 12, {0.3, 0.2}), sheet(layers, 6, 6, -7, {-0.2, 0.35}, true);
  add("three sheets", layers, true);
  // Contacts with t, the first triangle.
  contacts.triangle({0, 0}, {4, 0}, {2, 3});             // t
  contacts.triangle({1, 0}, {6, 0}, {3, 2});             // bottom edges collinear on [1, 4]
  contacts.triangle({-1, 0}, {2, 0}, {1, -2});           // touches t along [0, 2] only
  contacts.triangle({4, 0}, {5, -1}, {6, -0.5});         // t's corner only
  contacts.triangle({3, 1.5}, {5, 1.5}, {4, 3.5});       // a corner on t's right edge, else outside
  contacts.triangle({0.5, 0.75}, {1.5, 2.25}, {-1, 2});  // along t's left edge, outside
  contacts.triangle({0.5, 0.75}, {1.5, 2.25}, {2, 1});   // along t's left edge, inside
  contacts.triangle({0, 0}, {4, 0}, {2, -3});            // t's edge, outside
  contacts.triangle({0, 0}, {4, 0}, {2, 3.25});          // t's edge, contains t
  contacts.triangle({4, 0}, {0, 0}, {2.25, 3});          // t's edge, turned the other way
  contacts.triangle({2, 3}, {1, 4}, {3, 4});             // t's apex only
  wall(contacts, {2.5, -2}, {2.5, 4}), wall(contacts, {1.5, -2}, {3.5, 4}), wall(contacts, {3.5, -2}, {1.5, 4});
  add("contacts", contacts);
  // T-junctions: grid corners on the other grids' edges.
  sheet(tj, 6, 6, 0, {0, 0}), sheet(tj, 6, 6, 0, {0.5, 0}), sheet(tj, 6, 6, 0, {0.25, 0.5}, true);
  add("T-junctions", tj, true);
  // The same corners split along both diagonals; coarser cells through them.
  sheet(corners, 4, 4, 0, {0, 0}), sheet(corners, 4, 4, 0, {0, 0}, true), sheet(corners, 2, 4, 0, {0, 0}, true);
  add("shared corners", corners);
  nested.triangle({-4, -4}, {4, -4}, {0, 4});
  nested.triangle({-1, -1}, {1, -1}, {0, 1});              // inside
  nested.triangle({-0.5, -0.75}, {0.5, -0.75}, {0, 0.5});  // inside that one
  nested.triangle({-1, -4}, {1, -4}, {0, -3});             // inside, an edge on the big one's
  nested.triangle({0, -4}, {1, -2}, {-1, -2});             // inside, a corner on its edge
  nested.triangle({-1, -1}, {1, -1}, {0, -2});             // shares an edge with the second
  add("nested", nested);
  for (int s = 0; s < 2; ++s) {
    Builder b;  // corners on a coarse lattice: collinear edges, T-junctions, both orientations
    auto at = [&] { return P2{0.5 * static_cast<double>(rng() % 9) - 2, 0.5 * static_cast<double>(rng() % 9) - 2}; };
    for (int k = 0; k < 40; ++k) {
      const int c0 = b.vertex(at()), c1 = b.vertex(at()), c2 = b.vertex(at());  // (in this order)
      b.triangle(c0, c1, c2);
    }
    add("lattice " + std::to_string(s), b);
  }
  return out;
}

// The plane w = 0 mapped to z = 0, y = 0, x = 0, z = x or z = x + y, moved by 2^20 along
// (1, 1, 1) or not, then scaled by 2^k (exact: checked).
struct Placement {
  int plane, k;
  bool offset;
  std::string name() const {
    static const char* planes[] = {"z=0", "y=0", "x=0", "z=x", "z=x+y"};
    return std::string(planes[plane]) + " 2^" + std::to_string(k) + (offset ? " +2^20" : "");
  }
};

TriangleSoup place(TriangleSoup s, const Placement& p) {
  for (Vec3& v : s.vertices) {
    const double x = v[0], y = v[1], w = v[2];
    const Vec3 maps[5] = {{x, y, w}, {x, w, y}, {w, x, y}, {x, y, x + w}, {x, y, x + y + w}}, m = maps[p.plane];
    EXPECT_EQ(Q(m[2]), p.plane == 3 ? Q(x) + Q(w) : p.plane == 4 ? Q(x) + Q(y) + Q(w) : Q(m[2]));  // (coplanar)
    for (int c = 0; c < 3; ++c) {
      v[c] = std::ldexp(m[c] + (p.offset ? 0x1p20 : 0.0), p.k);
      EXPECT_EQ(Q(std::ldexp(v[c], -p.k)) - (p.offset ? Q(1 << 20) : Q(0)), Q(m[c]));
    }
  }
  return s;
}

// z = 0, then each plane at one scale (large scenes: two planes; sanitizer runs: z = 0).
std::vector<Placement> placements(std::size_t scene, bool large) {
  std::vector<Placement> out = {{0, 0, false}};
  if (tritri_test::scaled_down()) return out;
  const int ks[3] = {-60, 0, 40};
  for (int plane = 0; plane < 5; ++plane)
    if (!large || plane == static_cast<int>(scene % 4) + 1)
      out.push_back({plane, ks[(static_cast<std::size_t>(plane) + scene) % 3], (plane + scene) % 2 == 0});
  return out;
}

// The oracle: exact geometry in the projection (i, j) dropping the normal's largest axis.

struct Projection {
  int axis, i, j;
};

// A point: rational, over a common denominator, and rounded (mpq_get_d truncates: each
// coordinate within 1 ulp, 2u relative).
struct XPoint {
  Q3 q;
  ZPoint z;
  Vec3 d;
};

template <class Point>
XPoint exact_point(const Point& p) {
  const Q3 q = tritri_test::exact(p);
  return {q, tritri_test::common_denominator(q), {q[0].get_d(), q[1].get_d(), q[2].get_d()}};
}

Projection projection_of(const std::array<const XPoint*, 3>& c) {
  const Q3 n = tritri_test::normal(c[0]->q, c[1]->q, c[2]->q);
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (abs(n[k]) > abs(n[a])) a = k;
  return {a, (a + 1) % 3, (a + 2) % 3};
}

// The edge lines of a triangle with double corners, each >= 0 on the closed triangle's
// side: rational a x + b y + c (for clipping), the same times a positive integer (for
// points over a common denominator), and corner A and B - A rounded (for the filter).
struct Lines {
  std::array<std::array<Q, 3>, 3> q;
  std::array<std::array<mpz_class, 3>, 3> z;
  std::array<std::array<double, 4>, 3> f;
  int orientation = 0;
};

Lines lines_of(const std::array<const XPoint*, 3>& c, const Projection& pr) {
  Lines L;
  L.orientation = sgn(tritri_test::normal(c[0]->q, c[1]->q, c[2]->q)[pr.axis]);
  EXPECT_NE(L.orientation, 0) << "triangle degenerate in the projection";
  for (int e = 0; e < 3; ++e) {
    const XPoint &A = *c[e], &B = *c[(e + 1) % 3];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(Q(A.d[k]), A.q[k]) << "the filter needs double corners";
    auto& q = L.q[e];
    q = {-(B.q[pr.j] - A.q[pr.j]) * L.orientation, (B.q[pr.i] - A.q[pr.i]) * L.orientation, 0};
    q[2] = -(q[0] * A.q[pr.i] + q[1] * A.q[pr.j]);
    mpz_class d = 1;
    for (const Q& x : q) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), x.get_den_mpz_t());
    for (int k = 0; k < 3; ++k) L.z[e][k] = q[k].get_num() * (d / q[k].get_den());
    L.f[e] = {A.d[pr.i], A.d[pr.j], B.d[pr.i] - A.d[pr.i], B.d[pr.j] - A.d[pr.j]};
  }
  return L;
}

constexpr double kU = 0x1p-53;

// Membership of t's local vertices and triangles in one closed triangle (its Lines).
// Filter: line e at X is dx (X_j - A_j) - dy (X_i - A_i); with A, B doubles, X within 2u|X|
// per coordinate and each operation within u, |error| <= 6.2u S + O(u^2) where
// S = |dx| (|X_j| + |A_j|) + |dy| (|X_i| + |A_i|): 16u S plus an underflow margin is safe.
// A centroid's value is the corners' sum, within the sum of their bounds plus 2 additions.
struct Membership {
  const Lines* L;
  const Projection* pr;
  const std::vector<const XPoint*>* vs;
  std::vector<double> val, bnd;
  std::vector<signed char> sign;

  mpz_class exact(int e, const ZPoint& p) const {
    return L->z[e][0] * p.num[pr->i] + L->z[e][1] * p.num[pr->j] + L->z[e][2] * p.den;
  }
  Membership(const Lines& lines, const Projection& p, const std::vector<const XPoint*>& v) : L(&lines), pr(&p), vs(&v) {
    for (const XPoint* x : v)
      for (int e = 0; e < 3; ++e) {
        const auto& f = lines.f[e];
        const double X = x->d[p.i], Y = x->d[p.j];
        val.push_back(lines.orientation * (f[2] * (Y - f[1]) - f[3] * (X - f[0])));
        bnd.push_back(16 * kU * (std::abs(f[2]) * (std::abs(Y) + std::abs(f[1])) +
                                 std::abs(f[3]) * (std::abs(X) + std::abs(f[0]))) + 0x1p-1000);
        sign.push_back(static_cast<signed char>(std::abs(val.back()) > bnd.back() ? (val.back() > 0 ? 1 : -1)
                                                                                  : sgn(exact(e, x->z))));
      }
  }
  bool corner_in(int v) const { return sign[3 * v] >= 0 && sign[3 * v + 1] >= 0 && sign[3 * v + 2] >= 0; }
  bool centroid_in(const std::array<int, 3>& T) const {
    for (int e = 0; e < 3; ++e) {
      double s = 0, b = 0, m = 0;
      for (int k : T) s += val[3 * k + e], b += bnd[3 * k + e], m += std::abs(val[3 * k + e]);
      b = (b + 4 * kU * m) * (1 + 8 * kU);
      int sg = std::abs(s) > b ? (s > 0 ? 1 : -1) : 0;
      if (sg == 0) {  // the sum of L(X_k) / D_k over the common denominator D_0 D_1 D_2
        mpz_class sum = 0;
        for (int k = 0; k < 3; ++k)
          sum += exact(e, (*vs)[T[k]]->z) * (*vs)[T[(k + 1) % 3]]->z.den * (*vs)[T[(k + 2) % 3]]->z.den;
        sg = sgn(sum);
      }
      if (sg < 0) return false;
    }
    return true;
  }
};

// Twice the signed area of (a, b, c) in the projection.
Q area2(const ZPoint& a, const ZPoint& b, const ZPoint& c, const Projection& pr) {
  mpz_class m[2][2];
  const ZPoint* r[2] = {&b, &c};
  for (int k = 0; k < 2; ++k)
    for (int x = 0; x < 2; ++x) m[k][x] = r[k]->num[x ? pr.j : pr.i] * a.den - a.num[x ? pr.j : pr.i] * r[k]->den;
  Q out(mpz_class(m[0][0] * m[1][1] - m[0][1] * m[1][0]), mpz_class(a.den * a.den * b.den * c.den));
  out.canonicalize();  // (mpq arithmetic needs canonical operands)
  return out;
}

// Convex polygons in the projection, rational; twice their area.
using Poly = std::vector<std::array<Q, 2>>;

Q area2(const Poly& P) {
  Q s = 0;
  for (std::size_t k = 0, n = P.size(); k < n; ++k) s += P[k][0] * P[(k + 1) % n][1] - P[k][1] * P[(k + 1) % n][0];
  return abs(s);
}

Poly projected(const std::array<const XPoint*, 3>& c, const Projection& pr) {
  return {{c[0]->q[pr.i], c[0]->q[pr.j]}, {c[1]->q[pr.i], c[1]->q[pr.j]}, {c[2]->q[pr.i], c[2]->q[pr.j]}};
}

// P's part where side * (a x + b y + c) >= 0.
Poly clip(const Poly& P, const std::array<Q, 3>& h, int side) {
  Poly out;
  std::vector<Q> v;
  for (const auto& x : P) v.push_back(side * (h[0] * x[0] + h[1] * x[1] + h[2]));
  for (std::size_t k = 0; k < P.size(); ++k) {
    const std::size_t n = (k + 1) % P.size();
    if (sgn(v[k]) >= 0) out.push_back(P[k]);
    if (sgn(v[k]) * sgn(v[n]) >= 0) continue;
    const Q r = v[k] / (v[k] - v[n]);
    out.push_back({P[k][0] + (P[n][0] - P[k][0]) * r, P[k][1] + (P[n][1] - P[k][1]) * r});
  }
  return out;
}

// Twice the area of t minus the union of the triangles `cut` (as disjoint convex pieces).
Q area2_minus(const Poly& t, const std::vector<const Lines*>& cut) {
  std::vector<Poly> pieces = {t};
  for (const Lines* L : cut) {
    std::vector<Poly> next;
    for (Poly& P : pieces) {
      bool apart = false, inside = true;  // P beyond an edge line of L; P in closed L
      for (int e = 0; e < 3 && !apart; ++e) {
        int lo = 1, hi = -1;
        for (const auto& x : P) {
          const int s = sgn(L->q[e][0] * x[0] + L->q[e][1] * x[1] + L->q[e][2]);
          lo = std::min(lo, s), hi = std::max(hi, s);
        }
        apart = hi <= 0, inside &= lo >= 0;
      }
      if (apart) next.push_back(std::move(P));
      if (apart || inside) continue;
      Poly rest = std::move(P);
      for (int e = 0; e < 3 && !rest.empty(); ++e) {  // beyond edge e, inside the ones before
        Poly out = clip(rest, L->q[e], -1);
        if (sgn(area2(out)) != 0) next.push_back(std::move(out));
        rest = clip(rest, L->q[e], 1);
      }
    }
    pieces = std::move(next);
  }
  Q s = 0;
  for (const Poly& P : pieces) s += area2(P);
  return s;
}

enum { kSplit, kEmitted, kUncovered, kOnePartner, kMorePartners, kSkipping, kFlood, kSearched, kDirect, kCounts };
using Counts = std::array<std::size_t, kCounts>;

std::string str(const Counts& c) {
  const char* after[kCounts] = {" split, ", " emitted (", " uncovered, ", " by 1 partner, ", " by 2+), ",
                                " skip some; flood ", " (", " with long chains), direct ", ""};
  std::string s;
  for (int k = 0; k < kCounts; ++k) s += std::to_string(c[k]) + after[k];
  return s;
}

// The partner lists against a brute force: every coplanar pair whose intersection has an
// area is listed, both ways (listed partners are checked coplanar in check()).
template <class M>
void check_partners(const std::vector<Tri>& F, const BasicIntersectionGraph<typename M::Point>& g,
                    const std::vector<XPoint>& gx, const std::string& what) {
  auto corners = [&](std::size_t u) { return std::array<const XPoint*, 3>{&gx[F[u][0]], &gx[F[u][1]], &gx[F[u][2]]}; };
  std::vector<std::array<double, 6>> box(F.size());  // exact: the corners are doubles
  for (std::size_t u = 0; u < F.size(); ++u)
    for (int c = 0; c < 3; ++c)
      std::tie(box[u][c], box[u][c + 3]) = std::minmax({gx[F[u][0]].d[c], gx[F[u][1]].d[c], gx[F[u][2]].d[c]});
  for (std::size_t t = 0; t < F.size(); ++t) {
    const auto ct = corners(t);
    const auto& partners = g.coplanar_partners[t];
    EXPECT_TRUE(std::is_sorted(partners.begin(), partners.end())) << what;
    for (std::size_t u = t + 1; u < F.size(); ++u) {
      bool apart = false, listed = std::binary_search(partners.begin(), partners.end(), static_cast<int>(u));
      for (int c = 0; c < 3; ++c) apart |= box[u][c] > box[t][c + 3] || box[t][c] > box[u][c + 3];
      const auto& back = g.coplanar_partners[u];
      EXPECT_EQ(listed, std::binary_search(back.begin(), back.end(), static_cast<int>(t))) << what << ": " << t;
      const auto cu = corners(u);
      bool coplanar = !apart && !listed;
      for (int k = 0; k < 3 && coplanar; ++k) coplanar = !tritri_test::orient3d(ct[0]->z, ct[1]->z, ct[2]->z, cu[k]->z);
      if (!coplanar) continue;
      const Projection pr = projection_of(ct);
      const Lines lu = lines_of(cu, pr);
      EXPECT_EQ(area2_minus(projected(ct, pr), {&lu}), area2(projected(ct, pr))) << what << ": " << u << " meets " << t;
    }
  }
}

// Every triangle with coplanar partners split and checked against the oracle.
template <class M>
void check(const BasicTriangleSoup<typename M::Vertex>& soup, const BasicIntersectionGraph<typename M::Point>& g,
           const std::string& what, Counts& n) {
  const auto& F = soup.triangles;
  std::vector<XPoint> gx;
  for (const auto& p : g.points) gx.push_back(exact_point(p));
  check_partners<M>(F, g, gx, what);
  auto corners = [&](int u) { return std::array<const XPoint*, 3>{&gx[F[u][0]], &gx[F[u][1]], &gx[F[u][2]]}; };
  for (std::size_t t = 0; t < F.size(); ++t) {
    const auto& partners = g.coplanar_partners[t];
    if (partners.empty()) continue;
    const int ti = static_cast<int>(t);
    const std::string at = what + ", t=" + std::to_string(t);
    const auto piece = split_triangle_of<M>(soup, g, ti);
    const auto ct = corners(ti);
    const Projection pr = projection_of(ct);
    const Lines lt = lines_of(ct, pr);
    // The Euler count of t's local triangles, 2 V - B - 2 (V: corners, edge points, inside
    // points, new TPIs; B: corners and edge points), gives the path partner_covers takes.
    std::set<int> on_boundary(F[t].begin(), F[t].end()), all(g.triangle_points[t].begin(), g.triangle_points[t].end());
    std::size_t longest = 0;  // the longest chain, corners included
    for (int e : g.triangle_edges[t])
      on_boundary.insert(g.edge_points[e].begin(), g.edge_points[e].end()),
          longest = std::max(longest, g.edge_points[e].size() + 2);
    all.insert(on_boundary.begin(), on_boundary.end());
    const std::size_t local = 2 * (all.size() + piece.tpis.size()) - on_boundary.size() - 2;
    const bool flood = local * partners.size() > 256;
    ++(flood ? n[kFlood] : n[kDirect]);
    bool corner_outside = false;  // a partner with no corner among t's vertices: a seed searched
    for (int q : partners) corner_outside |= !all.count(F[q][0]) && !all.count(F[q][1]) && !all.count(F[q][2]);
    n[kSearched] += flood && longest > 16 && corner_outside;

    ASSERT_EQ(piece.covered_by.size(), piece.triangles.size()) << at;
    std::vector<XPoint> tx;  // the new TPIs
    for (const auto& p : piece.tpis) tx.push_back(exact_point(p));
    std::map<int, int> index;  // id -> local vertex
    std::vector<const XPoint*> vs;
    std::vector<std::array<int, 3>> T;
    for (const Tri& tri : piece.triangles)
      for (int k = 0; k < 3; ++k) {
        const int id = tri[k];
        ASSERT_TRUE(id >= 0 ? id < static_cast<int>(g.points.size()) : -1 - id < static_cast<int>(tx.size())) << at;
        auto [it, fresh] = index.emplace(id, static_cast<int>(vs.size()));
        if (fresh) vs.push_back(id >= 0 ? &gx[id] : &tx[-1 - id]);
        if (k == 0) T.emplace_back();
        T.back()[k] = it->second;
      }
    // The partners containing each emitted triangle (and no straddling).
    std::vector<std::vector<int>> S(T.size());
    std::vector<Lines> lq;
    std::vector<const Lines*> smaller;  // the partners q < t
    lq.reserve(partners.size());
    for (int q : partners) {
      const auto cq = corners(q);
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(tritri_test::orient3d(ct[0]->z, ct[1]->z, ct[2]->z, cq[k]->z), 0) << at << ": partner off t's plane";
      lq.push_back(lines_of(cq, pr));
      if (q < ti) smaller.push_back(&lq.back());
      const Membership m(lq.back(), pr, vs);
      for (std::size_t k = 0; k < T.size(); ++k) {
        const bool c = m.centroid_in(T[k]);
        EXPECT_EQ(c, m.corner_in(T[k][0]) && m.corner_in(T[k][1]) && m.corner_in(T[k][2]))
            << at << ": local triangle " << k << " straddles partner " << q;
        if (c) S[k].push_back(q);
      }
    }
    // The rule; positive area in t's orientation, corners in closed t, no edge twice.
    EXPECT_EQ(std::set<std::vector<int>>(piece.covers.begin(), piece.covers.end()).size(), piece.covers.size()) << at;
    const Membership in_t(lt, pr, vs);
    Q emitted_area = 0;
    std::set<std::pair<int, int>> directed;
    for (std::size_t k = 0; k < T.size(); ++k) {
      const Q a = area2(vs[T[k][0]]->z, vs[T[k][1]]->z, vs[T[k][2]]->z, pr) * lt.orientation;
      EXPECT_GT(sgn(a), 0) << at << ": local triangle " << k << " not positive";
      emitted_area += a;
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(in_t.corner_in(T[k][c])) << at << ": corner of local triangle " << k << " outside t";
        EXPECT_TRUE(directed.insert({T[k][c], T[k][(c + 1) % 3]}).second) << at << ": an edge twice";
      }
      std::sort(S[k].begin(), S[k].end());
      EXPECT_TRUE(S[k].empty() || S[k][0] > ti) << at << ": local triangle " << k << " emitted, but " << S[k][0]
                                                << " < t covers it";
      const int c = piece.covered_by[k];
      EXPECT_EQ(c == -1, S[k].empty()) << at << ": local triangle " << k << ", " << S[k].size() << " partners";
      ++(S[k].empty() ? n[kUncovered] : S[k].size() == 1 ? n[kOnePartner] : n[kMorePartners]);
      if (S[k].empty() || c < 0) continue;
      S[k].insert(S[k].begin(), ti);
      ASSERT_LT(c, static_cast<int>(piece.covers.size())) << at << ": local triangle " << k;
      EXPECT_EQ(piece.covers[c], S[k]) << at << ": cover of local triangle " << k;
    }
    n[kEmitted] += T.size(), ++n[kSplit];
    // Completeness: the emitted triangles tile t minus the partners q < t.
    const Q whole = area2(projected(ct, pr)), want = area2_minus(projected(ct, pr), smaller);
    EXPECT_EQ(emitted_area, want) << at << ": emitted area";
    EXPECT_TRUE(T.size() <= local && (T.size() == local) == (want == whole)) << at << ": " << T.size() << "/" << local;
    n[kSkipping] += want != whole;
  }
}

template <class M>
Counts run(const BasicTriangleSoup<typename M::Vertex>& soup, Classifier classifier, const std::string& what) {
  const auto& V = soup.vertices;
  const auto& F = soup.triangles;
  std::vector<std::pair<int, int>> pairs;
  if constexpr (std::is_same_v<M, DoubleModel>) pairs = candidate_pairs(V, F);  // every box pair
  if constexpr (!std::is_same_v<M, DoubleModel>) pairs = detect_pairs<M>(V, F, 0).pairs;
  const auto g = build_intersection_graph<M>(V, F, classify_pairs<M>(V, F, pairs, classifier));
  Counts n{};
  check<M>(soup, g, what, n);
  return n;
}

TEST(PartnerCovers, DoubleModelMatchesExactOracle) {
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  const auto start = Clock::now();
  const std::vector<Scene> all = scenes();
  Counts sum{};
  for (std::size_t s = 0; s < all.size(); ++s) {
    const auto scene_start = Clock::now();
    const std::vector<Placement> where = placements(s, all[s].large);
    std::string first;
    for (std::size_t p = 0; p < where.size(); ++p) {
      const std::string what = all[s].name + ", " + where[p].name();
      PreprocessStats stats;
      const TriangleSoup soup = preprocess(place(all[s].soup, where[p]), PreprocessOptions{}, stats);
      const Counts c = run<DoubleModel>(soup, p % 2 == 0 ? Classifier::Native : Classifier::Tritri, what);
      for (int k = 0; k < kCounts; ++k) sum[k] += c[k];
      // Exact maps of the plane change no incidence: the same counts everywhere.
      if (p == 0) first = str(c);
      EXPECT_EQ(str(c), first) << what;
      EXPECT_GT(c[kSplit], 0u) << what;
    }
    std::printf("%-18s %s; %zu placements, %.2f s\n", all[s].name.c_str(), first.c_str(), where.size(),
                seconds_since(scene_start));
  }
  std::printf("all: %s; %.2f s\n", str(sum).c_str(), seconds_since(start));
  // Not vacuous: both paths, seeds searched on long chains, covers of one and of several
  // partners, triangles that skip what a smaller partner emits.
  for (int k : {kFlood, kSearched, kDirect, kOnePartner, kMorePartners, kUncovered, kSkipping})
    EXPECT_GT(sum[k], 0u) << "count " << k;
}

// The exact model on the small scenes, z = 0 and z = x + y moved and scaled by 2^-60:
// the same oracle, and the same counts as the double model.
TEST(PartnerCovers, ExactModelMatchesExactOracle) {
  const std::vector<Scene> all = scenes();
  for (std::size_t s = 0; s < all.size(); ++s) {
    if (all[s].large) continue;
    for (const Placement& p : {Placement{0, 0, false}, Placement{4, -60, true}}) {
      if (tritri_test::scaled_down() && p.plane != 0) continue;
      const std::string what = all[s].name + ", " + p.name() + " (exact)";
      const TriangleSoup input = place(all[s].soup, p);
      PreprocessStats stats;
      const auto soup = preprocess<ExactModel>(to_exact(input), PreprocessOptions{}, stats);
      const Counts c = run<ExactModel>(soup, Classifier::Native, what);
      const Counts d = run<DoubleModel>(preprocess(input, PreprocessOptions{}, stats), Classifier::Native, what);
      EXPECT_EQ(str(c), str(d)) << what;
    }
  }
}

}  // namespace
