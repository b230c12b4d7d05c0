// Stage 6, second half: winding numbers per cell (see 6_winding.h).
#include "stages/6_winding.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <type_traits>

#include "arrangements/memory_budget.h"
#include "booleans/fan_order.h"
#include "booleans/point_orient.h"
#include "booleans/ray_winding.h"
#include "models/double_model.h"
#include "models/exact_model.h"

namespace arrangements {
namespace {

// Where to cast a component's ray from: the midpoint of the edge (v, u) at v that leans
// most towards +x, and the side of a triangle of that edge that faces the cell just
// beyond it along +x (the component's unbounded cell). v is the lexicographically largest
// vertex of the component; at_v are its triangles at v.
struct RayStart {
  int side;
  ExactVec3 origin;
};

template <class M>
RayStart ray_start(const BasicOutputMesh<typename M::Point>& mesh, int v, const std::vector<int>& at_v) {
  const ExactVec3 V = M::to_exact(mesh.vertices[v]);
  std::map<int, ExactVec3> exact;  // the neighbours' coordinates
  auto exact_of = [&](int id) -> const ExactVec3& {
    auto it = exact.find(id);
    if (it == exact.end()) it = exact.emplace(id, M::to_exact(mesh.vertices[id])).first;
    return it->second;
  };
  // The neighbour u whose direction from v makes the smallest angle with +x: the largest
  // dx / |u - v|; every dx <= 0, so the smallest dx^2 / |u - v|^2.
  int best = -1;
  CGAL::Gmpq best_dx2, best_len2;
  for (int f : at_v)
    for (int u : mesh.triangles[f]) {
      if (u == v || u == best) continue;
      const ExactVec3& U = exact_of(u);
      const CGAL::Gmpq dx = U[0] - V[0], dy = U[1] - V[1], dz = U[2] - V[2];
      const CGAL::Gmpq dx2 = dx * dx, len2 = dx2 + dy * dy + dz * dz;
      if (best < 0 || dx2 * best_len2 < best_dx2 * len2 || (dx2 * best_len2 == best_dx2 * len2 && u < best)) {
        best = u;
        best_dx2 = dx2;
        best_len2 = len2;
      }
    }
  // The fan of edge (v, best), ordered around it from the direction +x.
  std::vector<int> fan;
  std::vector<const ExactVec3*> third;
  std::vector<char> forward;  // the triangle runs v -> best
  for (int f : at_v) {
    const Tri& t = mesh.triangles[f];
    const int iv = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    if (t[(iv + 1) % 3] != best && t[(iv + 2) % 3] != best) continue;
    fan.push_back(f);
    forward.push_back(t[(iv + 1) % 3] == best);
    third.push_back(&exact_of(forward.back() ? t[(iv + 2) % 3] : t[(iv + 1) % 3]));
  }
  ExactVec3 beyond = V;
  beyond[0] += 1;
  std::vector<int> order(fan.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const ExactVec3& U = exact_of(best);
  order_around_axis(order, -1,
                    [&](int i, int j) { return orient3d_points(V, U, i < 0 ? beyond : *third[i], *third[j]); });
  // The first triangle after +x faces it with its side towards decreasing angle.
  const int first = order.front();
  ExactVec3 mid = V;
  for (int k = 0; k < 3; ++k) mid[k] = (V[k] + U[k]) / 2;
  return {2 * fan[first] + (forward[first] ? 1 : 0), mid};
}

// A point of the output's frame in the soup's (scaled by 2^k).
ExactVec3 scaled(ExactVec3 p, int k) {
  if (k == 0) return p;
  const CGAL::Gmpq factor(std::ldexp(1.0, k));
  for (CGAL::Gmpq& c : p) c *= factor;
  return p;
}

}  // namespace

template <class M>
CellWindings cell_windings(const BasicOutputMesh<typename M::Point>& mesh, const SideCells& sides,
                           const OperandWeights& deltas, const BasicTriangleSoup<typename M::Vertex>& soup,
                           const OperandWeights& soup_weights, int operands, int scale_exponent) {
  const std::size_t nT = mesh.triangles.size();
  const int cells = sides.cells;
  // Cells -> triangles bounding them.
  std::vector<std::size_t> begin(cells + 1, 0);
  for (int c : sides.cell) ++begin[c + 1];
  for (int c = 0; c < cells; ++c) begin[c + 1] += begin[c];
  std::vector<int> adjacent(begin[cells]);
  {
    std::vector<std::size_t> at(begin.begin(), begin.end() - 1);
    for (std::size_t s = 0; s < 2 * nT; ++s) adjacent[at[sides.cell[s]]++] = static_cast<int>(s / 2);
  }
  // Walk each component from its first cell: numbers relative to that cell.
  CellWindings out;
  out.operands = operands;
  std::vector<int>& w = out.winding;
  w.assign(static_cast<std::size_t>(cells) * operands, 0);
  std::vector<int> component(cells, -1);
  std::deque<int> queue;
  // A cell is numbered when first reached: its neighbour's numbers plus the jump (only
  // the jump's entries differ). Reaching it again agrees: every operand is balanced
  // around every edge (checked by side_cells), so the numbers are well defined.
  for (int start = 0; start < cells; ++start) {
    if (component[start] >= 0) continue;
    component[start] = static_cast<int>(out.components++);
    queue.push_back(start);
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      for (std::size_t k = begin[c]; k < begin[c + 1]; ++k) {
        const int f = adjacent[k];
        const int front = sides.cell[2 * f], back = sides.cell[2 * f + 1];
        const int to = c == front ? back : front;
        if (component[to] >= 0) continue;
        component[to] = component[c];
        const int sign = c == front ? 1 : -1;
        std::copy_n(&w[static_cast<std::size_t>(c) * operands], operands, &w[static_cast<std::size_t>(to) * operands]);
        for (auto it = deltas.row_begin(f); it != deltas.row_end(f); ++it)
          w[static_cast<std::size_t>(to) * operands + it->first] += sign * it->second;
        queue.push_back(to);
      }
    }
  }
  // Per component: its lexicographically largest vertex (explicit points suffice).
  std::vector<int> top(out.components, -1);
  for (std::size_t f = 0; f < nT; ++f) {
    const int comp = component[sides.cell[2 * f]];
    for (int v : mesh.triangles[f]) {
      if constexpr (std::is_same_v<typename M::Point, tritri::ImplicitPoint>)
        if (!mesh.vertices[v].is_explicit()) continue;
      if (top[comp] < 0 || (v != top[comp] && M::compare_xyz(mesh.vertices[v], mesh.vertices[top[comp]]) > 0))
        top[comp] = v;
    }
  }
  std::vector<std::vector<int>> at_top(out.components);
  for (std::size_t f = 0; f < nT; ++f) {
    const int comp = component[sides.cell[2 * f]];
    const Tri& t = mesh.triangles[f];
    if (t[0] == top[comp] || t[1] == top[comp] || t[2] == top[comp]) at_top[comp].push_back(static_cast<int>(f));
  }
  std::vector<std::array<Vec3, 2>> boxes(soup.triangles.size());
  tbb::parallel_for(std::size_t{0}, soup.triangles.size(), [&](std::size_t t) {
    detail::memory_checkpoint();
    Vec3 lo, hi;
    boxes[t] = {Vec3{HUGE_VAL, HUGE_VAL, HUGE_VAL}, Vec3{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
    for (int v : soup.triangles[t]) {
      M::bounds(soup.vertices[v], lo, hi);
      for (int k = 0; k < 3; ++k) {
        boxes[t][0][k] = std::min(boxes[t][0][k], lo[k]);
        boxes[t][1][k] = std::max(boxes[t][1][k], hi[k]);
      }
    }
  });
  // The constant of each component: its unbounded cell holds the other components' numbers.
  std::vector<int> offset(out.components * static_cast<std::size_t>(operands));
  tbb::parallel_for(std::size_t{0}, out.components, [&](std::size_t comp) {
    const RayStart start = ray_start<M>(mesh, top[comp], at_top[comp]);
    const int cell = sides.cell[start.side];
    const std::vector<int> outside =
        winding_beyond<M>(scaled(start.origin, scale_exponent), soup, soup_weights, boxes, operands);
    for (int i = 0; i < operands; ++i)
      offset[comp * operands + i] = outside[i] - w[static_cast<std::size_t>(cell) * operands + i];
  });
  for (int c = 0; c < cells; ++c)
    for (int i = 0; i < operands; ++i)
      w[static_cast<std::size_t>(c) * operands + i] += offset[static_cast<std::size_t>(component[c]) * operands + i];
  return out;
}

template CellWindings cell_windings<DoubleModel>(const OutputMesh&, const SideCells&, const OperandWeights&,
                                                 const TriangleSoup&, const OperandWeights&, int, int);
template CellWindings cell_windings<ExactModel>(const BasicOutputMesh<ExactModel::Point>&, const SideCells&,
                                                const OperandWeights&, const BasicTriangleSoup<ExactModel::Vertex>&,
                                                const OperandWeights&, int, int);

}  // namespace arrangements
