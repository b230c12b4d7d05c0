// arrangements/src/stages/6_side_cells.h
//
// Stage 6, first half (the Boolean stage; arrangements/boolean.h): which sides of the
// output triangles face the same cell of space.
//
// side_cells<M>(mesh, deltas, soup, emitted_by, scale_exponent): every output triangle f
// has two sides, 2 f (front: where its normal points, by its corner order) and 2 f + 1
// (back). Around each edge of the arrangement the triangles using it are ordered exactly
// by angle (orient3d of a triangle's third corner against the plane of the soup triangle
// that emitted the other, whose orientation it keeps; an edge of two triangles needs no
// predicate), and the two sides that face each other across each wedge between
// neighbours lie in one cell. Returns the sides grouped into cells: cell[s] in
// 0..cells-1, numbered in order of their first side (so the result does not depend on
// the number of threads). Cells reached only through a vertex (two solids touching at a
// corner) or not at all (nested shells) stay apart: stage 6's second half (6_winding.h)
// places them.
//   deltas   per output triangle, the jump of each operand's winding number across it
//            (booleans/operand_weights.h)
//   soup, emitted_by, scale_exponent   stage 1's soup (in the frame scaled by
//            2^scale_exponent) and, per output triangle, the soup triangle that emitted it
//            (TriangulationInfo::emitted_by)
// Checks that every operand is closed on the arrangement: around every edge, its jumps
// summed with the edge's direction in each triangle cancel; otherwise throws
// OpenOperandError naming the smallest such operand, its number of unbalanced edges and
// the first of them (its endpoints, rounded to doubles).
// Cost: O(T + sum of d log d over the vertices' d edges) for T triangles to group the
// edges (a counting sort by vertex, then each vertex's edges sorted), plus O(k log k)
// exact orient3d for every edge of k > 2 triangles (in parallel), plus a union-find.
#pragma once

#include <vector>

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"
#include "booleans/operand_weights.h"

namespace arrangements {

struct SideCells {
  std::vector<int> cell;  // per side 2 f + (0 front, 1 back)
  int cells = 0;
};

template <class M>
SideCells side_cells(const BasicOutputMesh<typename M::Point>& mesh, const OperandWeights& deltas,
                     const BasicTriangleSoup<typename M::Vertex>& soup, const std::vector<int>& emitted_by,
                     int scale_exponent);

}  // namespace arrangements
