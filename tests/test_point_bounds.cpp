// Specification of tritri/point_bounds.h, against exact rationals:
// - x_bounds(p) contains the exact x of every point, and direction_bounds(p) the exact
//   kSortDirection . p (explicit, LPI and TPI points of generated scenes: planes, lines,
//   coincident points built several ways, grid crossings, random points, then exact maps
//   from subnormal to near DBL_MAX);
// - compare_xyz_bounded equals compare_xyz;
// - compare_along_direction is the exact order (kSortDirection . p, ties by xyz order)
//   computed from the rationals: antisymmetric, 0 exactly for coincident points, and
//   consistent with that definition on every pair tried;
// - the bounds decide most pairs (a useful filter) but never when points coincide;
// - box_bounds(p) contains the exact point, and orient2d_bounded(a, b, box, plane), when it
//   decides, is the exact sign of orient2d(a, b, p) in that plane (for every plane, a and b
//   the scene's explicit points), deciding most of them.
// Cases at TRITRI_TEST_SCALE=1: 200,000 points and 400,000 pairs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <tritri/point_bounds.h>
#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/implicit_recipes.h"
#include "support/implicit_scenes.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using P = std::array<double, 3>;
using tritri_test::Q;
using tritri_test::Q3;

Q along(const Q3& p) {
  const auto& d = tritri::kSortDirection;
  return Q(d[0]) * p[0] + Q(d[1]) * p[1] + Q(d[2]) * p[2];
}

