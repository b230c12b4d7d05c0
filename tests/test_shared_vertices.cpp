// Specification of tritri::meet_only_in_shared (tritri/shared_vertices.h), against the full
// classifier on generated neighbour pairs:
//   - whenever it answers true, tritri::classify reports exactly the shared vertices (only
//     VA_ON_VB points, at equal indices, every shared vertex among them, nothing else);
//   - it answers true for every non-coplanar pair sharing an edge, and for every pair
//     sharing one vertex whose other corners lie strictly on one side of a plane;
//   - it never answers true for pairs sharing no vertex or all three.
// Pairs: a shared edge or vertex with the other corners drawn from small integer grids
// (many coplanar, collinear and touching cases), from random doubles, and the same scaled
// by 2^+-k and offset far from the origin. About 2 million pairs at TRITRI_TEST_SCALE=1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include <tritri/tritri.h>

#include "support/test_scale.h"

namespace {

using tritri_test::test_scale;
using P = tritri::DoubleKernel::Point;
using Ids = std::array<int, 3>;

struct Pair {
  std::array<P, 3> a, b;
  Ids ia, ib;
};

// Corners: index 0..5 name distinct points (u, v, a-corners, b-corners); a shared corner
// has the same index and point on both sides.
P draw(std::mt19937_64& rng, int style) {
  if (style == 0) {
    std::uniform_int_distribution<int> g(-2, 2);
    return {double(g(rng)), double(g(rng)), double(g(rng))};
  }
  std::uniform_real_distribution<double> r(-1, 1);
  return {r(rng), r(rng), r(rng)};
}

Pair make_pair(std::mt19937_64& rng, int shared, int style, int k, double offset) {
  std::array<P, 6> pts;
  for (P& p : pts) p = draw(rng, style);
  if (style == 2) pts[3][2] = pts[0][2] + (pts[3][2] - pts[0][2]) * 1e-12;  // nearly in a plane
  for (P& p : pts)
    for (double& c : p) c = std::ldexp(c, k) + offset;
  // A = (0, 1, 2); B shares the first `shared` of A's corners, in a shuffled position.
  Pair q;
  Ids ia = {0, 1, 2}, ib = {3, 4, 5};
  for (int s = 0; s < shared; ++s) ib[s] = ia[s];
  std::shuffle(ib.begin(), ib.end(), rng);
  if (rng() % 2) std::swap(ia[1], ia[2]);
  q.ia = ia;
  q.ib = ib;
  for (int i = 0; i < 3; ++i) {
    q.a[i] = pts[ia[i]];
    q.b[i] = pts[ib[i]];
  }
  return q;
}

bool degenerate(const std::array<P, 3>& t) {
  return tritri::projection(tritri::DoubleKernel{}, t[0], t[1], t[2]).second == 0;
}

// Does the full classification report exactly the shared vertices?
bool only_shared(const Pair& q, int shared) {
  const tritri::Result r = tritri::classify<tritri::DoubleKernel>(q.a[0], q.a[1], q.a[2], q.b[0], q.b[1], q.b[2]);
  if (r.degenerate || static_cast<int>(r.points.size()) != shared) return false;
  for (const auto& p : r.points)
    if (p.type != tritri::Type::VA_ON_VB || q.ia[p.id0] != q.ib[p.id1]) return false;
  return true;
}

TEST(MeetOnlyInShared, TrueOnlyWhenTheFullClassifierReportsJustTheSharedVertices) {
  std::mt19937_64 rng(99);
  const long n = std::max(1000L, std::lround(2'000'000 * test_scale()));
  long checked = 0, settled[4] = {0, 0, 0, 0}, failures = 0;
  const double offsets[] = {0.0, 1e6, -1e15, 1e200};
  for (long i = 0; i < n; ++i) {
    const int shared = static_cast<int>(rng() % 4), style = static_cast<int>(rng() % 3);
    const int k = static_cast<int>(rng() % 3) * 300 - 300;  // 2^-300, 1, 2^300
    const double offset = k == 0 ? offsets[rng() % 4] : 0.0;
    const Pair q = make_pair(rng, shared, style, k, offset);
    if (degenerate(q.a) || degenerate(q.b)) continue;
    ++checked;
    const bool answer = tritri::meet_only_in_shared(tritri::DoubleKernel{}, q.a, q.ia, q.b, q.ib);
    if (!answer) continue;
    ++settled[shared];
    if ((shared == 0 || shared == 3 || !only_shared(q, shared)) && ++failures <= 5)
      ADD_FAILURE() << "settled wrongly: pair " << i << " sharing " << shared;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(settled[0] + settled[3], 0);
  EXPECT_GT(settled[1], checked / 10);  // the fast path is taken often
  EXPECT_GT(settled[2], checked / 10);
  std::printf("neighbour pairs: %ld checked, %ld settled (vertex), %ld settled (edge)\n", checked, settled[1],
              settled[2]);
}

// Completeness where the proof says it must answer: non-coplanar shared edges, and shared
// vertices with the other triangle strictly on one side.
TEST(MeetOnlyInShared, SettlesEveryNonCoplanarSharedEdgeAndEverySeparatedSharedVertex) {
  std::mt19937_64 rng(7);
  const long n = std::max(1000L, std::lround(300'000 * test_scale()));
  for (long i = 0; i < n; ++i) {
    const int shared = 1 + static_cast<int>(rng() % 2);
    const Pair q = make_pair(rng, shared, static_cast<int>(rng() % 2), 0, 0.0);
    if (degenerate(q.a) || degenerate(q.b)) continue;
    const bool answer = tritri::meet_only_in_shared(tritri::DoubleKernel{}, q.a, q.ia, q.b, q.ib);
    auto side = [](const std::array<P, 3>& t, const P& p) { return tritri::orient3d(t[0], t[1], t[2], p); };
    bool expected = false;
    if (shared == 2) {
      for (const P& p : q.b) expected |= side(q.a, p) != tritri::Sign::Zero;
    } else {
      auto separated = [&](const std::array<P, 3>& t, const std::array<P, 3>& o, const Ids& it, const Ids& io) {
        tritri::Sign s = tritri::Sign::Zero;
        int others = 0;
        for (int j = 0; j < 3; ++j) {
          bool is_shared = false;
          for (int i2 = 0; i2 < 3; ++i2) is_shared |= io[j] == it[i2];
          if (is_shared) continue;
          const tritri::Sign sj = side(t, o[j]);
          if (sj == tritri::Sign::Zero || (others++ > 0 && sj != s)) return false;
          s = sj;
        }
        return true;
      };
      expected = separated(q.a, q.b, q.ia, q.ib) || separated(q.b, q.a, q.ib, q.ia);
    }
    ASSERT_EQ(answer, expected) << "pair " << i << " sharing " << shared;
  }
}

TEST(MeetOnlyInShared, CountsItsPredicatesThroughACountingKernel) {
  const std::array<P, 3> a = {P{0, 0, 0}, P{1, 0, 0}, P{0, 1, 0}};
  const std::array<P, 3> b_edge = {P{1, 0, 0}, P{0, 0, 0}, P{0, 0, 1}};
  const std::array<P, 3> b_vertex = {P{0, 0, 0}, P{-1, 0, 1}, P{0, -1, 1}};
  tritri::PredicateCounts counts;
  const tritri::CountingKernel<tritri::DoubleKernel> k(counts);
  EXPECT_TRUE(tritri::meet_only_in_shared(k, a, {0, 1, 2}, b_edge, {1, 0, 3}));
  EXPECT_EQ(counts.orient3d, 1u);
  EXPECT_TRUE(tritri::meet_only_in_shared(k, a, {0, 1, 2}, b_vertex, {0, 4, 5}));
  EXPECT_EQ(counts.orient3d, 3u);
  // Coplanar neighbours are left to the classifier.
  const std::array<P, 3> flat = {P{1, 0, 0}, P{0, 0, 0}, P{1, -1, 0}};
  EXPECT_FALSE(tritri::meet_only_in_shared(k, a, {0, 1, 2}, flat, {1, 0, 6}));
}

}  // namespace
