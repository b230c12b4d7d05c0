#include "booleans/csg_select.h"

#include <tbb/parallel_for.h>

#include <utility>

#include "models/exact_model.h"

namespace arrangements {

bool inside_tree(const CsgNode& tree, const int* w, int operands) {
  if (tree.operand >= 0) return tree.operand < operands && w[tree.operand] != 0;
  const auto& ch = tree.children;
  switch (tree.op) {
    case BooleanOp::Union:
      for (const CsgNode& c : ch)
        if (inside_tree(c, w, operands)) return true;
      return false;
    case BooleanOp::Intersection:
      if (ch.empty()) return false;
      for (const CsgNode& c : ch)
        if (!inside_tree(c, w, operands)) return false;
      return true;
    case BooleanOp::Difference:
      if (ch.empty() || !inside_tree(ch[0], w, operands)) return false;
      for (std::size_t i = 1; i < ch.size(); ++i)
        if (inside_tree(ch[i], w, operands)) return false;
      return true;
    case BooleanOp::Xor: {
      bool odd = false;
      for (const CsgNode& c : ch) odd ^= inside_tree(c, w, operands);
      return odd;
    }
  }
  return false;
}

template <class Point>
BasicOutputMesh<Point> boundary_of(BasicOutputMesh<Point>&& mesh, const SideCells& sides,
                                   const CellWindings& windings, const CsgNode& tree) {
  const int n = windings.operands;
  std::vector<char> inside(sides.cells);
  tbb::parallel_for(0, sides.cells, [&](int c) {
    inside[c] = inside_tree(tree, windings.winding.data() + static_cast<std::size_t>(c) * n, n);
  });
  BasicOutputMesh<Point> out;
  std::vector<int> vertex(mesh.vertices.size(), -1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const bool front = inside[sides.cell[2 * f]], back = inside[sides.cell[2 * f + 1]];
    if (front == back) continue;
    Tri t = mesh.triangles[f];
    if (front) std::swap(t[1], t[2]);  // the normal must point to the outside cell
    for (int& v : t) {
      if (vertex[v] < 0) {
        vertex[v] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(std::move(mesh.vertices[v]));
      }
      v = vertex[v];
    }
    out.triangles.push_back(t);
    out.source.push_back(mesh.source[f]);
    out.label_set.push_back(mesh.label_set[f]);
  }
  out.label_sets = std::move(mesh.label_sets);
  return out;
}

template OutputMesh boundary_of(OutputMesh&&, const SideCells&, const CellWindings&, const CsgNode&);
template BasicOutputMesh<ExactModel::Point> boundary_of(BasicOutputMesh<ExactModel::Point>&&, const SideCells&,
                                                        const CellWindings&, const CsgNode&);

}  // namespace arrangements
