// The cycles of round_safe's ladder (Ladder, round_ladder.h): rerouting's (step 3) and
// nudging's (step 7). Both alternate a last resort that makes no new points with arranging
// again, where the crossings its rounding left become points; their results keep the
// ladder's invariant through Ladder::finish. Included by whoever runs a Ladder.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "arrangements/arrange_stats.h"
#include "rounding/arrange_locally.h"
#include "rounding/ladder_limits.h"
#include "rounding/mesh_on_positions.h"
#include "rounding/round_ladder.h"
#include "rounding/round_nudged.h"
#include "rounding/round_rerouting.h"
#include "rounding/round_to_grid.h"

namespace arrangements::detail {

// The step the cycles of rerouting and of nudging share: `m` arranged again (a pass; the
// crossings its rounding left become points) and rounded to nearest, new points within
// an ulp snapped to a double vertex as the passes do; `move` receives the rounding's.
template <class Mesh>
RoundedMesh Ladder<Mesh>::arrange_and_round(const RoundedMesh& m, double& move) {
  ++r_.passes;
  const RoundedMesh clean = mesh_on_positions(m, options_.keep_closed);
  ArrangeStats again;
  return round_to_grid(arrange_locally(clean, tracker_.violations(clean), arrange_options_, again), 0, ulp_, move);
}

// Rerouting of `m` (round_rerouting.h) within max_rounds, and its best mesh.
template <class Mesh>
auto Ladder<Mesh>::reroute(const RoundedMesh& m, int max_rounds) -> Rerouted {
  Rerouting now = reroute_conflicts(m.vertices, m.triangles, m.source, m.label_set, m.label_sets, ulp_, max_rounds,
                                    tracker_, options_.keep_closed);
  r_.passes += now.rounds;
  RoundedMesh best =
      mesh_on_positions(m.vertices, now.triangles, now.source, now.label_set, now.label_sets, options_.keep_closed)
          .mesh;
  return {std::move(now), std::move(best)};
}

// Rerouting, in cycles: when one stalls, its best mesh is arranged again and rounded
// (arrange_and_round), and rerouting goes on from there. The bound adds each cycle's
// rounding move and an ulp per round of its rerouting. Keeps the cycle that left the
// fewest conflicts (for nudging).
template <class Mesh>
auto Ladder<Mesh>::reroute_in_cycles() -> Found {
  // The first cycle starts from the arrangement on its nearest doubles (the exact vertices
  // give its move; only rerouting needs either, so they are made here).
  std::vector<ExactVec3> exact;
  std::vector<Vec3> nearest;
  exact_and_nearest(mesh_, exact, nearest);
  double cycle_move = largest_distance(exact, nearest);
  RoundedMesh cycle_mesh{std::move(nearest), mesh_.triangles, mesh_.source, mesh_.label_set, mesh_.label_sets};
  std::size_t rerouted = 0;
  // Rerouting stops at kReroutePasses, leaving the rest of the budget to the steps below.
  const int reroute_limit = std::min(budget_, kReroutePasses);
  for (int cycle = 0; cycle < kRerouteCycles && r_.passes < reroute_limit; ++cycle) {
    Rerouted now = reroute(cycle_mesh, reroute_limit - r_.passes);
    rerouted += now.rerouting.rerouted;
    // Each round of rerouting moves the surface by an ulp at most (a vertex put on an
    // edge or a face lies within an ulp of it): rounds x ulp bounds the cycle's move.
    if (now.rerouting.rerouted > 0) cycle_move += ulp_ * now.rerouting.rounds;
    const std::size_t violations = now.rerouting.violations;
    closer(violations);
    // A cycle that leaves no fewer conflicts than the best one before it, when that left
    // many, means arranging again recreates what rerouting removes: on sphere_copies_4
    // the later cycles only swung upwards (2,574, 1,244, then 2,114, 5,026, 5,249,
    // 5,724), so they stop there. With a few left, cycles walk and often end at none
    // (sphere2 turned by pi: 6, 5, 5, then none): they go on.
    const bool no_fewer_than_best =
        fewest_ && violations >= fewest_violations_ && fewest_violations_ > kStopCyclesAbove;
    if (violations > 0 && (!fewest_ || violations < fewest_violations_)) {
      fewest_ = now.mesh;
      fewest_violations_ = violations;
      fewest_move_ = cycle_move;
      fewest_rerouted_ = rerouted;
      fewest_cycles_ = cycle;
    }
    const std::size_t triangles = now.mesh.triangles.size();
    RoundedMesh best = std::move(now.mesh);
    if (violations == 0) {
      r_.rerouted = rerouted;
      if (auto done = finish(std::move(best), cycle_move, 0.0)) return done;
      r_.rerouted = 0;
      return std::nullopt;
    }
    // Arranging again pays only for few conflicts; a cycle that grows the mesh by more
    // than a tenth feeds on itself.
    if (no_fewer_than_best || !few_conflicts(violations, triangles) ||
        triangles > mesh_.triangles.size() + mesh_.triangles.size() / 10 ||
        r_.passes >= reroute_limit || cycle_move > move_limit_)
      return std::nullopt;
    ++r_.reroute_cycles;
    double move_now = 0;
    cycle_mesh = arrange_and_round(best, move_now);
    cycle_move += move_now;
  }
  return std::nullopt;
}

// Nudging (round_nudged.h), when every other step failed: the corners of the conflicts
// that rerouting's best cycle left, moved by 1 to 1024 ulps one at a time where that
// leaves fewer (a grazing crossing far from any vertex, which no grid holds). In cycles,
// as rerouting's: where nudging stalls, its mesh is arranged again and rounded
// (arrange_and_round), rerouted and nudged again; each cycle adds its rounding move, an
// ulp per round of rerouting and its nudges to the bound.
template <class Mesh>
auto Ladder<Mesh>::nudge_in_cycles() -> Found {
  if (!fewest_ || !nudgeable(fewest_violations_, fewest_->triangles.size()) || fewest_move_ >= move_limit_)
    return std::nullopt;
  RoundedMesh start = std::move(*fewest_);
  double nudge_move = fewest_move_;
  std::size_t rerouted = fewest_rerouted_, nudged_vertices = 0;
  int cycles = fewest_cycles_;
  const std::size_t most_triangles = start.triangles.size() + start.triangles.size() / 10;
  auto settle_nudged = [&](RoundedMesh rounded) -> Found {
    const RoundReport before = r_;
    r_.rerouted = rerouted;
    r_.reroute_cycles = cycles;
    r_.nudged = nudged_vertices;
    if (auto done = finish(std::move(rounded), nudge_move, 0.0)) return done;
    r_ = before;
    return std::nullopt;
  };
  const int max_passes = options_.max_passes;
  for (int cycle = 0; cycle < kNudgeCycles && r_.passes < max_passes && nudge_move < move_limit_; ++cycle) {
    Nudged nudged = nudge_conflicts(start, ulp_, move_limit_ - nudge_move, max_passes - r_.passes);
    r_.passes += nudged.rounds;
    closer(nudged.violations);
    nudged_vertices += nudged.moved;
    nudge_move += nudged.max_move;
    if (nudged.violations == 0) return settle_nudged(std::move(nudged.mesh));
    // Arranging again is a pass, and rerouting needs a round after it.
    if (!nudgeable(nudged.violations, nudged.mesh.triangles.size()) || r_.passes + 1 >= max_passes)
      return std::nullopt;
    ++cycles;
    double rounding = 0;
    const RoundedMesh again = arrange_and_round(nudged.mesh, rounding);
    nudge_move += rounding;
    if (again.triangles.size() > most_triangles || nudge_move >= move_limit_) return std::nullopt;
    Rerouted now = reroute(again, max_passes - r_.passes);
    rerouted += now.rerouting.rerouted;
    if (now.rerouting.rerouted > 0) nudge_move += ulp_ * now.rerouting.rounds;
    start = std::move(now.mesh);
    closer(now.rerouting.violations);
    if (now.rerouting.violations == 0) return settle_nudged(std::move(start));
  }
  return std::nullopt;
}

}  // namespace arrangements::detail
