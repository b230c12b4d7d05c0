// round_per_vertex (round_per_vertex.h): rounding every vertex of the exact arrangement
// to a grid of its own, coarser only where the rounded mesh is not an arrangement.
#include "rounding/round_per_vertex.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstddef>

#include "arrangements/memory_budget.h"
#include "rounding/mesh_on_positions.h"
#include "rounding/rounding_grid.h"
#include "rounding/violation_tracker.h"

namespace arrangements {
namespace {

constexpr int kMaxLevel = 16;  // 2^(2 * 16) = 2^32 ulps
constexpr int kRoundsWithoutProgress = 2;

}  // namespace

std::optional<PerVertexRounding> round_per_vertex(const std::vector<ExactVec3>& exact,
                                                  const std::vector<Vec3>& nearest, const std::vector<Tri>& triangles,
                                                  const std::vector<std::int64_t>& source,
                                                  const std::vector<int>& label_set,
                                                  const std::vector<LabelSet>& label_sets, double largest,
                                                  int max_rounds, double move_limit) {
  const std::size_t nv = nearest.size();
  ViolationTracker tracker;  // only the vertices raised in a round move
  std::vector<int> level(nv, 0);
  std::vector<Vec3> position = nearest;
  PerVertexRounding out;
  std::size_t fewest = SIZE_MAX;  // violations: the fewest so far, and rounds since then
  int rounds_since_fewest = 0;
  for (int round = 1; round <= max_rounds; ++round) {
    detail::memory_checkpoint();
    MeshOnPositions c = mesh_on_positions(position, triangles, source, label_set, label_sets);
    const std::vector<std::pair<int, int>> violating_pairs = tracker.violations(c.mesh);
    if (violating_pairs.empty()) {
      out.mesh = std::move(c.mesh);
      out.rounds = round;
      const int top = *std::max_element(level.begin(), level.end());
      out.grid = top == 0 ? 0.0 : grid_spacing(largest, 2 * top);
      out.coarsened = static_cast<std::size_t>(std::count_if(level.begin(), level.end(), [](int j) { return j > 0; }));
      out.max_move = largest_distance(exact, position);
      return out;
    }
    // Coarser grids that stop reducing the conflicts only spread them (layers that nearly
    // coincide over whole faces): give up rather than collapse the model.
    if (violating_pairs.size() < fewest) {
      fewest = violating_pairs.size();
      rounds_since_fewest = 0;
    } else if (++rounds_since_fewest == kRoundsWithoutProgress) {
      return std::nullopt;
    }
    // Every vertex of a violating pair goes to the next coarser grid, with every vertex that
    // shares its position (else they part again).
    std::vector<char> violating(c.mesh.vertices.size(), 0);
    for (const auto& [i, j] : violating_pairs)
      for (int t : {i, j})
        for (int v : c.mesh.triangles[t]) violating[v] = 1;
    bool raised = false;
    for (std::size_t v = 0; v < nv; ++v) {
      if (c.vertex_of[v] < 0 || !violating[c.vertex_of[v]]) continue;
      raised = true;
      if (level[v] == kMaxLevel) return std::nullopt;
      ++level[v];
      position[v] = round_point(nearest[v], grid_spacing(largest, 2 * level[v]));
      if (distance_bound(exact[v], position[v]) > move_limit) return std::nullopt;
    }
    if (!raised) return std::nullopt;  // a violation without vertices: cannot happen
  }
  return std::nullopt;
}

}  // namespace arrangements
