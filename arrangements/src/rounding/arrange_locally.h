// arrange_locally: one pass of round_safe's arranging again (round_ladder.h), on the
// triangles that need it only.
//
// A triangle of a mesh is cut by the arrangement only where another triangle meets it
// beyond what the two share, and then the two form a violating pair (check_arrangement);
// a point the arrangement puts on a triangle's edge lies on every triangle of that edge and
// on the triangle that makes it, so those pairs violate too. The triangles of the violating
// pairs are therefore closed under cutting: arranging them alone and keeping the others as
// they are gives the arrangement of the whole mesh, while the pipeline's detection runs on
// a few triangles instead of all of them (the check that finds the pairs, incremental from
// pass to pass, is rounding/violation_tracker.h).
#pragma once

#include <utility>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/output_mesh.h"

namespace arrangements {

// The arrangement of m from its violating pairs.
//   m          a rounded mesh with distinct vertex positions, no degenerate triangle and no
//              two triangles on the same three vertices (mesh_on_positions makes them so)
//   violating  every pair (i, j) of m's triangles that meets beyond what it shares: all
//              of them (else the result is not an arrangement)
//   options    the arrangement's (threads)
//   stats      receives the pass's figures: intersecting_pairs (the violating pairs),
//              out_vertices and out_triangles (the result's)
// Returns the triangles of arrange(as_input(m)).mesh (the same geometry, provenance and
// label sets), in m's order: a triangle of no violating pair as it is, the others each
// replaced by their pieces; vertices: m's, then the new points. Exact. Cost: the
// arrangement of the violating pairs' triangles, plus O(#m) to assemble.
OutputMesh arrange_locally(const RoundedMesh& m, const std::vector<std::pair<int, int>>& violating,
                           const ArrangeOptions& options, ArrangeStats& stats);

}  // namespace arrangements
