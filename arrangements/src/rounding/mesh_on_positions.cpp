// mesh_on_positions (rounding/mesh_on_positions.h).
#include "rounding/mesh_on_positions.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>

#include <tritri/double_kernel.h>
#include <tritri/projection.h>

#include "support/label_set_table.h"

namespace arrangements {
namespace {

LabelSet label_union(const LabelSet& a, const LabelSet& b) {
  LabelSet u;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(u));
  return u;
}

}  // namespace

MeshOnPositions mesh_on_positions(const std::vector<Vec3>& position, const std::vector<Tri>& triangles,
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

  MeshOnPositions c;
  c.mesh.label_sets = label_sets;
  LabelSetTable sets(c.mesh.label_sets);
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
      s = sets.index_of(label_union(c.mesh.label_sets[s], label_sets[label_set[t]]));
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

}  // namespace arrangements
