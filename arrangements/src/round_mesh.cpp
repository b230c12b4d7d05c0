// round_nearest / round_safe (arrangements/round_mesh.h): rounding the exact arrangement to
// doubles, and the passes of rounding and re-arranging that keep it an arrangement.
#include "arrangements/round_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <tritri/implicit_point.h>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "round_merged_input.h"
#include "round_snapped_planes.h"
#include "round_nudged.h"
#include "round_per_vertex.h"
#include "round_refusal.h"
#include "round_rerouting.h"
#include "round_to_grid.h"
#include "support/bounding_box.h"
#include "support/mesh_on_positions.h"
#include "support/rounding_grid.h"
#include "support/vertex_coordinates.h"

namespace arrangements {
namespace {

using detail::double_coordinates;
using detail::round_to_grid;

// Rounding levels: level 0 rounds to the nearest double; level j >= 1 to the uniform grid of
// spacing 2^(8j) units in the last place of the largest coordinate magnitude. A uniform grid,
// unlike the doubles, is as coarse near zero as anywhere: features thinner than a cell (a
// sliver, two surfaces 1e-33 apart near a zero coordinate) collapse instead of crossing
// again after every pass.
constexpr int kLevels = 5;
constexpr int kPassesPerLevel = 4;
constexpr int kRerouteCycles = 8;
constexpr int kReroutePasses = 64;  // passes and rounds of round_safe when its rerouting stops
constexpr int kInputBudget = 32;  // passes and rounds of round_safe on each changed input
constexpr int kNudgeRounds = 64;  // kept for nudging (in cycles) on each changed input, beyond its kInputBudget
constexpr int kNudgeCycles = 8;   // nudgings, each after the last one's mesh was arranged again

// Conflicts few enough to arrange again (rerouting's and nudging's cycles): on at most a
// 20th of the triangles. Where they are more (layers that nearly coincide over whole
// faces), arranging again makes as many new ones.
bool few_conflicts(std::size_t violations, std::size_t triangles) { return violations <= triangles / 20; }

// Conflicts nudging takes on: few, or up to kNudgeAnyMesh on a small mesh. Nudging weighs
// 286 positions per corner; on more it would take minutes to leave as many.
constexpr std::size_t kNudgeAnyMesh = 1024;
bool nudgeable(std::size_t violations, std::size_t triangles) {
  return violations <= kNudgeAnyMesh || few_conflicts(violations, triangles);
}

double level_spacing(double largest, int level) { return level == 0 ? 0 : grid_spacing(largest, 8 * level); }

// True when arranging changed nothing: the mesh was an arrangement already.
bool unchanged(const ArrangeStats& s) {
  return s.intersecting_pairs == 0 && s.merged_vertices == 0 && s.removed_degenerate == 0 &&
         s.removed_duplicate == 0 && s.out_vertices == s.in_vertices && s.out_triangles == s.in_triangles;
}

// move_cap: the largest move the caller accepts (a changed input's limit less the change's
// own move; infinity from round_safe). Every step stops as soon as its move exceeds the
// limit: its result would be refused (this is what makes a refusal cheap).
// nudge_reserve: the last passes of options.max_passes kept for nudging, the last step (a
// changed input's ladder gets its passes and these on top); below options.max_passes.
// levels: the grid levels tried (kLevels; a changed input's ladder stops after level 1:
// the coarser ones move every vertex by 2^16 ulps or more, far more than the change, and
// the ladder above tries them itself, each after merging the input at its scale).
template <class Mesh>
RoundedMesh round_in_passes(const Mesh& mesh, const RoundSafeOptions& options, RoundReport* report,
                            double move_cap, int nudge_reserve, int levels) {
  if (options.max_passes < 1)
    throw std::invalid_argument("round_safe: max_passes must be at least 1, got " +
                                std::to_string(options.max_passes));
  if (!(options.max_move_relative > 0) || !std::isfinite(options.max_move_relative))
    throw std::invalid_argument("round_safe: max_move_relative must be a finite number above 0, got " +
                                std::to_string(options.max_move_relative));
  const int budget = options.max_passes - nudge_reserve;  // before nudging
  ArrangeOptions arrange_options;
  arrange_options.threads = options.threads;
  double move = 0;
  RoundReport r;
  ArrangeStats last{};  // what the latest pass's arrangement found
  int last_level = 0;   // the grid level of that pass
  const RoundedMesh nearest = round_to_grid(mesh, 0, 0, move);
  const double largest = largest_magnitude(nearest.vertices);
  const double ulp = level_spacing(largest, 1) / 256;
  // A result that moves a vertex by more than a 64th of the arrangement's diagonal (by
  // default: options.max_move_relative) is not a rounding of it (a grid or merge distance
  // as wide as the model collapses it, to nothing at worst): every step's result is refused
  // beyond that, and the next step tried. A model only a few ulps wide may move by 16 ulps
  // (rounding to nearest moves it by one), but not vanish.
  const double diagonal = bounding_box(nearest.vertices).diagonal();
  const double move_limit = std::min(std::max(diagonal * options.max_move_relative, 16 * ulp), move_cap);
  auto finish = [&](RoundedMesh rounded, double max_move, double grid) -> std::optional<RoundedMesh> {
    if (max_move > move_limit || (rounded.triangles.empty() && !mesh.triangles.empty())) return std::nullopt;
    r.grid = grid;
    r.max_move = max_move;
    r.max_move_relative = diagonal > 0 ? r.max_move / diagonal : 0.0;
    if (report) *report = r;
    return rounded;
  };
  // The passes of one level; the rounded mesh when one of them settles it.
  auto passes_at_level = [&](int level) -> std::optional<RoundedMesh> {
    // Each level starts again from the exact arrangement.
    const double h = level_spacing(largest, level);
    // No vertex snaps farther than the move limit (the result would be refused): on a model
    // a few hundred ulps wide, a coarse level's snap would make every double vertex a
    // candidate of every other one.
    const double snap = level == 0 ? ulp : std::max(ulp, std::min(h, move_limit));
    RoundedMesh rounded = level == 0 ? nearest : round_to_grid(mesh, h, snap, move, move_limit);
    double level_move = move;
    if (level_move > move_limit) return std::nullopt;
    const std::size_t level_triangles = rounded.triangles.size();
    for (int pass = 1;; ++pass) {
      ++r.passes;
      ArrangeResult again = arrange(as_input(rounded), arrange_options);
      if (unchanged(again.stats)) return finish(std::move(rounded), level_move, h);
      // A pass that does not reduce the intersections, or grows the mesh by more than a
      // tenth, means this grid keeps making features it cannot hold: go to the next level
      // (before the passes grow the mesh without bound). A pass that finds none, only
      // vertices to merge or triangles to drop (copies collapsed onto one grid), makes no
      // new point and shrinks the mesh: the next one may settle, even after the level's 4.
      const bool no_new_points = again.stats.intersecting_pairs == 0;
      const bool worse = (pass > 1 && !no_new_points && again.stats.intersecting_pairs >= last.intersecting_pairs) ||
                         again.stats.out_triangles > level_triangles + level_triangles / 10;
      last = again.stats;
      last_level = level;
      if (worse || r.passes >= budget || (pass >= kPassesPerLevel && !no_new_points)) break;
      rounded = round_to_grid(again.mesh, h, snap, move, move_limit - level_move);
      level_move += move;
      if (level_move > move_limit) break;
    }
    return std::nullopt;
  };
  if (auto done = passes_at_level(0)) return *done;

  // The last resorts make few or no new points: vertices stay at their nearest doubles while
  // slivers collapse and edges and faces are rerouted through vertices within an ulp
  // (round_rerouting.h), tried before the coarser levels because it moves the surface by
  // an ulp per round only; what that leaves, after the coarser levels, vertices on grids of their
  // own, coarser only where needed (round_per_vertex.h). Arranging the result once more
  // proves it.
  std::vector<ExactVec3> exact(mesh.vertices.size());
  std::vector<Vec3> nearest_positions(exact.size());
  tbb::parallel_for(std::size_t{0}, exact.size(), [&](std::size_t v) {
    if (is_double(mesh.vertices[v])) {
      nearest_positions[v] = double_coordinates(mesh.vertices[v]);
      exact[v] = to_exact(nearest_positions[v]);
    } else {
      exact[v] = exact_coordinates(mesh.vertices[v]);
      nearest_positions[v] = tritri::to_double(exact[v]);
    }
  });
  auto settled = [&](RoundedMesh rounded, double max_move, double grid) -> std::optional<RoundedMesh> {
    if (!unchanged(arrange(as_input(rounded), arrange_options).stats))
      throw RoundingError("round_safe: a last resort passed the check but arranging its result changed it");
    return finish(std::move(rounded), max_move, grid);
  };
  // Rerouting, in cycles: when one stalls, its best mesh is arranged again exactly (the
  // crossings its rounding left become points) and rounded to nearest, snapping new points
  // within an ulp to a double vertex as the passes do, and rerouting goes on from there.
  // The bound adds each cycle's rounding move and an ulp per round of its rerouting.
  Rerouting rerouting;  // the first cycle's, for rounding per vertex below
  // The cycle that left the fewest conflicts, for nudging at the end: its mesh, move,
  // vertices rerouted and cycles up to it.
  std::optional<RoundedMesh> fewest;
  std::size_t fewest_violations = 0, fewest_rerouted = 0;
  // The fewest conflicts any last resort left, here or on a changed input (for the refusal).
  std::size_t conflicts_left = 0;
  auto closer = [&](std::size_t left) {
    if (left > 0 && (conflicts_left == 0 || left < conflicts_left)) conflicts_left = left;
  };
  double fewest_move = 0;
  int fewest_cycles = 0;
  {
    // The first cycle starts from the arrangement on its nearest doubles.
    RoundedMesh cycle_mesh{nearest_positions, mesh.triangles, mesh.source, mesh.label_set, mesh.label_sets};
    double cycle_move = largest_distance(exact, nearest_positions);
    std::size_t rerouted = 0;
    // Rerouting stops at kReroutePasses, leaving the rest of the budget to the steps below.
    const int reroute_limit = std::min(budget, kReroutePasses);
    for (int cycle = 0; cycle < kRerouteCycles && r.passes < reroute_limit; ++cycle) {
      const RoundedMesh& c = cycle_mesh;
      Rerouting now = reroute_conflicts(c.vertices, c.triangles, c.source, c.label_set, c.label_sets, ulp,
                                        reroute_limit - r.passes);
      r.passes += now.rounds;
      rerouted += now.rerouted;
      // Each round of rerouting moves the surface by an ulp at most (a vertex put on an
      // edge or a face lies within an ulp of it): rounds x ulp bounds the cycle's move.
      if (now.rerouted > 0) cycle_move += ulp * now.rounds;
      RoundedMesh best = mesh_on_positions(c.vertices, now.triangles, now.source, now.label_set, now.label_sets).mesh;
      const std::size_t violations = now.violations;
      closer(violations);
      if (cycle == 0) rerouting = std::move(now);
      if (violations > 0 && (!fewest || violations < fewest_violations)) {
        fewest = best;
        fewest_violations = violations;
        fewest_move = cycle_move;
        fewest_rerouted = rerouted;
        fewest_cycles = cycle;
      }
      if (violations == 0) {
        r.rerouted = rerouted;
        if (auto done = settled(std::move(best), cycle_move, 0.0)) return *done;
        r.rerouted = 0;
        break;
      }
      // Arranging again pays only for few conflicts: where they are many (layers that
      // nearly coincide over whole faces, for the input merge and the coarser grids) it
      // makes as many new ones; a cycle that grows the mesh by more than a tenth feeds on
      // itself the same way.
      const std::size_t triangles = best.triangles.size();
      if (!few_conflicts(violations, triangles) || triangles > mesh.triangles.size() + mesh.triangles.size() / 10 ||
          r.passes >= reroute_limit || cycle_move > move_limit)
        break;
      ++r.passes;
      ++r.reroute_cycles;
      double move_now = 0;
      cycle_mesh = round_to_grid(arrange(as_input(best), arrange_options).mesh, 0, ulp, move_now);
      cycle_move += move_now;
    }
  }
  // Back to the input, when given: a changed input (double or exact soup) arranged and
  // rounded safely as here (without the input steps), within kInputBudget passes (a change
  // that does not settle soon is not the right one); `note` records the change in the
  // report. The bound adds the input's largest move.
  auto settle_input = [&](const auto& soup, double input_move, auto note) -> std::optional<RoundedMesh> {
    if (input_move > move_limit) return std::nullopt;
    RoundSafeOptions inner = options;
    inner.input = nullptr;
    // kInputBudget passes, then kNudgeRounds for nudging's cycles, within what is left.
    inner.max_passes = std::min(kInputBudget + kNudgeRounds, budget - r.passes);
    const int reserve = std::max(0, inner.max_passes - kInputBudget);
    RoundReport done;
    try {
      RoundedMesh rounded =
          round_in_passes(arrange(soup, arrange_options).mesh, inner, &done, move_limit - input_move, reserve, 2);
      done.passes += r.passes;
      note(done);
      const RoundReport before = r;
      r = done;
      if (auto result = finish(std::move(rounded), input_move + done.max_move, done.grid)) return result;
      r = before;  // refused by the move limit: nothing of it stays in the report but its passes
      r.passes = done.passes;
      return std::nullopt;
    } catch (const RoundingError&) {
      r.passes += done.passes;
      closer(done.conflicts_left);
      return std::nullopt;
    }
  };
  // One input step: the input changed within 4^k ulps for k = first..last (`change`, whose
  // result counts the vertices it moved in `count`) and settled as above. A distance that
  // moves no more vertices than the last one tried (`moved_before`) is not tried again; with
  // `stable`, neither is one where 4 times the distance would move more than a 16th more
  // vertices (a scale inside the clusters, not between them: copies not all caught yet).
  auto input_step = [&](int first, int last, bool stable, std::size_t& moved_before, auto change,
                        auto count, std::size_t RoundReport::*reported) -> std::optional<RoundedMesh> {
    if (options.input == nullptr) return std::nullopt;
    std::optional<decltype(change(ulp))> ahead;  // the change at 4 times the distance, when made
    for (int k = first; k <= last && r.passes < budget; ++k) {
      const auto changed = ahead ? std::move(*ahead) : change(std::ldexp(ulp, 2 * k));
      ahead.reset();
      if (changed.*count == moved_before) continue;
      if (stable) {
        ahead = change(std::ldexp(ulp, 2 * k + 2));
        if ((*ahead).*count > changed.*count + changed.*count / 16) continue;
      }
      moved_before = changed.*count;
      auto note = [&](RoundReport& d) { d.*reported = changed.*count; };
      if (auto done = settle_input(changed.soup, changed.max_move, note)) return done;
    }
    return std::nullopt;
  };
  auto merge_within = [&](double delta) { return merge_close_input_vertices(*options.input, delta); };
  // Merged input (round_merged_input.h): its vertices within 4, 16, 64, then 256 ulps of each
  // other merged (a move of a few ulps where copies of one mesh nearly coincide, before the
  // coarser grids move every vertex by 2^8 ulps or more).
  std::size_t merged_before = 0, snapped_before = 0;
  if (auto done = input_step(1, 4, false, merged_before, merge_within, &MergedInput::merged,
                             &RoundReport::merged_input))
    return *done;
  // Snapped planes (round_snapped_planes.h): layers within 4, 16, then 64 ulps of each other's
  // planes made coplanar (exact rationals), for faces that nearly coincide without sharing
  // vertices.
  auto snap_within = [&](double delta) {
    return snap_near_coplanar_faces(*options.input, delta, options.threads, false);
  };
  if (auto done = input_step(1, 3, false, snapped_before, snap_within, &SnappedPlanes::moved,
                             &RoundReport::snapped_vertices))
    return *done;
  // Then contacts as well: corners within 4, 16, then 64 ulps of the plane of a triangle
  // they touch moved onto it (an edge on a face that a turn left 1e-17 off it).
  auto snap_contacts_within = [&](double delta) {
    return snap_near_coplanar_faces(*options.input, delta, options.threads, true);
  };
  if (auto done = input_step(1, 3, false, snapped_before, snap_contacts_within, &SnappedPlanes::moved,
                             &RoundReport::snapped_vertices))
    return *done;
  // Level 1 (a grid of 2^8 ulps), then rounding per vertex, which moves only the vertices of
  // conflicting triangles (a far smaller change, where it settles, than the levels below).
  if (r.passes < budget && levels > 1)
    if (auto done = passes_at_level(1)) return *done;
  if (r.passes < budget) {
    // Rounding per vertex from the arrangement's triangles, then from the rerouted ones
    // (within an ulp per round of rerouting of the rounded ones: extra_move).
    auto per_vertex = [&](const std::vector<Tri>& triangles, const std::vector<std::int64_t>& source,
                          const std::vector<int>& label_set, const std::vector<LabelSet>& label_sets,
                          double extra_move) -> std::optional<RoundedMesh> {
      if (extra_move > move_limit) return std::nullopt;
      std::optional<PerVertexRounding> per =
          round_per_vertex(exact, nearest_positions, triangles, source, label_set, label_sets, largest,
                           budget - r.passes, move_limit - extra_move);
      if (!per) return std::nullopt;
      r.passes += per->rounds;
      r.coarsened = per->coarsened;
      if (auto done = settled(per->mesh, per->max_move + extra_move, per->grid)) return done;
      r.coarsened = 0;
      return std::nullopt;
    };
    if (auto done = per_vertex(mesh.triangles, mesh.source, mesh.label_set, mesh.label_sets, 0.0)) return *done;
    if (rerouting.rerouted > 0) {
      r.rerouted = rerouting.rerouted;
      if (auto done = per_vertex(rerouting.triangles, rerouting.source, rerouting.label_set, rerouting.label_sets,
                                 ulp * rerouting.rounds))
        return *done;
      r.rerouted = 0;
    }
  }
  // The coarser levels, each after merging the input within its spacing: copies of one mesh
  // moved and turned by far more than ulps (1e-9 of the size, 1e-7 rad) coincide once every
  // copied vertex merges with its original, a smaller change than moving every vertex to the
  // level's grid. Merges that catch some copies only leave layers crossing as before, so
  // these distances are `stable` ones.
  for (int level = 2; level < levels && r.passes < budget; ++level) {
    if (auto done = input_step(4 * level - 3, 4 * level, true, merged_before, merge_within, &MergedInput::merged,
                               &RoundReport::merged_input))
      return *done;
    if (auto done = passes_at_level(level)) return *done;
  }
  // Nudging (round_nudged.h), when every other step failed: the corners of the conflicts
  // that rerouting's best cycle left, moved by 1 to 1024 ulps one at a time where that
  // leaves fewer (a grazing crossing far from any vertex, which no grid holds). In cycles,
  // as rerouting's: where nudging stalls, its mesh is arranged again (the crossings it left
  // become points), rounded with the snap of level 0, rerouted and nudged again; each cycle
  // adds its rounding move, an ulp per round of rerouting and its nudges to the bound.
  if (fewest && nudgeable(fewest_violations, fewest->triangles.size()) && fewest_move < move_limit) {
    RoundedMesh start = std::move(*fewest);
    double nudge_move = fewest_move;
    std::size_t rerouted = fewest_rerouted, nudged_vertices = 0;
    int cycles = fewest_cycles;
    const std::size_t most_triangles = start.triangles.size() + start.triangles.size() / 10;
    auto settle_nudged = [&](RoundedMesh rounded) -> std::optional<RoundedMesh> {
      const RoundReport before = r;
      r.rerouted = rerouted;
      r.reroute_cycles = cycles;
      r.nudged = nudged_vertices;
      if (auto done = settled(std::move(rounded), nudge_move, 0.0)) return done;
      r = before;
      return std::nullopt;
    };
    for (int cycle = 0; cycle < kNudgeCycles && r.passes < options.max_passes && nudge_move < move_limit;
         ++cycle) {
      Nudged nudged = nudge_conflicts(start, ulp, move_limit - nudge_move, options.max_passes - r.passes);
      r.passes += nudged.rounds;
      closer(nudged.violations);
      nudged_vertices += nudged.moved;
      nudge_move += nudged.max_move;
      if (nudged.violations == 0) {
        if (auto done = settle_nudged(std::move(nudged.mesh))) return *done;
        break;
      }
      // Arranging again is a pass, and rerouting needs a round after it.
      if (!nudgeable(nudged.violations, nudged.mesh.triangles.size()) || r.passes + 1 >= options.max_passes) break;
      ++r.passes;
      ++cycles;
      double rounding = 0;
      const RoundedMesh again = round_to_grid(arrange(as_input(nudged.mesh), arrange_options).mesh, 0, ulp, rounding);
      nudge_move += rounding;
      if (again.triangles.size() > most_triangles || nudge_move >= move_limit) break;
      const Rerouting now = reroute_conflicts(again.vertices, again.triangles, again.source, again.label_set,
                                              again.label_sets, ulp, options.max_passes - r.passes);
      r.passes += now.rounds;
      rerouted += now.rerouted;
      if (now.rerouted > 0) nudge_move += ulp * now.rounds;
      start = mesh_on_positions(again.vertices, now.triangles, now.source, now.label_set, now.label_sets).mesh;
      closer(now.violations);
      if (now.violations == 0) {
        if (auto done = settle_nudged(std::move(start))) return *done;
        break;
      }
    }
  }
  r.conflicts_left = conflicts_left;
  if (report) *report = r;
  throw RoundingError(refusal_message({.conflicts_left = conflicts_left,
                                       .last = last,
                                       .last_level = last_level,
                                       .input_steps = options.input != nullptr,
                                       .move_limit_ulps = move_limit / ulp,
                                       .max_move_relative = options.max_move_relative,
                                       .diagonal_ulps = diagonal / ulp,
                                       .passes = r.passes,
                                       .max_passes = options.max_passes}));
}

}  // namespace

RoundedMesh round_nearest(const OutputMesh& mesh) {
  double move = 0;
  return round_to_grid(mesh, 0, 0, move);
}

RoundedMesh round_nearest(const ExactOutputMesh& mesh) {
  double move = 0;
  return round_to_grid(mesh, 0, 0, move);
}

RoundedMesh round_safe(const OutputMesh& mesh, const RoundSafeOptions& options, RoundReport* report) {
  return round_in_passes(mesh, options, report, std::numeric_limits<double>::infinity(), 0, kLevels);
}

RoundedMesh round_safe(const ExactOutputMesh& mesh, const RoundSafeOptions& options, RoundReport* report) {
  return round_in_passes(mesh, options, report, std::numeric_limits<double>::infinity(), 0, kLevels);
}

}  // namespace arrangements
