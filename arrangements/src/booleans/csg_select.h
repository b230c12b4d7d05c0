// arrangements/src/booleans/csg_select.h (internal to the Boolean stage)
//
// inside_tree(tree, w): whether a cell whose winding numbers are w (one per operand,
// `operands` of them) is inside the CSG tree's solid: a leaf is inside where its
// operand's winding number is not zero (operands beyond w: never); Union: inside any
// child (none: never); Intersection: inside every child; Difference: inside the first
// and no other; Xor: inside an odd number. O(tree size).
//
// boundary_of(mesh, sides, windings, tree): the output triangles that separate a cell
// inside the tree's solid from one outside, each turned (two corners swapped) when its
// front is the inside one, so that every normal points out; vertices not used any more
// are dropped (the others keep their order), source and label sets follow their
// triangles. O(T + cells x tree size), in parallel over cells.
#pragma once

#include "arrangements/boolean.h"
#include "arrangements/output_mesh.h"
#include "stages/6_side_cells.h"
#include "stages/6_winding.h"

namespace arrangements {

bool inside_tree(const CsgNode& tree, const int* w, int operands);

template <class Point>
BasicOutputMesh<Point> boundary_of(BasicOutputMesh<Point>&& mesh, const SideCells& sides,
                                   const CellWindings& windings, const CsgNode& tree);

}  // namespace arrangements
