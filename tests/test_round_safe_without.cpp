// RoundSafeOptions::without (arrange --round-without), the switch behind the study of what
// each step of round_safe's ladder settles that no other does (docs/ROUNDING.md): leaving
// out the step that settles a mesh makes round_safe refuse it, with the left-out steps
// named in the message, or settle it by a later step that the report shows; leaving out
// steps the ladder never reaches changes nothing, byte for byte. The meshes are the
// rotated copies of test_round_safe.cpp whose settling step is known.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "arrangements/arrange.h"
#include "arrangements/round_mesh.h"
#include "support/mesh_generators.h"

namespace {

using namespace arrangements;


// round_safe of `exact` with `without`; the message of its RoundingError, "" when it settles.
std::string rounding_refusal(const OutputMesh& exact, const TriangleSoup& input, unsigned without, RoundedMesh& out,
                             RoundReport& report) {
  try {
    out = round_safe(exact, RoundSafeOptions{.input = &input, .without = without}, &report);
    return "";
  } catch (const RoundingError& e) {
    return e.what();
  }
}

// The soup's arrangement, rounded with every step (refusal "" when it settles).
struct WithAllSteps {
  ArrangeResult first;
  RoundedMesh mesh;
  RoundReport report;
  std::string refusal;
};
WithAllSteps round_with_all_steps(const TriangleSoup& soup) {
  WithAllSteps all{arrange(soup, ArrangeOptions{}), {}, {}, {}};
  all.refusal = rounding_refusal(all.first.mesh, soup, 0, all.mesh, all.report);
  return all;
}

// The list after "Tried: " in a refusal, up to the move limit ("" when there is none).
std::string tried_steps(const std::string& refusal) {
  const std::size_t begin = refusal.find("Tried: "), end = refusal.find("; move limit");
  if (begin == std::string::npos || end == std::string::npos || end < begin) return "";
  return refusal.substr(begin + 7, end - begin - 7);
}

TEST(RoundSafeWithout, EveryStepHasOneDistinctName) {
  for (std::size_t i = 0; i < kRoundSteps; ++i) {
    EXPECT_FALSE(kRoundStepNames[i].empty());
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(kRoundStepNames[i], kRoundStepNames[j]);
  }
  EXPECT_EQ(kRoundStepNames[static_cast<std::size_t>(RoundStep::nudging)], "nudging");
}

TEST(RoundSafeWithout, LeavingOutNudgingRefusesWhatOnlyNudgingSettles) {
  // Three copies of a 10 x 21 sphere turned about one axis: only nudging settles them
  // (test_round_safe.cpp, GrazingLayersOfThreeCopiesWith21MeridiansSettleByNudging).
  const TriangleSoup soup = rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 21), 3);
  const WithAllSteps all = round_with_all_steps(soup);
  ASSERT_EQ(all.refusal, "");
  ASSERT_GT(all.report.nudged, 0u);
  RoundedMesh without;
  RoundReport without_report;
  const std::string refusal =
      rounding_refusal(all.first.mesh, soup, round_step_bit(RoundStep::nudging), without, without_report);
  EXPECT_NE(refusal.find("; left out: nudging"), std::string::npos) << refusal;
  // What it tried names rerouting and the grid, not the step left out.
  const std::string tried = tried_steps(refusal);
  EXPECT_NE(tried.find("rerouting"), std::string::npos) << refusal;
  EXPECT_NE(tried.find("the grid of 2^8 ulps"), std::string::npos) << refusal;
  EXPECT_EQ(tried.find("nudging"), std::string::npos) << refusal;
  EXPECT_EQ(without_report.nudged, 0u);
  EXPECT_GT(without_report.conflicts_left, 0u);
  std::printf("10 x 21 copies without nudging: %d passes, then refused with %zu conflicts left\n",
              without_report.passes, without_report.conflicts_left);
}

TEST(RoundSafeWithout, StepsNotReachedChangeNothing) {
  // Two copies of a 10 x 19 sphere turned by pi: rerouting's cycles settle them, so the
  // steps after rerouting are never reached, and leaving them out gives the same mesh.
  const TriangleSoup soup = rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 19), 2);
  const WithAllSteps all = round_with_all_steps(soup);
  ASSERT_EQ(all.refusal, "");
  ASSERT_GT(all.report.rerouted, 0u);
  ASSERT_EQ(all.report.nudged, 0u);
  RoundedMesh without;
  RoundReport without_report;
  const unsigned later = round_step_bit(RoundStep::merged_input) | round_step_bit(RoundStep::snapped_layers) |
                         round_step_bit(RoundStep::snapped_contacts) | round_step_bit(RoundStep::level_1) | round_step_bit(RoundStep::nudging);
  ASSERT_EQ(rounding_refusal(all.first.mesh, soup, later, without, without_report), "");
  EXPECT_EQ(without.vertices, all.mesh.vertices);
  EXPECT_EQ(without.triangles, all.mesh.triangles);
  EXPECT_EQ(without.source, all.mesh.source);
  EXPECT_EQ(without_report.passes, all.report.passes);
  EXPECT_EQ(without_report.max_move, all.report.max_move);
  // Without rerouting (and so nudging), a later step settles it with no vertex rerouted,
  // or nothing does and the refusal names both.
  const std::string refusal =
      rounding_refusal(all.first.mesh, soup, round_step_bit(RoundStep::rerouting), without, without_report);
  EXPECT_EQ(without_report.rerouted, 0u);
  EXPECT_EQ(without_report.nudged, 0u);
  if (!refusal.empty()) {
    EXPECT_NE(refusal.find("; left out: rerouting"), std::string::npos) << refusal;
    // Neither rerouting nor nudging (which starts from rerouting's best) was tried.
    EXPECT_EQ(tried_steps(refusal).find("rerouting"), std::string::npos) << refusal;
    EXPECT_EQ(tried_steps(refusal).find("nudging"), std::string::npos) << refusal;
  } else {
    EXPECT_NE(without.vertices, all.mesh.vertices);
  }
  std::printf("10 x 19 turned by pi without rerouting: %s after %d passes\n", refusal.empty() ? "settled" : "refused",
              without_report.passes);
}

}  // namespace
