// Specification of tritri/direction_slabs.h, the certified broad-phase test of stage 2:
//   1. slabs_apart(a, b) is true only for triangles that do not meet, judged by
//      tritri::classify (exact), over every generator of support/pair_generators.h (shared
//      vertices and edges, vertices on edges and faces, coplanar overlaps, one-ulp
//      perturbations), each under random exact symmetries, scaled by 2^k (k from -1070 to
//      960) and translated by 0, 1e6, 2^40 + small or 1e12 (the oracle judges the rounded
//      doubles);
//   2. triangles that touch in one point of a plane normal to a three-coordinate direction
//      (1,1,1), (1,1,-1), ...: the other triangle lies in that plane, at integer coordinates
//      near 2^60 where (x + y) + z rounds differently for points with the same exact sum;
//   3. the test does reject: long thin triangles crossing each other's box diagonals, and
//      a share of the generated pairs;
//   4. coordinates near the overflow threshold (sums overflow) give whole-line slabs, never
//      a rejection of a meeting pair;
//   5. each extent in doubles (detail::direction_extents) contains the exact extent, computed
//      in rationals, for corners of random exponents (subnormal to near overflow) and signs,
//      given as points or as boxes around them, and the floats of the slabs contain the
//      doubles. Without the widening this test
//      fails (checked by hand);
//   6. candidate_triangle_pairs (the batch API's candidates) on soups of long thin triangles
//      in random directions, some sharing corners: every pair that meets is a candidate,
//      every candidate is a box pair, far fewer candidates than box pairs, the same for 1,
//      2 and all threads.
#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <tritri/box_pairs.h>
#include <tritri/candidate_triangle_pairs.h>
#include <tritri/direction_slabs.h>
#include <tritri/tritri.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri_test::Pair;
using tritri_test::Point;
using tritri_test::Rng;
using tritri_test::Triangle;

tritri::DirectionSlabs slabs(const Triangle& t) { return tritri::direction_slabs(t[0], t[1], t[2]); }

bool meet(const Pair& p) {
  const tritri::Result r = tritri::classify<tritri::DoubleKernel>(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
  return r.intersects();
}

bool degenerate(const Triangle& t) {
  return tritri::orient2d(t[0], t[1], t[2], tritri::Plane::XY) == tritri::Sign::Zero &&
         tritri::orient2d(t[0], t[1], t[2], tritri::Plane::YZ) == tritri::Sign::Zero &&
         tritri::orient2d(t[0], t[1], t[2], tritri::Plane::ZX) == tritri::Sign::Zero;
}

// 1.
TEST(DirectionSlabs, NeverRejectAPairThatMeets) {
  Rng rng(tritri_test::seed_for(0x51ab5));
  const int per_generator = static_cast<int>(tritri_test::scaled_count(20000));
  const int exponents[] = {-1070, -1040, -500, -60, -20, 0, 20, 60, 500, 960};
  const Point offsets[] = {{0, 0, 0}, {1e6, -1e6, 1e6}, {0x1p40 + 3, 0x1p40 - 5, -0x1p40 + 7}, {1e12, 1e12, -1e12}};
  long long judged = 0, meeting = 0, rejected = 0;
  for (const auto& gen : tritri_test::pair_generators()) {
    for (int n = 0; n < per_generator; ++n) {
      Pair p = tritri_test::random_symmetry(gen.make(rng), rng);
      Pair q;
      if (tritri_test::scale_by_power_of_two(p, exponents[rng.uniform(0, 9)], q)) p = q;
      const Point& d = offsets[rng.uniform(0, 3)];
      for (Triangle* t : {&p.a, &p.b})  // rounded: the oracle judges the doubles as they are
        for (Point& v : *t)
          for (int k = 0; k < 3; ++k) v[k] += d[k];
      if (degenerate(p.a) || degenerate(p.b)) continue;
      ++judged;
      const bool m = meet(p);
      meeting += m;
      const bool apart = tritri::slabs_apart(slabs(p.a), slabs(p.b));
      ASSERT_EQ(apart, tritri::slabs_apart(slabs(p.b), slabs(p.a))) << gen.name;
      if (apart) {
        ++rejected;
        ASSERT_FALSE(m) << gen.name << ": rejected a pair that meets\n" << tritri_test::describe(p);
      }
    }
  }
  std::printf("judged %lld pairs, %lld meet, %lld rejected\n", judged, meeting, rejected);
  EXPECT_GT(meeting, judged / 4);  // the generators are mostly contacts
  EXPECT_GT(rejected, judged / 50);
}

// 2. a's corner v touches b, which lies in the plane n . x = n . v (n a three-coordinate
// direction) around v; a lies on the other side. Integer coordinates near 2^60 (spacing
// 2^8) keep every corner exact, while (x + y) + z rounds at 2^9 and 2^10.
TEST(DirectionSlabs, TouchingInAPlaneOfAThreeCoordinateDirection) {
  Rng rng(tritri_test::seed_for(0x7e1a));
  const std::array<std::array<int, 3>, 4> directions = {{{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}}};
  const int trials = static_cast<int>(tritri_test::scaled_count(20000));
  long long touching = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const auto& n = directions[rng.uniform(0, 3)];
    auto big = [&] { return std::ldexp(static_cast<double>((std::int64_t{1} << 51) + rng.uniform(0, 1 << 30)), 9); };
    const Point v = {big() * n[0], big() * n[1], big() * n[2]};
    auto small = [&] { return std::ldexp(static_cast<double>(rng.uniform(1, 1 << 12)), 8); };
    // e1, e2 with n . e = 0 (integers), e3 = -(e1 + e2): v is b's centroid, so inside b.
    const double s = small(), t = small(), u = small();
    const Point e1 = {s * n[0], -s * n[1], 0}, e2 = {0, t * n[1], -t * n[2]};
    const Point e3 = {-(e1[0] + e2[0]), -(e1[1] + e2[1]), -(e1[2] + e2[2])};
    Pair p;
    p.b = {tritri_test::add(v, e1), tritri_test::add(v, e2), tritri_test::add(v, e3)};
    // a: v and two corners on the far side of the plane (n . f1, n . f2 < 0).
    const Point f1 = {-u * n[0], -small() * n[1], 0}, f2 = {0, -small() * n[1], -u * n[2]};
    p.a = {v, tritri_test::add(v, f1), tritri_test::add(v, f2)};
    if (degenerate(p.a) || degenerate(p.b)) continue;
    ASSERT_TRUE(meet(p)) << "construction: v must lie in b\n" << tritri_test::describe(p);
    ++touching;
    ASSERT_FALSE(tritri::slabs_apart(slabs(p.a), slabs(p.b))) << tritri_test::describe(p);
  }
  EXPECT_GT(touching, trials / 2);
}

