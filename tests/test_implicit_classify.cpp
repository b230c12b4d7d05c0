// tests/test_implicit_classify.cpp
//
// classify<ImplicitKernel> on triangles whose vertices are implicit points equals
// classify<CgalKernel<Simple_cartesian<Gmpq>>> on their exact coordinates (computed in GMP
// rationals from the defining points, independently of the library; support/exact_oracle.h,
// soups from support/implicit_soups.h).
//
// The triangles are sub-triangles of a soup, as in a mesh arrangement: each soup triangle
// keeps its vertices and the LPIs where edges cross the other triangles' planes, and a
// sub-triangle takes three of those points. So pairs share vertices and edges, have vertices
// on each other's edges and faces, are coplanar, ... and every point is used in several
// representations (an LPI of one edge, the LPI of the reversed edge, TPIs of planes through
// the edge, the explicit point when it is a double point, LPIs that land on a vertex), so
// one triangle may name a point as an LPI and the other the same point as a TPI or explicitly.
// Soups live on the integer grid or use random doubles, under exact power-of-two scalings
// (2^k, k in [-60, 60], 2^+-300, rarely up to 2^1010 and down to subnormal 2^-1068) and
// translations.
//
// Also: on explicit points only, classify<ImplicitKernel> equals classify<DoubleKernel>.
//
// Counts scale with TRITRI_TEST_SCALE (default 1.0: 100,000 implicit pairs and 200,000
// explicit pairs; the sanitizer CI uses 0.1). TRITRI_TEST_SEED changes the seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/implicit_recipes.h"
#include "support/implicit_soups.h"
#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri::Result;
using tritri_test::Rng;
using tritri_test::Soup;

using tritri_test::RationalKernel;
using ExactPoint = RationalKernel::Point_3;

constexpr int kMaxReports = 10;

// A vertex of a sub-triangle: a soup point and which of its representations is used.
struct Vertex {
  int id;
  int rep;
};
using Tri = std::array<Vertex, 3>;

// The soup's points built through the library (every representation) and exactly.
struct BuiltSoup {
  Soup soup;
  std::vector<std::vector<ImplicitPoint>> reps;  // reps[id][r]
  std::vector<ExactPoint> exact;                 // exact[id]
  int refused = 0;                               // defined representations the library refused
};

// Every representation is defined (the generator keeps only those); a refusal is a failure.
BuiltSoup build_soup(Rng& rng) {
  BuiltSoup b{tritri_test::random_soup(rng), {}, {}, 0};
  for (const auto& p : b.soup.points) {
    b.exact.push_back(tritri_test::to_cgal<RationalKernel>(p.exact));
    b.reps.emplace_back();
    for (const auto& r : p.reps) {
      const auto built = tritri_test::build(r, rng.percent(25));
      if (built) {
        b.reps.back().push_back(*built);
      } else {
        ++b.refused;
        ADD_FAILURE() << "defined point refused: " << tritri_test::describe(r);
      }
    }
  }
  return b;
}

class PairPicker {
 public:
  PairPicker(const BuiltSoup& b, Rng& rng) : b_(b), rng_(rng) {}

  Vertex vertex(int id) { return {id, rng_.uniform(0, static_cast<int>(b_.reps[id].size()) - 1)}; }

  int from(const std::vector<int>& set) { return set[rng_.uniform(0, static_cast<int>(set.size()) - 1)]; }

