// arrangements/src/stages/6_boolean.h
//
// Stage 6 (Booleans only; arrangements/boolean.h): from the arrangement to the boundary
// of a CSG tree's solid.
//
// boolean_stage<M>(mesh, soup, kept_as, input, info, tree, scale_exponent, stats):
//   mesh            stage 5's output (internal points), replaced by the tree's boundary
//   soup, kept_as   stage 1's soup and its map from input triangles (PreprocessOptions)
//   input           the pipeline's input (its label sets name the operands)
//   info            stage 5's TriangulationInfo, filled with keep_covers
// Steps: the operands' signed counts per soup triangle and their jumps across every
// output triangle (booleans/operand_weights.h), the sides grouped into cells around the
// edges (6_side_cells.h, which also refuses an operand that is not closed), the winding
// numbers per cell (6_winding.h), and the triangles between inside and outside
// (booleans/csg_select.h). Fills stats.winding_cells and winding_components.
// Exact; deterministic; cost: see those headers (about linear in the output).
#pragma once

#include <vector>

#include "arrangements/arrange_stats.h"
#include "arrangements/boolean.h"
#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"
#include "stages/5_triangulate.h"

namespace arrangements {

template <class M, class InputCoordinates>
void boolean_stage(BasicOutputMesh<typename M::Point>& mesh, const BasicTriangleSoup<typename M::Vertex>& soup,
                   const std::vector<int>& kept_as, const BasicTriangleSoup<InputCoordinates>& input,
                   const TriangulationInfo& info, const CsgNode& tree, int scale_exponent, ArrangeStats& stats);

}  // namespace arrangements
