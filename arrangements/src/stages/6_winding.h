// arrangements/src/stages/6_winding.h
//
// Stage 6, second half (the Boolean stage; arrangements/boolean.h): the winding number of
// every operand in every cell.
//
// cell_windings<M>(mesh, sides, deltas, soup, soup_weights, operands, scale_exponent):
//   mesh, deltas   stage 5's output mesh and its jumps (booleans/operand_weights.h)
//   sides          its sides grouped into cells (6_side_cells.h)
//   soup, soup_weights, scale_exponent   stage 1's soup (in the frame scaled by
//                  2^scale_exponent), with per soup triangle its operands' signed counts
// returns per cell the winding number of each operand (cells x operands, row-major) and
// the number of connected components of the arrangement (triangles joined by edges).
// How: across every triangle, winding behind = winding in front + its jump, so a walk
// over the cells of one component gives their numbers up to one constant vector. The
// constant: the component's lexicographically largest vertex v (an input vertex, since
// an extreme point of a union of triangles is a corner of one) has the whole component at
// x <= v.x, so the cell just beyond v along +x is the component's unbounded cell; it is
// found exactly around the edge at v that leans most towards +x (no triangle of that
// edge's fan lies in the half-plane from the edge towards +x, so +x falls strictly in one
// wedge). The winding numbers there are those of all the other components (constant
// along the component, which they never cross), counted by a ray cast along +x from the
// midpoint of that edge (a point of the component that no other component touches)
// against the whole soup (booleans/ray_winding.h; the component itself adds nothing
// beyond that point).
// Exact throughout (rational arithmetic on the few points around each v). Deterministic.
// Cost: O(cells x operands + T) for the walk, plus one ray cast, O(#soup triangles), per
// component (in parallel).
#pragma once

#include <cstddef>
#include <vector>

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"
#include "booleans/operand_weights.h"
#include "stages/6_side_cells.h"

namespace arrangements {

struct CellWindings {
  int operands = 0;
  std::vector<int> winding;  // cell c, operand i: winding[c * operands + i]
  std::size_t components = 0;
};

template <class M>
CellWindings cell_windings(const BasicOutputMesh<typename M::Point>& mesh, const SideCells& sides,
                           const OperandWeights& deltas, const BasicTriangleSoup<typename M::Vertex>& soup,
                           const OperandWeights& soup_weights, int operands, int scale_exponent);

}  // namespace arrangements
