// arrangements/round_mesh.h
//
// After the pipeline: the exact arrangement (OutputMesh or ExactOutputMesh) as a mesh with
// double coordinates (RoundedMesh, output_mesh.h).
//
// round_nearest(mesh)
//   Every vertex rounded to the nearest double (ties to even), triangles and provenance
//   unchanged. The result need not be an arrangement any more: rounding can move a vertex
//   through a nearby triangle, make a thin triangle degenerate, or merge two vertices.
//
// round_safe(mesh, options = {}, report = nullptr)
//   A RoundedMesh that is still an arrangement: its triangles meet only in shared vertices
//   and shared edges, none is degenerate, no two vertices coincide (decided exactly). In
//   passes of rounding and arranging:
//     1. round every vertex (to the level's grid, below);
//     2. clean the rounded mesh (one vertex per position; triangles without area, or on
//        the same three vertices as another, dropped, the latter's labels kept; with
//        options.keep_closed, opposite ones on the same three vertices cancel) and check
//        it exactly (check_arrangement, incremental from the previous pass: only the pairs
//        with a triangle the last mesh did not have);
//     3. if no pair violates, it is an arrangement: done. Else arrange the triangles of
//        the violating pairs again (the exact pipeline, double path; the others cannot be
//        cut, so this is the arrangement of the whole mesh: new LPI and TPI points where
//        rounding made crossings) and round the result: its new points (made only because
//        rounding moved vertices) are merged into the nearest vertex that is a double
//        already when one lies within the level's snap distance (snap rounding's rule: new
//        vertices at existing hot pixels), else rounded; triangles that collapse are
//        dropped; go to 2.
//   Levels: level 0 rounds to the nearest double (snap distance: one ulp of the largest
//   coordinate magnitude L). Some meshes hold features far thinner than an ulp (slivers,
//   two surfaces 1e-33 apart near a zero coordinate); passes at level 0 then keep making
//   new points at that scale. When a pass does not reduce the violating pairs, grows the
//   mesh by more than a tenth, or 4 passes did not succeed, rerouting is tried (below: it
//   moves the surface by an ulp per round at most), then merging input vertices (below), then
//   level 1 starts again from the exact arrangement, on the uniform grid of spacing
//   h = 2^8 ulps of L (snap distance h): unlike the doubles, the grid is as coarse near
//   zero as anywhere, so features thinner than a cell collapse instead of crossing again.
//   Input vertices move too at level 1 (onto the grid). Rounding per vertex (the vertices
//   of conflicts alone to coarser grids) and levels 2-4 (grids of 2^16 to 2^32 ulps, each
//   after merging input vertices at its spacing) came next until a study (docs/ROUNDING.md)
//   found that they settled nothing the other steps do not: gone.
//   Displacement: the points of a pass move by at most the snap distance or the rounding
//   from a point of the previous pass's surface; report->max_move sums the largest move
//   of each pass of the successful level (bounded from exact coordinate differences), so
//   every vertex of the result lies within it of the exact arrangement's surface. No
//   result moves a vertex by more than a 64th of the exact arrangement's diagonal (by
//   default: options.max_move_relative; or 16 ulps of L, for models a few ulps wide), and no result of a mesh with triangles is
//   empty: a step whose result would is refused and the next one tried, so a grid or merge
//   distance as wide as the model never collapses it.
//   Merged input at nearest, when level 0 fails leaving more intersecting pairs than a
//   quarter of the triangles, options.input is given and the model is wider than 2^22 ulps
//   of L (on a narrower one 4 ulps is no small change): input vertices
//   within 4 ulps of L of each other merged (below), the merged input arranged and given one
//   pass of level 0; nearly coincident input vertices (the poles of turned copies of one
//   mesh) make crossings that rerouting would fight for many passes (five turned 12 x 24
//   spheres: 17.5 s before, 2.3 s with this step). When that pass does not settle, it costs
//   the pass and nothing else changes.
//   Last resorts; the rounds of rerouting and of nudging do not arrange again, so they make
//   no new points (their cycles do, few):
//   Rerouting (src/rounding/round_rerouting.h), when level 0 fails: every vertex stays at its
//   nearest double; slivers whose apex lies within an ulp of the opposite edge collapse onto it, and of
//   each violating pair the vertex within an ulp of the other's edge or face is put on it
//   (the triangles there split through it: snap rounding's hot-pixel rule); each round
//   checks the result exactly. This settles operands placed in contact by transforms
//   rounded to doubles (the EMBER pairs), with the surface moved by an ulp per round at most. When
//   it stalls with conflicts on fewer than 5% of the triangles, its best mesh is arranged
//   again (exactly: the crossings its rounding left become points), rounded to nearest
//   with the snap of level 0 and rerouted again, in up to 8 cycles (stopping when the mesh
//   grows by a tenth or, where the best cycle so far left more than 64 conflicts, at one
//   that leaves no fewer); each cycle adds its rounding move and an ulp per round to the
//   bound. Layers crossing at grazing angles with few conflicts settle this way (three
//   copies of a 10 x 19 sphere rotated about its box centre: 7 cycles, 1.3e-15 of the
//   diagonal).
//   Merging input vertices (src/rounding/round_merged_input.h), when rerouting fails and
//   options.input is given, before level 1 (it moves vertices by a few ulps, level 1 by
//   2^8 ulps): input vertices within 4 ulps of L of each other are merged
//   (transitively; then 16, 64, 256 ulps while it does not settle, skipping a distance
//   that merges no more), the merged input is arranged again and rounded safely as here
//   (without this step). Copies of one mesh
//   placed by transforms rounded to doubles (rotated copies whose vertices map onto each
//   other, instances) then coincide exactly, each shared face once with the union of the
//   labels, instead of crossing wherever the rounding errors change sign. The bound adds
//   the largest distance a vertex moved to its cluster's representative.
//   Snapping nearly coplanar faces (src/rounding/round_snapped_planes.h), when merging input
//   vertices fails: triangles of the input whose corners lie within 4 ulps of L of each
//   other's planes (then 16, 64), grouped where two layers overlap, are moved exactly onto
//   one plane per group (a vertex of two or three groups onto their line or point, as
//   rationals), and the snapped input is arranged (exact path) and rounded safely as here.
//   Parts turned by angles that map them onto themselves (an ulp off) and moved along a
//   face then have exactly coplanar faces, each shared region once with the union of the
//   labels, instead of layers crossing wherever the errors change sign. The bound adds the
//   largest snap. Then the same with contacts (4, 16, 64 ulps): a corner within that
//   distance of the plane of a triangle it touches moves onto it (an edge that lay on a
//   face, 1e-17 off it once turned, which cuts slivers 1e-17 wide along the whole edge).
//   Each changed input (every input step) gets 32 passes and 64 for nudging's cycles on
//   top, rerouting at most 64 in all.
//   Nudging (src/rounding/round_nudged.h), the last step (also of each changed input's ladder):
//   from rerouting's cycle with the fewest conflicts (at most 1024, or on up to a 20th of
//   the triangles: as for arranging again in the cycles), the corners of
//   violating pairs move one at a time to the position 1, 2, 4, ... 1024 ulps around them
//   (the nearest ring that helps) that leaves the fewest violating pairs, if fewer; triangles
//   stay. This settles a grazing crossing far from any vertex (three copies of a 10 x 21
//   sphere: 2 vertices moved, 1.2e-15 of the diagonal). In up to 8 cycles (without
//   rerouting's stop at a cycle that leaves no fewer conflicts): where nudging stalls, its
//   mesh is arranged again (the crossings it left become points),
//   rounded with the snap of level 0, rerouted and nudged again (stopping when the mesh
//   grows by a tenth); each cycle adds its rounding move, an ulp per round of rerouting and
//   its nudges to the bound. Faces crossing at 1e-5 rad beside triangles a few thousand
//   ulps wide settle this way (a turned copy of manifold's openscad-nonmanifold-crash:
//   785 conflicts, nudged to 149, then 8, 6, 4 and none in 4 cycles, 2.1e-13 of the diagonal).
//   Termination: the passes have no proof (3D snap rounding with a proven bound needs a
//   grid far coarser than doubles): at most kLevels x 4 = 8 of them. Rerouting stops
//   after 3 rounds without fewer violations, its cycles after 8 (or sooner, above).
//   Every step stops when options.max_passes (passes and rounds together) is reached.
//   Nudging lowers the violations with every move, and stops at a round without one; its
//   cycles after 8. What is
//   measured (tests/test_round_safe.cpp: every shared mesh with intersections, MCUT and
//   EMBER pairs, rotated copies; tests/test_round_safe_input.cpp: the input steps) is given
//   in the tests' output.
//   Known failures (RoundingError): surfaces that cross at grazing angles over whole faces
//   with many conflicts, more than nudging takes on (bench/round_safe_sweep.py measures
//   how often); without options.input, also copies whose vertices coincide to 1e-7.
//   At every level the rounded layers cross again in as many places, their conflicts are
//   not within an ulp of a feature, and coarsening them only spreads them. Also models of
//   thousands of triangles only a few thousand ulps wide (features of tens of ulps: a mesh
//   scaled by 2^-30 and moved to 1e6), which no step rounds within the default move limit:
//   they settle with moves of a fifth to two thirds of the diagonal, which a caller may
//   accept (options.max_move_relative). Every step stops as soon as its move exceeds the
//   limit, so such refusals take seconds. The exact output (--exact) is always available.
//   Provenance is kept: a triangle of the result lies in (the rounded image of) the input
//   triangle `source` names, with the union of labels of every input triangle covering it;
//   triangles that collapsed to a segment or a point are gone (they had no area).
//
// Preconditions: a mesh as arrange() makes it (every index in range, per-triangle arrays
// of the right size); vertices within the double range.
// Throws std::invalid_argument for options.max_passes < 1 or options.max_move_relative not
// a finite number above 0, RoundingError when the passes
// do not converge within options.max_passes (or a vertex rounds beyond the double range);
// `report`, when given, is filled before throwing (the passes and rounds spent, and
// conflicts_left: how close the best attempt came).
// Cost: round_nearest: one exact rounding per implicit vertex. round_safe: per pass one
// rounding, one check of the triangles that changed (the first pass: of all, about the time
// of arranging a clean mesh of that size) and one run of the pipeline on the violating
// pairs' triangles; per round of a last resort the same check.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string_view>

