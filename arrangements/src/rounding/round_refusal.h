// refusal_message: what round_safe (arrangements/round_mesh.h) says when no step settled the
// rounding within the move limit: how close the best attempt came, what the last pass of
// rounding and arranging found, which steps were tried, and the limits they ran under.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "arrangements/arrange_stats.h"
#include "arrangements/round_mesh.h"

namespace arrangements {

struct RefusalFacts {
  std::size_t conflicts_left = 0;  // the fewest violating pairs a last resort left (0: none ran)
  ArrangeStats last{};             // what the last pass's arrangement found
  int last_level = 0;              // that pass's grid level (0: the nearest doubles)
  bool input_steps = false;        // whether the input was given (merging, snapping were tried)
  double move_limit_ulps = 0;      // the move limit, in ulps of the largest coordinate magnitude
  double max_move_relative = 0;    // the caller's limit, as a fraction of the diagonal
  double diagonal_ulps = 0;        // the exact arrangement's diagonal, in the same ulps
  int passes = 0;                  // passes and rounds spent
  int max_passes = 0;              // the caller's budget of them
  unsigned without = 0;            // the steps left out (RoundSafeOptions::without)
};

namespace detail {

// x with 6 significant digits ("0.015625", "3046.9", "1e-05").
inline std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// "; left out: rerouting, nudging" for the steps of `without` ("" for none).
inline std::string left_out(unsigned without) {
  std::string names;
  for (std::size_t k = 0; k < kRoundSteps; ++k)
    if (leaves_out(without, static_cast<RoundStep>(k))) names += (names.empty() ? "; left out: " : ", ") + std::string(kRoundStepNames[k]);
  return names;
}

// "rerouting (...), ..., nudging": the steps after the passes at the nearest doubles that
// ran, in the ladder's order (round_ladder.h): none that `without` leaves out, the input
// steps only with the input, nudging only after rerouting (it starts from rerouting's best).
inline std::string steps_tried(bool input_steps, unsigned without) {
  const auto used = [without](RoundStep step) { return !leaves_out(without, step); };
  std::string names;
  const auto add = [&names](const char* name) { names += (names.empty() ? "" : ", ") + std::string(name); };
  if (used(RoundStep::rerouting)) add("rerouting (it stops after 3 rounds without fewer violations)");
  if (input_steps && used(RoundStep::merged_input)) add("merging input vertices (within 4 to 256 ulps)");
  if (input_steps && used(RoundStep::snapped_layers)) add("snapping nearly coplanar faces");
  if (input_steps && used(RoundStep::snapped_contacts)) add("snapping corners onto faces they touch");
  if (used(RoundStep::level_1)) add("the grid of 2^8 ulps");
  if (used(RoundStep::rerouting) && used(RoundStep::nudging)) add("nudging");
  return names.empty() ? "nothing after the passes at the nearest doubles" : names;
}

}  // namespace detail

inline std::string refusal_message(const RefusalFacts& f) {
  using detail::left_out;
  using detail::short_number;
  const std::string closest =
      f.conflicts_left > 0 ? "the closest attempt left " + std::to_string(f.conflicts_left) +
                                 " pairs of triangles meeting beyond their shared vertices and edges"
                           : "no attempt came close";
  const std::string grid = f.last_level == 0 ? std::string("the nearest doubles")
                                             : "the grid of 2^" + std::to_string(8 * f.last_level) + " ulps";
  return "round_safe: no rounding within the move limit keeps the mesh an arrangement (" + closest +
         "). The last pass of rounding and arranging, on " + grid + ", found " +
         std::to_string(f.last.intersecting_pairs) + " intersecting pairs, merged " +
         std::to_string(f.last.merged_vertices) + " vertices and removed " +
         std::to_string(f.last.removed_degenerate + f.last.removed_duplicate) +
         " degenerate or duplicate triangles. Tried: " + detail::steps_tried(f.input_steps, f.without) +
         "; move limit " + short_number(f.move_limit_ulps) + " ulps (max_move_relative " +
         short_number(f.max_move_relative) + " of the diagonal of " + short_number(f.diagonal_ulps) +
         " ulps, or 16 ulps); " + std::to_string(f.passes) + " passes and rounds in all (at most " +
         std::to_string(f.max_passes) + ")" + left_out(f.without);
}

}  // namespace arrangements
