// arrangements/src/booleans/operand_weights.h (internal to the Boolean stage)
//
// What each triangle adds to the operands' winding numbers.
//
// OperandWeights: a sparse table, per row (a triangle), of (operand, count) entries with
// count != 0, operands increasing: row r is items[begin[r] .. begin[r + 1]).
//
// soup_weights(kept_as, input_label_set, input_label_sets, soup_triangles): per soup
// triangle (stage 1's output), the signed number of input triangles of each operand that
// it stands for: +1 for each copy with its orientation, -1 for each copy turned the other
// way (kept_as: PreprocessOptions::kept_as; the operands of an input triangle are the
// labels of its label set). A triangle and its reversed copy in one operand cancel (a
// two-sided sheet adds nothing to that operand's winding number).
//
// output_deltas<M>(soup, soup_weights, emitted_by, cover_of, covers, output_triangles):
// per output triangle (stage 5's, with TriangulationInfo::keep_covers), the jump of each
// operand's winding number across it: winding behind it minus winding in front of it
// (front: where its normal, by its corner order, points). That is the sum of the weights
// of the soup triangles covering it, each counted with +1 when it runs the same way as
// the output triangle and -1 otherwise (decided by an exact orient2d in a projection
// where the emitting triangle is not degenerate).
// Cost: O(entries log entries) and O(covers) exact orient2d. Deterministic.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct OperandWeights {
  std::vector<std::size_t> begin{0};
  std::vector<std::pair<int, int>> items;  // (operand, count)

  std::size_t rows() const { return begin.size() - 1; }
  const std::pair<int, int>* row_begin(std::size_t r) const { return items.data() + begin[r]; }
  const std::pair<int, int>* row_end(std::size_t r) const { return items.data() + begin[r + 1]; }
};

OperandWeights soup_weights(const std::vector<int>& kept_as, const std::vector<int>& input_label_set,
                            const std::vector<LabelSet>& input_label_sets, std::size_t soup_triangles);

template <class M>
OperandWeights output_deltas(const BasicTriangleSoup<typename M::Vertex>& soup, const OperandWeights& soup_weights,
                             const std::vector<int>& emitted_by, const std::vector<int>& cover_of,
                             const std::vector<std::vector<int>>& covers);

}  // namespace arrangements