int sign_of(const Q& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

// The order of compare_along_direction, from its definition in rationals.
int exact_order(const Q3& p, const Q3& q) {
  const int s = sign_of(along(p) - along(q));
  if (s != 0) return s;
  for (int k = 0; k < 3; ++k)
    if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
  return 0;
}

// (-inf, +inf) is the "unknown" interval; GMP cannot hold infinities.
bool contains(const tritri::XBounds& b, const Q& v) {
  return (std::isinf(b.lo) || Q(b.lo) <= v) && (std::isinf(b.hi) || v <= Q(b.hi));
}

TEST(PointBounds, IntervalsContainTheExactValues) {
  long long points = 0, finite = 0;
  tritri_test::run_scenes(
      101, tritri_test::scaled_count(200000), [&](const tritri_test::Scene& s, tritri_test::Rng&, long long left) {
        long long n = 0;
        for (const auto& sample : s.points) {
          if (n >= left) break;
          ++n;
          const tritri::XBounds xb = tritri::x_bounds(sample.point), db = tritri::direction_bounds(sample.point);
          EXPECT_TRUE(contains(xb, sample.exact[0])) << tritri_test::describe(sample.recipe);
          EXPECT_TRUE(contains(db, along(sample.exact))) << tritri_test::describe(sample.recipe);
          finite += std::isfinite(db.lo) && std::isfinite(db.hi);
        }
        points += n;
        return n;
      });
  // Useful: most points get a finite interval (the rest are scenes mapped near DBL_MAX or
  // into the subnormals, where the cached filter itself overflows or underflows).
  EXPECT_GT(finite, points * 3 / 4) << finite << " of " << points;
}

TEST(PointBounds, ComparisonsAreTheExactOrders) {
  long long pairs = 0, equal = 0, decided_by_bounds = 0;
  tritri_test::run_scenes(
      102, tritri_test::scaled_count(400000), [&](const tritri_test::Scene& s, tritri_test::Rng& rng, long long left) {
        const int m = static_cast<int>(s.points.size());
        std::vector<tritri::XBounds> xb(m), db(m);
        for (int i = 0; i < m; ++i) {
          xb[i] = tritri::x_bounds(s.points[i].point);
          db[i] = tritri::direction_bounds(s.points[i].point);
        }
        long long n = 0;
        for (; n < left && n < 4 * m; ++n) {
          // Half the pairs from one coincidence group when there is one (equal points).
          int i = rng.uniform(0, m - 1), j = rng.uniform(0, m - 1);
          for (const auto& g : s.groups)
            if (n % 2 == 0 && g.members.size() >= 2 && rng.percent(30)) {
              i = g.members[rng.uniform(0, static_cast<int>(g.members.size()) - 1)];
              j = g.members[rng.uniform(0, static_cast<int>(g.members.size()) - 1)];
              break;
            }
          const auto &a = s.points[i], &b = s.points[j];
          const int want = exact_order(a.exact, b.exact);
          const int got = tritri::compare_along_direction(a.point, db[i], b.point, db[j]);
          EXPECT_EQ(got, want) << tritri_test::describe(a.recipe) << " vs " << tritri_test::describe(b.recipe);
          EXPECT_EQ(tritri::compare_along_direction(b.point, db[j], a.point, db[i]), -want);
          EXPECT_EQ(tritri::compare_xyz_bounded(a.point, xb[i], b.point, xb[j]), tritri::compare_xyz(a.point, b.point));
          if (::testing::Test::HasFailure()) return n + 1;
          equal += want == 0;
          const bool by_bounds = db[i].hi < db[j].lo || db[j].hi < db[i].lo;
          if (want == 0) {
            EXPECT_FALSE(by_bounds);
          }
          decided_by_bounds += by_bounds;
        }
        pairs += n;
        return n;
      });
  EXPECT_GT(equal, 0) << "no coincident pair was generated";
  // A useful filter: most pairs of distinct points are settled by the bounds alone.
  EXPECT_GT(decided_by_bounds, (pairs - equal) / 2) << decided_by_bounds << " of " << pairs - equal;
}

TEST(PointBounds, BoxesContainThePointsAndDecideOrient2dExactly) {
  long long tests = 0, decided = 0;
  tritri_test::run_scenes(
      103, tritri_test::scaled_count(200000), [&](const tritri_test::Scene& s, tritri_test::Rng& rng, long long left) {
        std::vector<int> explicit_points;
        for (int i = 0; i < static_cast<int>(s.points.size()); ++i)
          if (s.points[i].point.is_explicit()) explicit_points.push_back(i);
        if (explicit_points.size() < 2) return 0LL;
        long long n = 0;
        for (const auto& sample : s.points) {
          if (n >= left) break;
          const tritri::BoxBounds box = tritri::box_bounds(sample.point);
          for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(contains(box[k], sample.exact[k]))
                << "axis " << k << ": " << tritri_test::describe(sample.recipe);
          const auto& a = s.points[explicit_points[rng.uniform(0, static_cast<int>(explicit_points.size()) - 1)]];
          const auto& b = s.points[explicit_points[rng.uniform(0, static_cast<int>(explicit_points.size()) - 1)]];
          for (tritri::Plane plane : {tritri::Plane::XY, tritri::Plane::YZ, tritri::Plane::ZX}) {
            const int i = plane == tritri::Plane::XY ? 0 : (plane == tritri::Plane::YZ ? 1 : 2), j = (i + 1) % 3;
            const int want = sign_of((b.exact[i] - a.exact[i]) * (sample.exact[j] - a.exact[j]) -
                                     (b.exact[j] - a.exact[j]) * (sample.exact[i] - a.exact[i]));
            const int got = tritri::orient2d_bounded(a.point.approx(), b.point.approx(), box, plane);
            ++tests;
            if (got == tritri::kUndecided) continue;
            ++decided;
            EXPECT_EQ(got, want) << tritri_test::describe(sample.recipe) << " plane " << i;
            if (want == 0) {
              EXPECT_TRUE(sample.point.is_explicit()) << "a zero certified for a box that is not a point";
            }
          }
          ++n;
          if (::testing::Test::HasFailure()) return n;
        }
        return n;
      });
  EXPECT_GT(decided, tests / 2) << decided << " of " << tests;
}

// Distinct points sharing x, or x and y, exactly (grids, copies about an axis): the
// direction separates them with the bounds; compare_xyz needs the exact stage there.
TEST(PointBounds, SharedCoordinatesAreSeparatedAlongTheDirection) {
  long long separated = 0, total = 0;
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = 0; z < 4; ++z) {
        // An LPI at (x, y, z + 1/3): the vertical line through (x, y) cut by a plane z = const.
        const double c = z + 1.0 / 3.0;
        const auto p = ImplicitPoint::lpi(P{double(x), double(y), -10.0}, P{double(x), double(y), 10.0}, P{0.0, 0.0, c},
                                          P{1.0, 0.0, c}, P{0.0, 1.0, c});
        const auto q = ImplicitPoint::lpi(P{double(x), double(y), -10.0}, P{double(x), double(y), 10.0},
                                          P{0.0, 0.0, c + 1}, P{1.0, 0.0, c + 1}, P{0.0, 1.0, c + 1});
        const auto bp = tritri::direction_bounds(p), bq = tritri::direction_bounds(q);
        ++total;
        separated += bp.hi < bq.lo || bq.hi < bp.lo;
        EXPECT_EQ(tritri::compare_along_direction(p, bp, q, bq), -1);
        EXPECT_EQ(tritri::compare_xyz(p, q), -1);
      }
  EXPECT_EQ(separated, total);
}

}  // namespace
