// Ladder (arrangements::detail): the steps of round_safe (arrangements/round_mesh.h, where
// they are documented) in the order they are tried, each on the exact arrangement, the
// first result that is an arrangement within the move limit returned. round_mesh.cpp runs
// one; each changed input runs one of its own.
//
// The steps of Ladder::run, in order. Invariant of every step: a result is returned only
// if it is an arrangement (the exact check of every pair finds no violating pair: a full
// check, or tracker_'s incremental one after it), its largest vertex move is within the
// move limit (a 64th of the diagonal by default, capped by move_cap), it is not emptied,
// and it is closed where options.keep_closed asks (`finish`); otherwise the next step is
// tried, and after the last one the ladder throws RoundingError (round_refusal.h).
//   1. Level 0 (passes_at_level): round to the nearest doubles, check, arrange the
//      violating pairs' triangles again (arrange_locally.h), round again, up to
//      kPassesPerLevel passes; stops early when a pass does not reduce the violating pairs
//      or grows the mesh by more than a tenth.
//   2. Merged input at nearest (merged_input_at_nearest), only with options.input: input
//      vertices within 4 ulps merged, the changed input given one pass at level 0 (models
//      wider than 2^22 ulps, where level 0 left many conflicts).
//   3. Rerouting (round_rerouting.h; reroute_in_cycles, ladder_cycles.h): vertices stay at their nearest
//      doubles; slivers collapse and edges and faces reroute through vertices within an
//      ulp; in cycles of arranging again and rounding while the conflicts are few (and,
//      above kStopCyclesAbove, fewer than the best cycle before left). Its
//      bound adds an ulp per round of rerouting.
//   4. Merged input (round_merged_input.h), only with options.input: input vertices
//      within 4^k ulps (k = 1..4) merged, the changed input arranged and rounded by a
//      ladder of its own (settle_input, levels 0 and 1); the bound adds the input's move.
//   5. Snapped planes (round_snapped_planes.h), only with options.input: near-coplanar
//      layers, then corners near a touched face's plane, within 4^k ulps (k = 1..3) made
//      coplanar exactly, settled as in 4.
//   6. Level 1: the passes of 1 on the grid of 2^8 ulps.
//   7. Nudging (round_nudged.h; nudge_in_cycles, ladder_cycles.h), the last step: the corners of the
//      conflicts that rerouting's best cycle left move by 1 to 1024 ulps one at a time
//      where that leaves fewer; in cycles of arranging again and rerouting.
// Every step counts its passes against options.max_passes (less the nudging reserve). A
// study leaves steps 2-7 out by options.without (RoundStep), in every ladder it starts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/arrange.h"
#include "arrangements/round_mesh.h"
#include "booleans/unbalanced_edges.h"
#include "rounding/ladder_limits.h"
#include "rounding/round_merged_input.h"
#include "rounding/round_snapped_planes.h"
#include "rounding/round_refusal.h"
#include "rounding/round_rerouting.h"
#include "rounding/round_to_grid.h"
#include "rounding/arrange_locally.h"
#include "rounding/violation_tracker.h"
#include "support/bounding_box.h"
#include "rounding/mesh_on_positions.h"
#include "rounding/rounding_grid.h"
#include "support/vertex_coordinates.h"

