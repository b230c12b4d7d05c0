// arrangements/boolean.h
//
// Exact mesh Booleans and CSG trees on the arrangement.
//
// boolean(input, tree, options): the arrangement of `input` (arrange.h), then, for every
// output triangle, the winding numbers of the operands on its two sides (decided exactly,
// stage 6: src/stages/6_winding.cpp), and the triangles where the CSG tree's value changes
// from outside to inside, oriented outwards.
//   input    a soup whose labels name the operands: label i is operand i (each file of
//            the CLI one label; a triangle with several labels belongs to each of them).
//            Every operand must be closed: for every operand, each edge is used as often
//            in one direction as in the other (a closed, consistently oriented surface,
//            self-intersecting or not, several components allowed); otherwise
//            OpenOperandError names the operand, the number of unbalanced edges and the
//            first one.
//   tree     a CSG tree over the operands (leaves name labels; every label used by the
//            input needs not appear: an operand absent from the tree is ignored)
//   options  as for arrange()
// Membership rule: a point is inside operand i where the winding number of operand i
// there is not zero (so a self-intersecting or doubly covered operand is still a solid,
// and an inverted one too). Union: inside any child; intersection: inside all;
// difference: inside the first and none of the others; xor: inside an odd number.
// Returns the boundary of the tree's solid: the output triangles separating an inside
// cell from an outside cell, each oriented so that its normal points out; vertices
// (unreferenced ones dropped), source and label sets as in arrange(). Coplanar overlaps
// are handled exactly (A u A = A, A \ A is empty, two boxes sharing a face unite
// without an inner face). Deterministic for any number of threads.
// Cost: the arrangement, plus O(T log T) for T output triangles (edges sorted), plus an
// exact sort around every edge used by more than two triangles, plus one ray cast
// against the input per connected component of the arrangement.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "arrangements/arrange.h"

namespace arrangements {

enum class BooleanOp { Union, Intersection, Difference, Xor };

// A node of a CSG tree: a leaf (operand >= 0: the label) or an operation over children
// (Difference: the first minus all others). Union, Difference and Xor of no children are
// the empty set; Intersection of none (all of space) is refused (std::invalid_argument).
struct CsgNode {
  int operand = -1;
  BooleanOp op = BooleanOp::Union;
  std::vector<CsgNode> children;

  static CsgNode leaf(int label) { return CsgNode{label, BooleanOp::Union, {}}; }
  static CsgNode of(BooleanOp op, std::vector<CsgNode> children) { return CsgNode{-1, op, std::move(children)}; }
};

// op applied to operands 0..n-1 in order (the CLI's `--boolean`).
CsgNode operation_tree(BooleanOp op, int n);

// Thrown when an operand is not closed (see above); what() names the operand (label),
// the count and the first unbalanced edge (its two vertices' coordinates).
struct OpenOperandError : std::runtime_error {
  using std::runtime_error::runtime_error;
  int operand = -1;            // the label
  std::size_t open_edges = 0;  // its unbalanced edges in the arrangement
};

ArrangeResult boolean(const TriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options);
ExactArrangeResult boolean(const ExactTriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options);

namespace detail {
// boolean() without validate_soup, for entry points that checked the soup at their own
// boundary (as detail::arrange_validated); the tree is still checked.
ArrangeResult boolean_validated(const TriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options);
ExactArrangeResult boolean_validated(const ExactTriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options);
}  // namespace detail

}  // namespace arrangements