// 3.
TEST(DirectionSlabs, RejectLongThinTrianglesAcrossTheirBoxes) {
  // Two needles along (1,1,0), side by side: their boxes overlap almost entirely, their
  // slabs along (1,-1,0) are apart.
  const Triangle a = {{{0, 0, 0}, {100, 100, 0}, {100, 100.5, 1}}};
  const Triangle b = {{{0, 2, 0}, {100, 102, 0}, {99, 101.5, 1}}};
  EXPECT_TRUE(tritri::slabs_apart(slabs(a), slabs(b)));
  EXPECT_FALSE(meet({a, b}));
  // The same needles crossing: not apart.
  const Triangle c = {{{0, 100, 0}, {100, 0, 0}, {50, 50.5, 1}}};
  EXPECT_FALSE(tritri::slabs_apart(slabs(a), slabs(c)));
  EXPECT_TRUE(meet({a, c}));
}

// 4.
TEST(DirectionSlabs, OverflowingSumsGiveTheWholeLine) {
  const double big = std::numeric_limits<double>::max() / 2;
  const Triangle a = {{{big, big, big}, {big, 0, 0}, {0, big, 0}}};
  const Triangle b = {{{big, big, big}, {0, 0, big}, {big, 0, big}}};  // shares a corner with a
  const auto sa = slabs(a), sb = slabs(b);
  for (int d = 0; d < tritri::DirectionSlabs::kLanes; ++d) {
    EXPECT_FALSE(std::isnan(sa.lo[d]) || std::isnan(sa.hi[d])) << d;
    EXPECT_LE(sa.lo[d], sa.hi[d]) << d;
  }
  EXPECT_TRUE(meet({a, b}));
  EXPECT_FALSE(tritri::slabs_apart(sa, sb));
  // Far apart along x + y even at this scale: still rejected where the sums are finite.
  const Triangle c = {{{-big, -big / 2, 0}, {-big, -big / 2, 1}, {-big / 2, -big, 0}}};
  EXPECT_FALSE(meet({a, c}));
}