namespace arrangements::detail {

// One ladder of round_safe: its steps, each tried when the ones before it failed (the
// smallest change first), on `mesh`; run() returns the first result that is an
// arrangement within the move limit, or throws RoundingError. A changed input's ladder
// (settle_input) is one more Ladder, on the arrangement of the changed input.
// move_cap: the largest move the caller accepts (a changed input's limit less the change's
// own move; infinity from round_safe). Every step stops as soon as its move exceeds the
// limit: its result would be refused (this is what makes a refusal cheap).
// nudge_reserve: the last passes of options.max_passes kept for nudging, the last step (a
// changed input's ladder gets its passes and these on top); below options.max_passes.
// levels: the grid levels tried (kLevels: level 0, the nearest doubles, and level 1;
// merged_input_at_nearest's one pass: level 0 only).
template <class Mesh>
class Ladder {
 public:
  Ladder(const Mesh& mesh, const RoundSafeOptions& options, double move_cap, int nudge_reserve, int levels)
      : mesh_(mesh), options_(options), levels_(levels) {
    if (options.max_passes < 1)
      throw std::invalid_argument("round_safe: max_passes must be at least 1, got " +
                                  std::to_string(options.max_passes));
    if (!(options.max_move_relative > 0) || !std::isfinite(options.max_move_relative))
      throw std::invalid_argument("round_safe: max_move_relative must be a finite number above 0, got " +
                                  std::to_string(options.max_move_relative));
    budget_ = options.max_passes - nudge_reserve;
    arrange_options_.threads = options.threads;
    nearest_ = round_to_grid(mesh, 0, 0, nearest_move_);
    largest_ = largest_magnitude(nearest_.vertices);
    ulp_ = level_spacing(largest_, 1) / 256;
    // A result that moves a vertex by more than a 64th of the arrangement's diagonal (by
    // default: options.max_move_relative) is not a rounding of it (a grid or merge distance
    // as wide as the model collapses it, to nothing at worst): every step's result is
    // refused beyond that, and the next step tried. A model only a few ulps wide may move
    // by 16 ulps (rounding to nearest moves it by one), but not vanish.
    diagonal_ = bounding_box(nearest_.vertices).diagonal();
    move_limit_ = std::min(std::max(diagonal_ * options.max_move_relative, 16 * ulp_), move_cap);
  }

  RoundedMesh run(RoundReport* report) {
    report_ = report;
    if (auto done = passes_at_level(0)) return *done;
    std::size_t merged_before = 0, snapped_before = 0;  // vertices the last input change moved
    // The steps in the order of the list at the top of this file: the smallest change first.
    if (uses(RoundStep::merged_input_at_nearest))
      if (auto done = merged_input_at_nearest()) return *done;
    // Rerouting moves the surface by an ulp per round only, so it comes before level 1 and
    // the input changes.
    if (uses(RoundStep::rerouting))
      if (auto done = reroute_in_cycles()) return *done;
    // Merged input within 4, 16, 64, then 256 ulps (before the grids' 2^8 ulps or more).
    if (uses(RoundStep::merged_input))
      if (auto done = input_step(1, 4, merged_before, &Ladder::merge_within, &MergedInput::merged,
                                 &RoundReport::merged_input))
        return *done;
    // Snapped planes: near-coplanar layers, then corners near a face they touch (an edge on
    // a face that a turn left 1e-17 off it), within 4, 16, then 64 ulps.
    if (uses(RoundStep::snapped_layers))
      if (auto done = input_step(1, 3, snapped_before, &Ladder::snap_layers_within, &SnappedPlanes::moved,
                                 &RoundReport::snapped_vertices))
        return *done;
    if (uses(RoundStep::snapped_contacts))
      if (auto done = input_step(1, 3, snapped_before, &Ladder::snap_contacts_within,
                                 &SnappedPlanes::moved, &RoundReport::snapped_vertices))
        return *done;
    // Level 1. Rounding per vertex and the coarser levels 2-4 that came next settled
    // nothing in the sweep or the tests that the other steps do not (docs/ROUNDING.md).
    if (uses(RoundStep::level_1) && r_.passes < budget_ && levels_ > 1)
      if (auto done = passes_at_level(1)) return *done;
    if (uses(RoundStep::nudging))
      if (auto done = nudge_in_cycles()) return *done;
    refuse();
  }

 private:
  using Found = std::optional<RoundedMesh>;

  // Whether options.without leaves `step` in (a study of the ladder leaves some out).
  bool uses(RoundStep step) const { return !leaves_out(options_.without, step); }

  // The result, with the report filled, when within the move limit, not emptied and, where
  // options.keep_closed asks, closed.
  Found finish(RoundedMesh rounded, double max_move, double grid) {
    if (max_move > move_limit_ || (rounded.triangles.empty() && !mesh_.triangles.empty())) return std::nullopt;
    if (options_.keep_closed && unbalanced_edges(rounded) != 0) return std::nullopt;
    r_.grid = grid;
    r_.max_move = max_move;
    r_.max_move_relative = diagonal_ > 0 ? r_.max_move / diagonal_ : 0.0;
    if (report_) *report_ = r_;
    return rounded;
  }

  // The fewest conflicts any last resort left, here or on a changed input (for the refusal).
  void closer(std::size_t left) {
    if (left > 0 && (conflicts_left_ == 0 || left < conflicts_left_)) conflicts_left_ = left;
  }

