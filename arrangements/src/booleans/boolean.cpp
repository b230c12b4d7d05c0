// boolean(): the pipeline with stage 6 (arrangements/boolean.h).
#include "arrangements/boolean.h"

#include <stdexcept>
#include <string>

#include "pipeline.h"

namespace arrangements {
namespace {

void validate_tree(const CsgNode& node, int depth) {
  if (depth > 100000) throw std::invalid_argument("boolean: the CSG tree is deeper than 100000 levels");
  if (node.operand >= 0) {
    if (!node.children.empty()) throw std::invalid_argument("boolean: a CSG leaf (an operand) has children");
    return;
  }
  if (node.operand < -1) throw std::invalid_argument("boolean: a CSG leaf names a negative operand");
  if (node.op == BooleanOp::Intersection && node.children.empty())
    throw std::invalid_argument("boolean: an intersection of no operand (all of space) is not a solid");
  for (const CsgNode& c : node.children) validate_tree(c, depth + 1);
}

}  // namespace

CsgNode operation_tree(BooleanOp op, int n) {
  std::vector<CsgNode> leaves;
  for (int i = 0; i < n; ++i) leaves.push_back(CsgNode::leaf(i));
  return CsgNode::of(op, std::move(leaves));
}

ArrangeResult boolean(const TriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options) {
  validate_soup(input);
  return detail::boolean_validated(input, tree, options);
}

ExactArrangeResult boolean(const ExactTriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options) {
  validate_soup(input);
  return detail::boolean_validated(input, tree, options);
}

ArrangeResult detail::boolean_validated(const TriangleSoup& input, const CsgNode& tree, const ArrangeOptions& options) {
  validate_tree(tree, 0);
  return run_pipeline(input, options, nullptr, &tree);
}

ExactArrangeResult detail::boolean_validated(const ExactTriangleSoup& input, const CsgNode& tree,
                                             const ArrangeOptions& options) {
  validate_tree(tree, 0);
  return run_pipeline(input, options, nullptr, &tree);
}

}  // namespace arrangements
