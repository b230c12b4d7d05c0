// Safe rounding's move limit (issue 14, arrangements/round_mesh.h,
// RoundSafeOptions::max_move_relative): no result moves a vertex by more than that
// fraction of the diagonal (or 16 ulps), and a caller may accept more. Generated input:
// two crossing spheres scaled by 2^-22 .. 2^-28 and moved to 1e6, from a few thousand ulps
// wide down to about a hundred (the sweep's `scaled` copies, bench/round_safe_sweep.py,
// are the shared meshes so treated). Every result, settled within whichever limit, is
// checked exactly: an arrangement (check_arrangement and arranging it again finds
// nothing), its reported move within the limit. The narrowest model is refused within
// the default limit, after few passes, and settles when the caller accepts the whole
// diagonal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/round_mesh.h"
#include "support/bounding_box.h"
#include "support/mesh_generators.h"

namespace {

using namespace arrangements;

// Two crossing spheres, every coordinate x replaced by x * 2^-e + 1e6 (in doubles).
TriangleSoup tiny_spheres_far_out(int e) {
  TriangleSoup s = concatenate(uv_sphere({0, 0, 0}, 1.0, 12, 24), uv_sphere({0.6, 0.25, 0.15}, 0.8, 12, 24));
  for (Vec3& v : s.vertices)
    for (double& c : v) c = std::ldexp(c, -e) + 1e6;
  return s;
}

// The rounded mesh is an arrangement: checked exactly, and arranging it again changes nothing.
void expect_arrangement(const RoundedMesh& r, const std::string& name) {
  const ArrangementCheck c = check_arrangement(r);
  EXPECT_TRUE(c.ok()) << name << ": " << (c.examples.empty() ? "" : c.examples.front());
  const ArrangeStats s = arrange(as_input(r), ArrangeOptions{}).stats;
  EXPECT_EQ(s.intersecting_pairs + s.intersection_points + s.merged_vertices, 0u) << name;
  EXPECT_EQ(s.removed_degenerate + s.removed_duplicate, 0u) << name;
  EXPECT_EQ(s.out_triangles, r.triangles.size()) << name;
}

TEST(RoundSafeMoveLimit, TinyModelsFarFromTheOriginStayWithinTheLimitTheCallerSets) {
  const double ulp = std::ldexp(1.0, -33);  // of 1e6 (2^19 <= 1e6 < 2^20)
  int refused_by_default = 0;
  for (int e : {22, 24, 26, 28}) {
    const TriangleSoup input = tiny_spheres_far_out(e);
    const ArrangeResult exact = arrange(input, ArrangeOptions{});
    ASSERT_GT(exact.stats.intersecting_pairs, 0u) << e;
    const double diagonal = bounding_box(input.vertices).diagonal();
    for (double fraction : {1.0 / 64, 1.0}) {
      const std::string name = "2^-" + std::to_string(e) + " within " + std::to_string(fraction);
      RoundReport report;
      try {
        const RoundedMesh r =
            round_safe(exact.mesh, RoundSafeOptions{.max_move_relative = fraction, .input = &input}, &report);
        expect_arrangement(r, name);
        EXPECT_LE(report.max_move, std::max(fraction * diagonal, 16 * ulp) * (1 + 1e-9)) << name;
        std::printf("%s: %d passes, move %.3g of the diagonal (%.0f ulps wide)\n", name.c_str(), report.passes,
                    report.max_move_relative, diagonal / ulp);
      } catch (const RoundingError&) {
        std::printf("%s: refused after %d passes (%.0f ulps wide)\n", name.c_str(), report.passes, diagonal / ulp);
        EXPECT_EQ(fraction, 1.0 / 64) << name << ": refused with the whole diagonal allowed";
        // Every step stops once its move exceeds the limit, before arranging: a refusal
        // spends few passes (50 when only the results were checked against the limit).
        EXPECT_LE(report.passes, 32) << name;
        ++refused_by_default;
      }
    }
  }
  // The narrowest (2^-28: about 150 ulps wide) needs a move of about a sixth of it.
  EXPECT_GE(refused_by_default, 1);
}

TEST(RoundSafeMoveLimit, LimitsThatAreNotFiniteNumbersAboveZeroAreRefused) {
  const TriangleSoup input = tiny_spheres_far_out(22);
  const ArrangeResult exact = arrange(input, ArrangeOptions{});
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(round_safe(exact.mesh, RoundSafeOptions{.max_move_relative = bad}), std::invalid_argument) << bad;
}

}  // namespace