  // Three vertices from `set`, `forced` among them at random positions; distinct ids.
  Tri triangle(const std::vector<int>& set, std::vector<int> forced) {
    for (int attempt = 0;; ++attempt) {
      std::vector<int> ids = forced;
      while (ids.size() < 3) ids.push_back(from(set));
      tritri_test::shuffle(ids.data(), 3, rng_);
      const bool distinct = ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2];
      // Collinear and repeated vertices make degenerate triangles: keep a few of them.
      const bool proper =
          distinct && !tritri_test::collinear(b_.soup.points[ids[0]].exact, b_.soup.points[ids[1]].exact,
                                              b_.soup.points[ids[2]].exact);
      if (proper || attempt >= 20 || rng_.percent(3)) return {vertex(ids[0]), vertex(ids[1]), vertex(ids[2])};
    }
  }

  std::pair<Tri, Tri> pair() {
    const int n = static_cast<int>(b_.soup.triangles.size());
    const int t = rng_.uniform(0, n - 1);
    const auto& on_t = b_.soup.on[t];
    switch (rng_.uniform(0, 19)) {
      case 0:
      case 1:
      case 2:
      case 3:
      case 4:
      case 5:
      case 6: {  // both in one soup triangle's plane, sharing 0 to 3 points
        const Tri a = triangle(on_t, {});
        std::vector<int> shared;
        for (int k = rng_.uniform(0, 3), i = 0; i < k; ++i) shared.push_back(a[i].id);
        return {a, triangle(on_t, shared)};
      }
      case 7:
      case 8:
      case 9:
      case 10:
      case 11:
      case 12:
      case 13: {  // in two soup triangles' planes, sharing points of both
        const int u = (t + rng_.uniform(1, n - 1)) % n;
        const auto& on_u = b_.soup.on[u];
        std::vector<int> common;
        for (int id : on_t)
          if (std::find(on_u.begin(), on_u.end(), id) != on_u.end()) common.push_back(id);
        std::vector<int> shared;
        if (!common.empty())
          for (int k = rng_.uniform(0, 2), i = 0; i < k; ++i) shared.push_back(from(common));
        if (shared.size() == 2 && shared[0] == shared[1]) shared.pop_back();
        return {triangle(on_t, shared), triangle(on_u, shared)};
      }
      case 14:
      case 15:
      case 16: {  // one triangle in two representations, possibly one vertex moved
        const Tri a = triangle(on_t, {});
        Tri b = {vertex(a[0].id), vertex(a[1].id), vertex(a[2].id)};
        if (rng_.percent(40)) b[rng_.uniform(0, 2)] = vertex(from(on_t));
        std::rotate(b.begin(), b.begin() + rng_.uniform(0, 2), b.end());
        if (rng_.percent(50)) std::swap(b[1], b[2]);
        return {a, b};
      }
      default: {  // two soup triangles themselves
        const int u = rng_.uniform(0, n - 1);
        const auto& on_u = b_.soup.on[u];
        return {Tri{vertex(on_t[0]), vertex(on_t[1]), vertex(on_t[2])},
                Tri{vertex(on_u[0]), vertex(on_u[1]), vertex(on_u[2])}};
      }
    }
  }

 private:
  const BuiltSoup& b_;
  Rng& rng_;
};

std::string describe_tri(const BuiltSoup& b, const Tri& t) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    s += "    " + std::to_string(i) + ": " + tritri_test::describe(b.soup.points[t[i].id].reps[t[i].rep]) +
         "\n       exact " + tritri_test::to_string(b.soup.points[t[i].id].exact) + "\n";
  return s;
}

