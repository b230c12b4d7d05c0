// nudge_conflicts: a last resort of round_safe (arrangements/round_mesh.h), for the few
// conflicts that rerouting (round_rerouting.h) leaves: a grazing crossing far from any
// vertex, which rerouting has nothing within an ulp to put on, and which arranging again
// only moves by half an ulp / sin(angle) per cycle.
//
// Vertices move, triangles do not: a local search on the grid of `step` (an ulp of the
// largest coordinate magnitude). In each round, every corner of a violating pair in turn
// tries the 26 positions 1 step around it, then 2, 4, ... 1024 steps (rings), and at the
// first ring that has one, takes the position that leaves the fewest violating pairs among
// its triangles and their neighbours (exact: the rule of check_arrangement per pair,
// support/pair_fault.h), if that is fewer than where it is: the smallest move that helps.
// A position that makes a triangle degenerate, or that is farther than `move_limit` from
// where the vertex started (an exact bound), is not tried.
//
// Termination: each move lowers the number of violating pairs of the whole mesh (only the
// pairs of its triangles change), so there are at most as many moves as violations at the
// start; a round without a move ends it, and so does max_rounds.
// Cost per round: one check (check_arrangement the first round, later ones only the pairs
// with a triangle that the last round's moves changed), one box search of the
// violating corners' triangles against all, then per corner and ring tried 26 x (pairs of
// the corner's triangles with neighbours whose boxes meet) classifications at most (a
// count stops where it reaches the current one; the corner's violating pairs are counted
// first, so a position that leaves them violating stops after them). Meant for few conflicts (round_safe calls
// it on at most 1024, or on a 20th of the triangles where that is more).
#pragma once

#include <cstddef>

#include "arrangements/output_mesh.h"

namespace arrangements {

struct Nudged {
  RoundedMesh mesh;            // the start with its vertices moved
  std::size_t violations = 0;  // violating pairs left (0: an arrangement)
  std::size_t moved = 0;       // vertices not where they started
  double max_move = 0;         // bound of the largest distance a vertex moved from the start
  int rounds = 0;              // checks made
};

// start: a rounded mesh without degenerate triangles or two vertices at one position
// (mesh_on_positions makes one); step > 0; move_limit >= 0.
Nudged nudge_conflicts(const RoundedMesh& start, double step, double move_limit, int max_rounds);

}  // namespace arrangements