// 5.
TEST(DirectionSlabs, ExtentsContainTheExactExtents) {
  using Q = CGAL::Gmpq;
  Rng rng(tritri_test::seed_for(0xe87e));
  const int dirs[tritri::DirectionSlabs::kDirections][3] = {{1, 1, 0},  {1, -1, 0}, {0, 1, 1}, {0, 1, -1},
                                                            {1, 0, 1},  {1, 0, -1}, {1, 1, 1}, {1, 1, -1},
                                                            {1, -1, 1}, {-1, 1, 1}};
  auto coordinate = [&](int exponent) {
    const double m = rng.symmetric_unit();
    return rng.percent(10) ? 0.0 : std::ldexp(m, exponent);
  };
  const int trials = static_cast<int>(tritri_test::scaled_count(8000));
  long long finite = 0;
  for (int trial = 0; trial < trials; ++trial) {
    // One base exponent per triangle, each coordinate within 60 binades of it (so the sums
    // round), sometimes anywhere.
    const int base = rng.uniform(-1074, 1022);
    Triangle t;
    for (Point& v : t)
      for (double& x : v)
        x = coordinate(rng.percent(20) ? rng.uniform(-1074, 1023) : std::clamp(base + rng.uniform(-60, 0), -1074, 1023));
    // Half the time the corners are boxes around the points (as for implicit points).
    Triangle lo = t, hi = t;
    if (rng.percent(50))
      for (int k = 0; k < 3; ++k)
        for (int axis = 0; axis < 3; ++axis) {
          lo[k][axis] -= std::abs(coordinate(std::clamp(base - rng.uniform(0, 30), -1074, 1023)));
          hi[k][axis] += std::abs(coordinate(std::clamp(base - rng.uniform(0, 30), -1074, 1023)));
          if (!std::isfinite(lo[k][axis]) || !std::isfinite(hi[k][axis])) lo[k][axis] = hi[k][axis] = t[k][axis];
        }
    const auto e = tritri::detail::direction_extents(lo, hi);
    const auto s = lo == hi ? slabs(t) : tritri::direction_slabs(lo, hi);
    for (int d = 0; d < tritri::DirectionSlabs::kDirections; ++d) {
      Q least, greatest;  // over the 8 corners of each corner's box
      for (int c = 0; c < 3; ++c)
        for (int corner = 0; corner < 8; ++corner) {
          Q along = 0;
          for (int k = 0; k < 3; ++k) along += Q((corner >> k) & 1 ? hi[c][k] : lo[c][k]) * dirs[d][k];
          if ((c == 0 && corner == 0) || along < least) least = along;
          if ((c == 0 && corner == 0) || along > greatest) greatest = along;
        }
      if (std::isfinite(e.lo[d])) {
        ++finite;
        ASSERT_LE(Q(e.lo[d]), least) << "direction " << d << "\n" << tritri_test::to_hex(t);
      }
      if (std::isfinite(e.hi[d])) {
        ASSERT_GE(Q(e.hi[d]), greatest) << "direction " << d << "\n" << tritri_test::to_hex(t);
      }
      ASSERT_LE(static_cast<double>(s.lo[d]), e.lo[d]) << d;
      ASSERT_GE(static_cast<double>(s.hi[d]), e.hi[d]) << d;
    }
  }
  EXPECT_GT(finite, trials * 5LL);
}

// 6.
TEST(DirectionSlabs, CandidateTrianglePairsKeepEveryPairThatMeets) {
  Rng rng(tritri_test::seed_for(0xca9d));
  for (int soup = 0; soup < 6; ++soup) {
    std::vector<Point> V;
    std::vector<std::array<int, 3>> F;
    const int n = 150 + 50 * soup;
    for (int t = 0; t < n; ++t) {
      auto unit = [&] { return rng.symmetric_unit(); };
      const Point c = {5 + 5 * unit(), 5 + 5 * unit(), 5 + 5 * unit()};
      const Point d = {4 * unit(), 4 * unit(), 4 * unit()}, w = {0.02 * unit(), 0.02 * unit(), 0.02 * unit()};
      int first = static_cast<int>(V.size());
      if (t > 0 && rng.percent(20)) {
        first = F[rng.uniform(0, t - 1)][rng.uniform(0, 2)];  // a shared corner
      } else {
        V.push_back(tritri_test::sub(c, d));
      }
      V.push_back(tritri_test::add(c, d));
      V.push_back(tritri_test::add(tritri_test::add(c, d), w));
      const int m = static_cast<int>(V.size());
      F.push_back({first, m - 2, m - 1});
    }
    std::vector<std::pair<int, int>> meeting;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const Triangle a = {V[F[i][0]], V[F[i][1]], V[F[i][2]]}, b = {V[F[j][0]], V[F[j][1]], V[F[j][2]]};
        if (!degenerate(a) && !degenerate(b) && meet({a, b})) meeting.emplace_back(i, j);
      }
    const auto boxes = tritri::overlapping_triangle_pairs(V, F, 1);
    const auto candidates = tritri::candidate_triangle_pairs(V, V, F, 1);
    for (const auto& p : meeting)
      ASSERT_TRUE(std::binary_search(candidates.begin(), candidates.end(), p)) << p.first << " " << p.second;
    for (const auto& p : candidates) ASSERT_TRUE(std::binary_search(boxes.begin(), boxes.end(), p));
    ASSERT_TRUE(std::is_sorted(candidates.begin(), candidates.end()));
    EXPECT_LT(2 * candidates.size(), boxes.size()) << soup;
    for (int threads : {2, 0}) EXPECT_EQ(tritri::candidate_triangle_pairs(V, V, F, threads), candidates);
    std::printf("soup %d: %zu box pairs, %zu candidates, %zu meeting\n", soup, boxes.size(), candidates.size(),
                meeting.size());
  }
}

}  // namespace