TEST(ImplicitClassify, SubTrianglesOfASoupMatchTheExactRationalKernel) {
  const long long target = tritri_test::scaled_count(100000);
  Rng rng(tritri_test::seed_for(41));
  long long pairs = 0, failures = 0, coplanar = 0, degenerate = 0, mixed_kinds = 0, rejected_reps = 0, bad_soups = 0;
  std::array<long long, 8> types{};
  while (pairs < target) {
    const BuiltSoup b = build_soup(rng);
    if (b.refused > 0) {  // reported; a point may have no representation left
      ASSERT_LT(++bad_soups, 100) << "the library refuses defined points in most soups";
      continue;
    }
    rejected_reps += static_cast<long long>(b.soup.rejected.size());
    for (const auto& r : b.soup.rejected)
      ADD_FAILURE() << "generator: a representation is not the point it was built for: " << tritri_test::describe(r);
    PairPicker pick(b, rng);
    for (int k = 0; k < 200 && pairs < target; ++k, ++pairs) {
      const auto [A, B] = pick.pair();
      auto P = [&](const Vertex& v) -> const ImplicitPoint& { return b.reps[v.id][v.rep]; };
      auto E = [&](const Vertex& v) -> const ExactPoint& { return b.exact[v.id]; };
      const Result got = tritri::classify<tritri::ImplicitKernel>(P(A[0]), P(A[1]), P(A[2]), P(B[0]), P(B[1]), P(B[2]));
      const Result expected =
          tritri::classify<tritri::CgalKernel<RationalKernel>>(E(A[0]), E(A[1]), E(A[2]), E(B[0]), E(B[1]), E(B[2]));
      coplanar += expected.coplanar;
      degenerate += expected.degenerate;
      for (const auto& p : expected.points) ++types[static_cast<int>(p.type)];
      for (const Vertex& va : A)
        for (const Vertex& vb : B) mixed_kinds += va.id == vb.id && P(va).kind() != P(vb).kind();
      if (!(got == expected) && ++failures <= kMaxReports)
        ADD_FAILURE() << "classify<ImplicitKernel> " << got << "\n  exact rationals    " << expected << "\n  A:\n"
                      << describe_tri(b, A) << "  B:\n"
                      << describe_tri(b, B);
    }
  }
  std::cout << "[ cases    ] " << pairs << " pairs: " << coplanar << " coplanar, " << degenerate << " degenerate, "
            << mixed_kinds << " shared points named by different kinds; points by type:";
  for (int t = 0; t < 8; ++t) std::cout << " " << tritri::to_string(static_cast<tritri::Type>(t)) << "=" << types[t];
  std::cout << "\n";
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(rejected_reps, 0);
  EXPECT_GT(coplanar, pairs / 10);
  EXPECT_GT(mixed_kinds, pairs / 10);
  for (int t = 0; t < 8; ++t)
    EXPECT_GT(types[t], 0) << tritri::to_string(static_cast<tritri::Type>(t)) << " never expected";
}

TEST(ImplicitClassify, ExplicitPointsMatchTheDoubleKernel) {
  const long long target = tritri_test::scaled_count(200000);
  Rng rng(tritri_test::seed_for(42));
  long long failures = 0, intersecting = 0;
  for (long long n = 0; n < target; ++n) {
    tritri_test::Pair p;
    switch (rng.uniform(0, 5)) {
      case 0:
        p = tritri_test::gen_structured(rng);
        break;
      case 1:
        p = tritri_test::gen_perturbed(rng);
        break;
      case 2:
        p = tritri_test::gen_scaled(rng);
        break;
      case 3:
        p = tritri_test::gen_edges_crossing_at_point(rng);
        break;
      case 4:
        p = tritri_test::gen_random_near(rng);
        break;
      default:
        p = tritri_test::gen_random(rng);
        break;
    }
    p = tritri_test::random_symmetry(p, rng);
    std::array<ImplicitPoint, 6> e;
    for (int i = 0; i < 3; ++i) {
      e[i] = ImplicitPoint::explicit_point(p.a[i]);
      e[3 + i] = ImplicitPoint::explicit_point(p.b[i]);
    }
    const Result got = tritri::classify<tritri::ImplicitKernel>(e[0], e[1], e[2], e[3], e[4], e[5]);
    const Result expected = tritri::classify<tritri::DoubleKernel>(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
    intersecting += expected.intersects();
    if (!(got == expected) && ++failures <= kMaxReports)
      ADD_FAILURE() << "classify<ImplicitKernel> " << got << "\n  DoubleKernel       " << expected << "\n"
                    << tritri_test::describe(p);
  }
  std::cout << "[ cases    ] " << target << " explicit pairs, " << intersecting << " intersecting\n";
  EXPECT_EQ(failures, 0);
}

}  // namespace
