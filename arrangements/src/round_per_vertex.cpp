// round_per_vertex (round_per_vertex.h): rounding every vertex of the exact arrangement
// to a grid of its own, coarser only where the rounded mesh is not an arrangement.
#include "round_per_vertex.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstddef>
#include <map>
#include <numeric>

#include <tritri/double_kernel.h>
#include <tritri/projection.h>

#include "arrangements/check_arrangement.h"
#include "support/rounding_grid.h"

namespace arrangements {
namespace {

constexpr int kMaxLevel = 16;  // 2^(2 * 16) = 2^32 ulps
constexpr int kRoundsWithoutProgress = 2;

// The mesh on the rounded positions, and for each vertex of the arrangement the vertex of
// the mesh at its position (-1: on no triangle of it).
struct Candidate {
  RoundedMesh mesh;
  std::vector<int> vertex_of;
};

LabelSet label_union(const LabelSet& a, const LabelSet& b) {
  LabelSet u;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(u));
  return u;
}

Candidate rounded_mesh(const std::vector<Vec3>& position, const std::vector<Tri>& triangles,
                       const std::vector<std::int64_t>& source, const std::vector<int>& label_set,
                       const std::vector<LabelSet>& label_sets) {
  // One vertex per position: the first of each run of equal positions.
  const std::size_t nv = position.size();
  std::vector<int> order(nv), same(nv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return position[a] < position[b] || (position[a] == position[b] && a < b); });
  for (std::size_t k = 0; k < nv; ++k)
    same[order[k]] = k > 0 && position[order[k]] == position[order[k - 1]] ? same[order[k - 1]] : order[k];

  Candidate c;
  c.mesh.label_sets = label_sets;
  std::map<LabelSet, int> set_index;
  for (std::size_t s = 0; s < label_sets.size(); ++s) set_index.emplace(label_sets[s], static_cast<int>(s));
  std::vector<int> index(nv, -1);
  std::map<Tri, int> kept;  // sorted corners -> triangle of the result
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Tri f;
    for (int k = 0; k < 3; ++k) f[k] = same[triangles[t][k]];
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
    if (tritri::projection(tritri::DoubleKernel{}, position[f[0]], position[f[1]], position[f[2]]).second == 0)
      continue;  // collinear: no area
    Tri key = f;
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = kept.emplace(key, static_cast<int>(c.mesh.triangles.size()));
    if (!inserted) {
      // The same face twice: once, covered by the labels of both.
      int& s = c.mesh.label_set[it->second];
      const LabelSet u = label_union(c.mesh.label_sets[s], label_sets[label_set[t]]);
      const auto [u_it, added] = set_index.emplace(u, static_cast<int>(c.mesh.label_sets.size()));
      if (added) c.mesh.label_sets.push_back(u);
      s = u_it->second;
      continue;
    }
    for (int& i : f) {
      if (index[i] < 0) {
        index[i] = static_cast<int>(c.mesh.vertices.size());
        c.mesh.vertices.push_back(position[i]);
      }
      i = index[i];
    }
    c.mesh.triangles.push_back(f);
    c.mesh.source.push_back(source[t]);
    c.mesh.label_set.push_back(label_set[t]);
  }
  c.vertex_of.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) c.vertex_of[v] = index[same[v]];
  return c;
}

}  // namespace

std::optional<PerVertexRounding> round_per_vertex(const std::vector<ExactVec3>& exact,
                                                  const std::vector<Vec3>& nearest, const std::vector<Tri>& triangles,
                                                  const std::vector<std::int64_t>& source,
                                                  const std::vector<int>& label_set,
                                                  const std::vector<LabelSet>& label_sets, int max_rounds) {
  const std::size_t nv = nearest.size();
  double largest = 0;
  for (const Vec3& p : nearest)
    for (double x : p) largest = std::max(largest, std::abs(x));
  std::vector<int> level(nv, 0);
  std::vector<Vec3> position = nearest;
  PerVertexRounding out;
  std::size_t fewest = SIZE_MAX;  // violations: the fewest so far, and rounds since then
  int rounds_since_fewest = 0;
  for (int round = 1; round <= max_rounds; ++round) {
    Candidate c = rounded_mesh(position, triangles, source, label_set, label_sets);
    const ArrangementCheck check = check_arrangement(c.mesh, 0);
    if (check.ok()) {
      out.mesh = std::move(c.mesh);
      out.rounds = round;
      const int top = *std::max_element(level.begin(), level.end());
      out.grid = top == 0 ? 0.0 : grid_spacing(largest, 2 * top);
      out.coarsened = static_cast<std::size_t>(std::count_if(level.begin(), level.end(), [](int j) { return j > 0; }));
      std::vector<double> move(nv);
      tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) { move[v] = distance_bound(exact[v], position[v]); });
      out.max_move = nv == 0 ? 0.0 : *std::max_element(move.begin(), move.end());
      return out;
    }
    // Coarser grids that stop reducing the conflicts only spread them (layers that nearly
    // coincide over whole faces): give up rather than collapse the model.
    if (check.violations < fewest) {
      fewest = check.violations;
      rounds_since_fewest = 0;
    } else if (++rounds_since_fewest == kRoundsWithoutProgress) {
      return std::nullopt;
    }
    // Every vertex of a violating pair goes to the next coarser grid, with every vertex that
    // shares its position (else they part again).
    std::vector<char> violating(c.mesh.vertices.size(), 0);
    for (const auto& [i, j] : check.violating_pairs)
      for (int t : {i, j})
        for (int v : c.mesh.triangles[t]) violating[v] = 1;
    bool raised = false;
    for (std::size_t v = 0; v < nv; ++v) {
      if (c.vertex_of[v] < 0 || !violating[c.vertex_of[v]]) continue;
      raised = true;
      if (level[v] == kMaxLevel) return std::nullopt;
      ++level[v];
      position[v] = round_point(nearest[v], grid_spacing(largest, 2 * level[v]));
    }
    if (!raised) return std::nullopt;  // a violation without vertices: cannot happen
  }
  return std::nullopt;
}

}  // namespace arrangements