  // The passes of one level; the rounded mesh when one of them settles it.
  Found passes_at_level(int level) {
    // Each level starts again from the exact arrangement.
    const double h = level_spacing(largest_, level);
    // No vertex snaps farther than the move limit (the result would be refused): on a model
    // a few hundred ulps wide, a coarse level's snap would make every double vertex a
    // candidate of every other one.
    const double snap = level == 0 ? ulp_ : std::max(ulp_, std::min(h, move_limit_));
    double move = nearest_move_;
    RoundedMesh rounded = level == 0 ? nearest_ : round_to_grid(mesh_, h, snap, move, move_limit_);
    double level_move = move;
    if (level_move > move_limit_) return std::nullopt;
    const std::size_t level_triangles = rounded.triangles.size();
    for (int pass = 1;; ++pass) {
      ++r_.passes;
      // Its vertices at distinct positions, none degenerate or repeated: then the exact
      // check proves it an arrangement, or names the pairs to arrange again.
      RoundedMesh clean = mesh_on_positions(rounded, options_.keep_closed);
      const std::vector<std::pair<int, int>> violating = tracker_.violations(clean);
      if (violating.empty()) return finish(std::move(clean), level_move, h);
      ArrangeStats again;
      OutputMesh arranged = arrange_locally(clean, violating, arrange_options_, again);
      // A pass that does not reduce the intersections, or grows the mesh by more than a
      // tenth, means this grid keeps making features it cannot hold: go to the next step
      // (before the passes grow the mesh without bound).
      const bool worse = (pass > 1 && again.intersecting_pairs >= last_.intersecting_pairs) ||
                         again.out_triangles > level_triangles + level_triangles / 10;
      last_ = again;
      last_level_ = level;
      if (worse || r_.passes >= budget_ || pass >= kPassesPerLevel) break;
      rounded = round_to_grid(arranged, h, snap, move, move_limit_ - level_move);
      level_move += move;
      if (level_move > move_limit_) break;
    }
    return std::nullopt;
  }

  // The cycles of rerouting and of nudging (ladder_cycles.h).
  RoundedMesh arrange_and_round(const RoundedMesh& m, double& move);
  struct Rerouted {
    Rerouting rerouting;
    RoundedMesh mesh;
  };
  Rerouted reroute(const RoundedMesh& m, int max_rounds);
  Found reroute_in_cycles();

  // Back to the input, when given: a changed input (double or exact soup) arranged and
  // rounded safely by a ladder of its own (without the input steps),
  // within kInputBudget passes (a change that does not settle soon is not the right one);
  // `note` records the change in the report. The bound adds the input's largest move.
  // passes, nudge_rounds, levels: the changed input's ladder (merged_input_at_nearest's: 1, 0, 1).
  template <class Soup, class Note>
  Found settle_input(const Soup& soup, double input_move, Note note, int passes = kInputBudget,
                     int nudge_rounds = kNudgeRounds, int levels = kLevels) {
    if (input_move > move_limit_) return std::nullopt;
    RoundSafeOptions inner = options_;
    inner.input = nullptr;
    // `passes`, then nudge_rounds for nudging's cycles, within what is left (callers check
    // that some is: r_.passes < budget_).
    inner.max_passes = std::min(passes + nudge_rounds, budget_ - r_.passes);
    const int reserve = std::max(0, inner.max_passes - passes);
    RoundReport done;
    try {
      const auto arranged = arrange(soup, arrange_options_);
      RoundedMesh rounded = Ladder<std::decay_t<decltype(arranged.mesh)>>(arranged.mesh, inner,
                                                                          move_limit_ - input_move, reserve, levels)
                                .run(&done);
      done.passes += r_.passes;
      note(done);
      const RoundReport before = r_;
      r_ = done;
      if (auto result = finish(std::move(rounded), input_move + done.max_move, done.grid)) return result;
      r_ = before;  // refused by the move limit: nothing of it stays in the report but its passes
      r_.passes = done.passes;
      return std::nullopt;
    } catch (const RoundingError&) {
      r_.passes += done.passes;
      closer(done.conflicts_left);
      return std::nullopt;
    }
  }

  MergedInput merge_within(double delta) const { return merge_close_input_vertices(*options_.input, delta); }
  SnappedPlanes snap_layers_within(double delta) const {
    return snap_near_coplanar_faces(*options_.input, delta, options_.threads, false);
  }
  SnappedPlanes snap_contacts_within(double delta) const {
    return snap_near_coplanar_faces(*options_.input, delta, options_.threads, true);
  }

