// round_per_vertex: the last resort of round_safe (arrangements/round_mesh.h), for meshes
// on which the passes of rounding and re-arranging do not converge.
//
// It never arranges again, so it makes no new points: every vertex of the exact
// arrangement is rounded, to the nearest double first; each round checks the rounded mesh
// exactly (check_arrangement) and moves every vertex of every violating pair to the next
// coarser grid (level j: the uniform grid of 2^(2j) ulps of the largest coordinate
// magnitude, j <= 16, that is 2^32 ulps, the coarsest grid of the passes). Vertices that
// land on one position become one vertex; triangles that collapse to an edge or a point
// are dropped; triangles that land on the same three vertices become one, with the union
// of their label sets. Features thinner than a cell (two layers of near-coincident
// surfaces, slivers) collapse where they conflict, and only there.
//
// Termination: every round that does not succeed raises the level of at least one vertex,
// and levels are bounded, so there are at most 16 x #vertices rounds; `max_rounds` bounds
// them further. Returns nullopt when a vertex would need a grid coarser than 2^32 ulps or
// would move by more than `move_limit` (its distance_bound, rounding/rounding_grid.h), when
// 2 rounds in a row found no fewer violations than the best round before them (coarsening
// then spreads the conflicts instead of removing them), or when the rounds run out.
// Displacement: a vertex moves by at most half a cell diagonal of its level from its
// nearest double (reported exactly bounded, from the rationals).
// Cost per round: one sort of the vertices and one check of the rounded mesh (support/
// violation_tracker.h: after the first round, only the pairs with a triangle that moved).
#pragma once

#include <optional>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

struct PerVertexRounding {
  RoundedMesh mesh;
  int rounds = 0;            // checks made (the last one passed)
  std::size_t coarsened = 0; // vertices rounded to a grid coarser than the doubles
  double grid = 0;           // spacing of the coarsest grid used (0: nearest doubles only)
  double max_move = 0;       // bound of the largest distance between a vertex and its exact position
};

// exact: every vertex of the exact arrangement; nearest: the same rounded to the nearest
// double; triangles, source, label_set, label_sets: the arrangement's (output_mesh.h);
// largest: the largest coordinate magnitude of `nearest` (the grids are its ulps);
// move_limit: the largest move a result may have (round_safe refuses any beyond it).
std::optional<PerVertexRounding> round_per_vertex(const std::vector<ExactVec3>& exact,
                                                  const std::vector<Vec3>& nearest, const std::vector<Tri>& triangles,
                                                  const std::vector<std::int64_t>& source,
                                                  const std::vector<int>& label_set,
                                                  const std::vector<LabelSet>& label_sets, double largest,
                                                  int max_rounds, double move_limit);

}  // namespace arrangements
