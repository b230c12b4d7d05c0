// Stage 6, first half: sides of output triangles grouped into cells around every edge
// (see 6_side_cells.h).
#include "stages/6_side_cells.h"

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "arrangements/boolean.h"
#include "arrangements/memory_budget.h"
#include "booleans/fan_order.h"
#include "booleans/point_orient.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "support/union_find.h"

namespace arrangements {
namespace {

std::string point_text(const Vec3& p) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p[0], p[1], p[2]);
  return buf;
}

}  // namespace

template <class M>
SideCells side_cells(const BasicOutputMesh<typename M::Point>& mesh, const OperandWeights& deltas) {
  using Point = typename M::Point;
  const std::size_t nT = mesh.triangles.size();
  const std::uint64_t nV = mesh.vertices.size();
  // Half-edges keyed by their undirected edge; each run of equal keys is one edge's fan.
  std::vector<std::pair<std::uint64_t, int>> half(3 * nT);
  tbb::parallel_for(std::size_t{0}, nT, [&](std::size_t f) {
    detail::memory_checkpoint();
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = t[k], b = t[(k + 1) % 3];
      half[3 * f + k] = {std::min(a, b) * nV + std::max(a, b), static_cast<int>(3 * f + k)};
    }
  });
  tbb::parallel_sort(half.begin(), half.end());
  std::vector<std::size_t> run_start;
  for (std::size_t i = 0; i < half.size(); ++i)
    if (i == 0 || half[i].first != half[i - 1].first) run_start.push_back(i);
  run_start.push_back(half.size());
  const std::size_t runs = run_start.size() - 1;

  // Per run: the balance check, then one pair of sides to unite per wedge.
  std::vector<std::pair<int, int>> unite(half.size());
  tbb::concurrent_vector<std::pair<std::size_t, int>> unbalanced;  // (run, operand)
  tbb::parallel_for(std::size_t{0}, runs, [&](std::size_t r) {
    const std::size_t s = run_start[r], e = run_start[r + 1];
    const int a = static_cast<int>(half[s].first / nV);  // the smaller endpoint
    const int b = static_cast<int>(half[s].first % nV);
    auto face = [&](std::size_t i) { return half[i].second / 3; };
    // +1 when the triangle runs a -> b along the edge
    auto forward = [&](std::size_t i) { return mesh.triangles[face(i)][half[i].second % 3] == a; };
    std::vector<std::pair<int, int>> sum;
    for (std::size_t i = s; i < e; ++i)
      for (auto it = deltas.row_begin(face(i)); it != deltas.row_end(face(i)); ++it)
        sum.emplace_back(it->first, forward(i) ? it->second : -it->second);
    std::sort(sum.begin(), sum.end());
    for (std::size_t i = 0; i < sum.size();) {
      std::size_t j = i;
      int total = 0;
      for (; j < sum.size() && sum[j].first == sum[i].first; ++j) total += sum[j].second;
      if (total != 0) unbalanced.push_back({r, sum[i].first});
      i = j;
    }
    std::vector<int> order(e - s);
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    if (order.size() > 2) {
      std::vector<const Point*> third(order.size());
      for (std::size_t i = 0; i < order.size(); ++i) {
        const Tri& t = mesh.triangles[face(s + i)];
        const int k = half[s + i].second % 3;
        third[i] = &mesh.vertices[t[(k + 2) % 3]];
      }
      // Pieces of the reference's own input triangle lie in its plane, across the edge.
      std::vector<char> opposite(order.size(), 0);
      for (std::size_t i = 1; i < order.size(); ++i)
        opposite[i] = mesh.source[face(s + i)] == mesh.source[face(s)];
      order_around_axis(
          mesh.vertices[a], mesh.vertices[b], *third[0], third, order, 0,
          [](const Point& p, const Point& q, const Point& x, const Point& y) { return orient3d_points(p, q, x, y); },
          &opposite);
    }
    // The wedge after triangle j (by angle) is faced by j's side towards increasing angle
    // (front if it runs a -> b) and by the next triangle's side towards decreasing angle.
    for (std::size_t j = 0; j < order.size(); ++j) {
      const std::size_t x = s + order[j], y = s + order[(j + 1) % order.size()];
      const int side_x = 2 * face(x) + (forward(x) ? 0 : 1);
      const int side_y = 2 * face(y) + (forward(y) ? 1 : 0);
      unite[s + j] = {side_x, side_y};
    }
  });
  if (!unbalanced.empty()) {
    std::vector<std::pair<std::size_t, int>> u(unbalanced.begin(), unbalanced.end());
    std::sort(u.begin(), u.end(), [](const auto& x, const auto& y) {
      return x.second != y.second ? x.second < y.second : x.first < y.first;
    });
    std::size_t count = 0;
    for (const auto& x : u) count += x.second == u[0].second;
    const std::uint64_t key = half[run_start[u[0].first]].first;
    const std::string edge = point_text(M::to_double(mesh.vertices[key / nV])) + " - " +
                             point_text(M::to_double(mesh.vertices[key % nV]));
    OpenOperandError error("operand " + std::to_string(u[0].second) + " is not closed: " + std::to_string(count) +
                           " edge" + (count == 1 ? "" : "s") +
                           " of the arrangement where its triangles do not balance (open, or inconsistently "
                           "oriented); the first: " + edge);
    error.operand = u[0].second;
    error.open_edges = count;
    throw error;
  }
  half = {};
  UnionFind sets(2 * nT);
  for (const auto& [x, y] : unite) sets.unite(x, y);
  SideCells out;
  out.cell.assign(2 * nT, -1);
  std::vector<int> cell_of_root(2 * nT, -1);
  for (std::size_t side = 0; side < 2 * nT; ++side) {
    int& c = cell_of_root[sets.find(static_cast<int>(side))];
    if (c < 0) c = out.cells++;
    out.cell[side] = c;
  }
  return out;
}

template SideCells side_cells<DoubleModel>(const OutputMesh&, const OperandWeights&);
template SideCells side_cells<ExactModel>(const BasicOutputMesh<ExactModel::Point>&, const OperandWeights&);

}  // namespace arrangements