  // One input step: the input changed within 4^k ulps for k = first..last (`change`, whose
  // result counts the vertices it moved in `count`) and settled as above. A distance that
  // moves no more vertices than the last one tried (`moved_before`) is not tried again.
  template <class Changed>
  Found input_step(int first, int last, std::size_t& moved_before, Changed (Ladder::*change)(double) const,
                   std::size_t Changed::*count, std::size_t RoundReport::*reported) {
    if (options_.input == nullptr) return std::nullopt;
    for (int k = first; k <= last && r_.passes < budget_; ++k) {
      const Changed changed = (this->*change)(std::ldexp(ulp_, 2 * k));
      if (changed.*count == moved_before) continue;
      moved_before = changed.*count;
      auto note = [&](RoundReport& d) { d.*reported = changed.*count; };
      if (auto done = settle_input(changed.soup, changed.max_move, note)) return done;
    }
    return std::nullopt;
  }

  // Merged input within 4 ulps, one pass at level 0, before rerouting: nearly coincident
  // input vertices (poles of turned copies) make crossings every rounding recreates and
  // rerouting fights for many passes (five turned spheres: 14.6 s, then this settled in
  // 1.3 s). Failing, it costs the pass; the ladder goes on unchanged. Only where level 0
  // left more intersecting pairs than a quarter of the triangles (those spheres: 0.44;
  // turned angle blocks, which rerouting settles sooner: 0.07-0.2), on models wider than
  // 2^22 ulps (on narrower ones 4 ulps merges most of the model).
  Found merged_input_at_nearest() {
    const double distance = std::ldexp(ulp_, 2);
    if (options_.input == nullptr || r_.passes >= budget_ || distance > diagonal_ * 0x1p-20 ||
        last_.intersecting_pairs <= mesh_.triangles.size() / 4)
      return std::nullopt;
    const MergedInput changed = merge_within(distance);
    if (changed.merged == 0) return std::nullopt;
    auto note = [&](RoundReport& d) { d.merged_input = changed.merged; };
    return settle_input(changed.soup, changed.max_move, note, 1, 0, 1);
  }

  Found nudge_in_cycles();  // ladder_cycles.h

  [[noreturn]] void refuse() {
    r_.conflicts_left = conflicts_left_;
    if (report_) *report_ = r_;
    throw RoundingError(refusal_message({.conflicts_left = conflicts_left_,
                                         .last = last_,
                                         .last_level = last_level_,
                                         .input_steps = options_.input != nullptr,
                                         .move_limit_ulps = move_limit_ / ulp_,
                                         .max_move_relative = options_.max_move_relative,
                                         .diagonal_ulps = diagonal_ / ulp_,
                                         .passes = r_.passes,
                                         .max_passes = options_.max_passes,
                                         .without = options_.without}));
  }

  const Mesh& mesh_;
  const RoundSafeOptions& options_;
  const int levels_;
  int budget_ = 0;  // passes and rounds before nudging
  ArrangeOptions arrange_options_;
  RoundReport r_;
  RoundReport* report_ = nullptr;
  // Checks every mesh the passes and cycles make, incrementally: each changes the last one
  // where it crossed itself only.
  ViolationTracker tracker_;
  RoundedMesh nearest_;        // the arrangement rounded to nearest
  double nearest_move_ = 0;    // and that rounding's largest move
  double largest_ = 0;         // largest coordinate magnitude of nearest_
  double ulp_ = 0;             // an ulp of largest_
  double diagonal_ = 0;        // of nearest_'s bounding box
  double move_limit_ = 0;
  ArrangeStats last_{};        // what the latest pass's arrangement found
  int last_level_ = 0;         // the grid level of that pass
  // Rerouting's cycle that left the fewest conflicts, for nudging: its mesh, the
  // conflicts, its move, the vertices rerouted and the cycles up to it.
  std::optional<RoundedMesh> fewest_;
  std::size_t fewest_violations_ = 0, fewest_rerouted_ = 0;
  double fewest_move_ = 0;
  int fewest_cycles_ = 0;
  std::size_t conflicts_left_ = 0;  // the fewest conflicts any last resort left
};

}  // namespace arrangements::detail
