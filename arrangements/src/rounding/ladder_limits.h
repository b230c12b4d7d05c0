// Ladder limits (arrangements::detail): the budgets, level spacings and conflict
// thresholds the steps of the rounding ladder (round_ladder.h) share.
#pragma once

#include <cstddef>

#include "rounding/rounding_grid.h"

namespace arrangements::detail {

// Rounding levels: level 0 rounds to the nearest double; level 1 to the uniform grid of
// spacing 2^8 units in the last place of the largest coordinate magnitude. A uniform grid,
// unlike the doubles, is as coarse near zero as anywhere: features thinner than a cell (a
// sliver, two surfaces 1e-33 apart near a zero coordinate) collapse instead of crossing
// again after every pass. (Levels 2-4, grids of 2^16 to 2^32 ulps, settled nothing that
// the other steps do not: docs/ROUNDING.md.)
constexpr int kLevels = 2;
constexpr int kPassesPerLevel = 4;
constexpr int kRerouteCycles = 8;
// Rerouting's cycles stop at one that leaves no fewer conflicts than the best before it
// when that best left more than this; with no more, they go on (their walk often ends at
// none).
constexpr std::size_t kStopCyclesAbove = 64;
constexpr int kReroutePasses = 64;  // passes and rounds of round_safe when its rerouting stops
constexpr int kInputBudget = 32;  // passes and rounds of round_safe on each changed input
constexpr int kNudgeRounds = 64;  // kept for nudging (in cycles) on each changed input, beyond its kInputBudget
constexpr int kNudgeCycles = 8;   // nudgings, each after the last one's mesh was arranged again

// Conflicts few enough to arrange again (rerouting's and nudging's cycles): on at most a
// 20th of the triangles. Where they are more (layers that nearly coincide over whole
// faces), arranging again makes as many new ones.
inline bool few_conflicts(std::size_t violations, std::size_t triangles) { return violations <= triangles / 20; }

// Conflicts nudging takes on: few, or up to kNudgeAnyMesh on a small mesh. Nudging weighs
// 286 positions per corner; on more it would take minutes to leave as many.
constexpr std::size_t kNudgeAnyMesh = 1024;
inline bool nudgeable(std::size_t violations, std::size_t triangles) {
  return violations <= kNudgeAnyMesh || few_conflicts(violations, triangles);
}

inline double level_spacing(double largest, int level) { return level == 0 ? 0 : grid_spacing(largest, 8 * level); }

}  // namespace arrangements::detail
