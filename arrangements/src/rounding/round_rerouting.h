// reroute_conflicts: the first last resort of round_safe (arrangements/round_mesh.h), for
// meshes on which the passes of rounding to nearest and re-arranging do not converge.
//
// Every vertex stays at its nearest double; only the triangles change. Rounding by half an
// ulp breaks an arrangement where a feature is thinner than an ulp: a sliver whose apex lies
// within an ulp of its longest edge folds over its neighbours, a vertex within an ulp of an
// edge or a face crosses it. Snap rounding's rule in 2D (a segment through a hot pixel is
// rerouted through the pixel's vertex) is applied to those features, decided exactly on the
// rounded coordinates against the distance `delta`:
//   - a sliver (the apex within delta of the longest edge, projecting inside it) is dropped,
//     and its apex is put on that edge;
//   - of a violating pair of other triangles, the vertex of one closest to an edge of the
//     other (within delta, projecting inside it) is put on that edge, else one within delta
//     of the other's face (projecting inside it) splits that face into three;
//   - putting vertices on an edge splits every triangle on that edge into a fan through them
//     (in order along the edge); a triangle with one of them as a corner is dropped (a
//     sliver, flat now).
// The first round treats every sliver of the mesh, later rounds those of violating pairs.
// Each round checks the result exactly (check_arrangement); each round moves the surface by
// at most delta (rounds x delta from the rounded one); provenance is kept (a piece of a split triangle keeps its
// source and label set; a dropped sliver has no area beyond delta).
//
// Termination: at most max_rounds rounds; it stops earlier after 3 rounds in a row without
// fewer violations than the best round. What is left of the conflicts then is for the
// cycles of arranging again, the input steps, level 1 and nudging (round_ladder.h).
// Cost per round: one check (rounding/violation_tracker.h: the first round every pair, later
// ones only the pairs with a triangle the round before did not have), exact distance tests
// (rationals of the doubles, after a double filter) on the triangles of violating pairs, a
// hash map of the edges.
#pragma once

#include <cstdint>
#include <vector>

#include "arrangements/output_mesh.h"
#include "rounding/violation_tracker.h"

namespace arrangements {

struct Rerouting {
  // The best round's triangles over the input vertices, with their provenance.
  std::vector<Tri> triangles;
  std::vector<std::int64_t> source;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
  std::size_t violations = 0;  // of the best round: 0 when it is an arrangement
  int rounds = 0;              // checks made
  std::size_t rerouted = 0;    // vertices put on an edge or a face, in all rounds up to the best
};

// position: every vertex of the arrangement rounded to the nearest double; triangles,
// source, label_set, label_sets: the arrangement's (output_mesh.h); delta > 0.
// tracker: checks each round's mesh (rounding/violation_tracker.h), incrementally from
// whatever mesh it checked last (the caller's passes over the same vertices, say).
// closed: the triangles bound solids and stay closed: every triangle on an edge that gets
// vertices is split through them (a sliver over the edge too, its flat pieces collapsed in
// turn), and each round's cleaning cancels opposite faces (mesh_on_positions). Not closed,
// a sliver over such an edge is dropped whole (what that leaves, the next round's check
// finds), which the sweep measures as the better trade for arrangements.
Rerouting reroute_conflicts(const std::vector<Vec3>& position, const std::vector<Tri>& triangles,
                            const std::vector<std::int64_t>& source, const std::vector<int>& label_set,
                            const std::vector<LabelSet>& label_sets, double delta, int max_rounds,
                            ViolationTracker& tracker, bool closed = false);

}  // namespace arrangements