#include "arrangements/arrange_stats.h"
#include "arrangements/output_mesh.h"

namespace arrangements {

// The steps of round_safe after level 0's passes, in the order they are tried (above;
// src/rounding/round_ladder.h lists them with the invariant each keeps). A study of what
// each one settles that no other does leaves some out: RoundSafeOptions::without.
// Leaving out rerouting leaves out nudging too (it starts from rerouting's best cycle).
enum class RoundStep : unsigned {
  merged_input_at_nearest,  // merged input at nearest (one pass), before rerouting
  rerouting,                // rerouting and its cycles
  merged_input,             // merging input vertices within 4 to 256 ulps
  snapped_layers,           // snapping nearly coplanar faces onto one plane
  snapped_contacts,         // snapping corners onto the plane of a face they touch
  level_1,                  // the passes on the grid of 2^8 ulps
  nudging,                  // nudging and its cycles
};
inline constexpr std::size_t kRoundSteps = static_cast<std::size_t>(RoundStep::nudging) + 1;
// Their names, indexed by RoundStep (as `arrange --round-without` takes them).
inline constexpr std::array<std::string_view, kRoundSteps> kRoundStepNames = {
    "merged-nearest", "rerouting", "merged-input", "snapped-layers", "snapped-contacts", "level-1", "nudging"};
// The bit of RoundSafeOptions::without that leaves `step` out.
constexpr unsigned round_step_bit(RoundStep step) { return 1u << static_cast<unsigned>(step); }
// Whether RoundSafeOptions::without = `without` leaves `step` out.
constexpr bool leaves_out(unsigned without, RoundStep step) { return (without & round_step_bit(step)) != 0; }

struct RoundSafeOptions {
  int max_passes = 384;  // passes of rounding and arranging, then rounds of the last resorts
  // The largest move accepted, as a fraction of the exact arrangement's bounding-box
  // diagonal (16 ulps of the largest coordinate magnitude when that is more): a step whose
  // result moves a vertex farther is refused, and the next one tried. A model only a few
  // hundred ulps wide (a mesh scaled by 2^-30 and moved to 1e6) settles only with far
  // larger moves, a fifth of its size or more: a caller who accepts that says so here.
  double max_move_relative = 1.0 / 64;
  int threads = 0;  // worker threads of the pipeline runs: 0 for all cores
  // The mesh is a closed solid (a Boolean's output, every edge used as often in one
  // direction as in the other): a step's result that is not is refused like one beyond the
  // move limit (rerouting can open a solid), and the next step tried.
  bool keep_closed = false;
  // The input that `mesh` is the arrangement of (double path only; optional): enables the
  // input steps (merging input vertices, snapping nearly coplanar faces).
  const TriangleSoup* input = nullptr;
  // The steps left out, round_step_bit each (0: every step; for studies of the ladder: a
  // mesh that only a left-out step settles is refused). Bits beyond kRoundSteps mean nothing.
  unsigned without = 0;
};

struct RoundReport {
  int passes = 0;                   // roundings done (1: rounding to nearest was enough)
  double max_move = 0;              // the displacement bound above (model units)
  double max_move_relative = 0;     // max_move / the diagonal of the exact arrangement's
                                    // bounding box (never above max_move_relative, unless
                                    // 16 ulps are more)
  double grid = 0;                  // 0: rounded to nearest doubles (level 0); else the
                                    // spacing of level 1's grid, where that succeeded
  std::size_t rerouted = 0;         // vertices rerouting put on an edge or a face
                                    // (0 when the passes succeeded)
  std::size_t merged_input = 0;     // input vertices merged into another one (the last
                                    // resort that needs options.input)
  std::size_t snapped_vertices = 0;  // input vertices moved onto the plane of a nearly
                                     // coplanar layer or of a face they touch (needs
                                     // options.input too)
  int reroute_cycles = 0;           // rerouted meshes arranged again (coplanar layers
                                    // then merge, one source for their area)
  std::size_t nudged = 0;           // moves of vertices by the last resort of nudging (by
                                    // 1 to 1024 ulps, from the rerouted mesh), summed over
                                    // its cycles: a vertex nudged in two counts twice
  std::size_t conflicts_left = 0;   // when refused (RoundingError): the fewest pairs of
                                    // triangles meeting beyond what they share (violating
                                    // pairs) that rerouting or nudging left,
                                    // here or on a changed input (0: neither ran); the
                                    // message gives it too. 0 when settled.
};

// The report's figures in `stats` (the round_* keys of arrange_stats.h), and the counts of
// the mesh that is written (out_vertices, out_edges, out_triangles, euler: the rounded
// mesh's, not the exact arrangement's). O(#F + #V).
void add_round_report(const RoundReport& report, const RoundedMesh& written, ArrangeStats& stats);

struct RoundingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

RoundedMesh round_nearest(const OutputMesh& mesh);
RoundedMesh round_nearest(const ExactOutputMesh& mesh);

RoundedMesh round_safe(const OutputMesh& mesh, const RoundSafeOptions& options = {}, RoundReport* report = nullptr);
RoundedMesh round_safe(const ExactOutputMesh& mesh, const RoundSafeOptions& options = {},
                       RoundReport* report = nullptr);

}  // namespace arrangements
