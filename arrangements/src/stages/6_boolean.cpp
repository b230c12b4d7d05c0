// Stage 6: the Boolean of the arrangement (see 6_boolean.h).
#include "stages/6_boolean.h"

#include <algorithm>

#include "booleans/csg_select.h"
#include "booleans/operand_weights.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/6_side_cells.h"
#include "stages/6_winding.h"

namespace arrangements {

template <class M, class InputCoordinates>
void boolean_stage(BasicOutputMesh<typename M::Point>& mesh, const BasicTriangleSoup<typename M::Vertex>& soup,
                   const std::vector<int>& kept_as, const BasicTriangleSoup<InputCoordinates>& input,
                   const TriangulationInfo& info, const CsgNode& tree, int scale_exponent, ArrangeStats& stats) {
  int operands = 0;
  for (const LabelSet& s : input.label_sets)
    for (std::uint32_t l : s) operands = std::max(operands, static_cast<int>(l) + 1);
  const OperandWeights weights = soup_weights(kept_as, input.label_set, input.label_sets, soup.triangles.size());
  const OperandWeights deltas = output_deltas<M>(soup, weights, info.emitted_by, info.cover_of, info.covers);
  const SideCells sides = side_cells<M>(mesh, deltas, soup, info.emitted_by, scale_exponent);
  const CellWindings windings = cell_windings<M>(mesh, sides, deltas, soup, weights, operands, scale_exponent);
  stats.winding_cells = static_cast<std::size_t>(sides.cells);
  stats.winding_components = windings.components;
  mesh = boundary_of(std::move(mesh), sides, windings, tree);
}

template void boolean_stage<DoubleModel, Vec3>(OutputMesh&, const TriangleSoup&, const std::vector<int>&,
                                               const TriangleSoup&, const TriangulationInfo&, const CsgNode&, int,
                                               ArrangeStats&);
template void boolean_stage<ExactModel, ExactVec3>(BasicOutputMesh<ExactModel::Point>&,
                                                   const BasicTriangleSoup<ExactModel::Vertex>&,
                                                   const std::vector<int>&, const ExactTriangleSoup&,
                                                   const TriangulationInfo&, const CsgNode&, int, ArrangeStats&);

}  // namespace arrangements
