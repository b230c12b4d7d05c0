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
// scaled by 2^k, moved by 2^20 (support/coplanar_scenes.h, as in test_share_coplanar.cpp);
// DoubleModel, and ExactModel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "arrangements/as_input.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate_triangle.h"
#include "support/coplanar_scenes.h"
#include "support/exact_oracle.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using namespace tritri_test::coplanar;

// The crossing triangles' corners: uniform in [-2.5, 2.5]^2.
P2 crossing_corner(std::mt19937_64& rng) {
  auto uniform = [&] { return 2.5 * (2 * unit(rng) - 1); };
  return {uniform(), uniform()};  // (a braced list: in order)
}

std::vector<Scene> scenes() {
  SceneList list{std::mt19937_64(tritri_test::seed_for(5113)), crossing_corner, {}};
  for (int n : {20, 40, 80}) {
    list.add("strips n=" + std::to_string(n), strips(n), n > 20);
    if (n == 80 && tritri_test::scaled_down()) list.scenes.pop_back();  // (after add: the same random numbers)
  }
  list.add("fans, own apexes", fans(false, Apex::kLast));
  list.add("fans, shared apex", fans(true, Apex::kLast));
  list.add("two sheets", two_sheets({0.2775, 0.1575}), true);
  list.add("three sheets", three_sheets(), true);
  list.add("contacts", contacts(true));
  list.add("T-junctions", t_junctions(), true);
  list.add("shared corners", shared_corners());
  list.add("nested", nested());
  for (int s = 0; s < 2; ++s) list.add("lattice " + std::to_string(s), lattice(list.rng, true));
  return std::move(list.scenes);
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

// The edge lines of a triangle with double corners (EdgeLines), and for the filter corner
// A and B - A of each line rounded.
struct Lines : EdgeLines {
  std::array<std::array<double, 4>, 3> f;
};

Lines lines_of(const std::array<const XPoint*, 3>& c, const Projection& pr) {
  Lines L{edge_lines(c[0]->q, c[1]->q, c[2]->q, pr), {}};
  for (int e = 0; e < 3; ++e) {
    const XPoint &A = *c[e], &B = *c[(e + 1) % 3];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(Q(A.d[k]), A.q[k]) << "the filter needs double corners";
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

  mpz_class exact(int e, const ZPoint& p) const { return L->at(e, p, *pr); }
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
      const Projection pr = projection_of(ct[0]->q, ct[1]->q, ct[2]->q);
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
    const Projection pr = projection_of(ct[0]->q, ct[1]->q, ct[2]->q);
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
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Scene> all = scenes();
  Counts sum{};
  for (std::size_t s = 0; s < all.size(); ++s) {
    const auto scene_start = std::chrono::steady_clock::now();
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
  for_each_exact_run(scenes(), [](const std::string& what, const TriangleSoup& input, const auto& soup) {
    PreprocessStats stats;
    const Counts c = run<ExactModel>(soup, Classifier::Native, what);
    const Counts d = run<DoubleModel>(preprocess(input, PreprocessOptions{}, stats), Classifier::Native, what);
    EXPECT_EQ(str(c), str(d)) << what;
  });
}

}  // namespace
