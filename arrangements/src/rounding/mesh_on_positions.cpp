// mesh_on_positions (rounding/mesh_on_positions.h).
#include "rounding/mesh_on_positions.h"

#include <algorithm>
#include <iterator>
#include <numeric>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

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
                                  const std::vector<LabelSet>& label_sets, bool closed) {
  // One vertex per position: the first of each run of equal positions.
  const std::size_t nv = position.size();
  std::vector<int> order(nv), same(nv);
  std::iota(order.begin(), order.end(), 0);
  // Both sorts order by index among equals: a total order, the same for any thread count.
  tbb::parallel_sort(order.begin(), order.end(),
                     [&](int a, int b) { return position[a] < position[b] || (position[a] == position[b] && a < b); });
  for (std::size_t k = 0; k < nv; ++k)
    same[order[k]] = k > 0 && position[order[k]] == position[order[k - 1]] ? same[order[k - 1]] : order[k];

  // Each triangle on the merged vertices; those with repeated or collinear corners (an
  // exact test) dropped. Then triangles on the same three vertices: the first of each run
  // keeps them (sorted corners as the key: a sort, no tree of the triangles).
  const std::size_t nt = triangles.size();
  std::vector<Tri> face(nt), key(nt);
  std::vector<char> alive(nt);
  tbb::parallel_for(std::size_t{0}, nt, [&](std::size_t t) {
    Tri& f = face[t];
    for (int k = 0; k < 3; ++k) f[k] = same[triangles[t][k]];
    alive[t] = f[0] != f[1] && f[1] != f[2] && f[0] != f[2] &&
               tritri::projection(tritri::DoubleKernel{}, position[f[0]], position[f[1]], position[f[2]]).second != 0;
    key[t] = f;
    std::sort(key[t].begin(), key[t].end());
  });
  std::vector<int> by_key;
  by_key.reserve(nt);
  for (std::size_t t = 0; t < nt; ++t)
    if (alive[t]) by_key.push_back(static_cast<int>(t));
  tbb::parallel_sort(by_key.begin(), by_key.end(),
                     [&](int a, int b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
  std::vector<int> first(nt, -1);  // the first triangle on the same three vertices
  for (std::size_t k = 0; k < by_key.size(); ++k)
    first[by_key[k]] = k > 0 && key[by_key[k]] == key[by_key[k - 1]] ? first[by_key[k - 1]] : by_key[k];
  if (closed) {
    // Per run of one key: the orientations summed (+1 as the first triangle, -1 opposite);
    // a run that sums to 0 goes, one that sums below 0 is kept by its first opposite one.
    std::vector<int> net(nt, 0);
    auto same_turn = [&](int t, int u) {
      int k = 0;
      while (face[u][k] != face[t][0]) ++k;
      return face[u][(k + 1) % 3] == face[t][1];
    };
    for (int t : by_key) net[first[t]] += same_turn(t, first[t]) ? 1 : -1;
    std::vector<int> keeper(nt, -1);
    for (int t : by_key) {
      const int f = first[t];
      if (net[f] == 0) alive[t] = 0;
      else if (keeper[f] < 0 && (net[f] > 0) == same_turn(t, f)) keeper[f] = t;
    }
    for (int t : by_key)
      if (alive[t]) first[t] = keeper[first[t]];
  }

  MeshOnPositions c;
  c.mesh.label_sets = label_sets;
  LabelSetTable sets(c.mesh.label_sets);
  std::vector<int> index(nv, -1), kept_as(nt, -1);
  for (std::size_t t = 0; t < nt; ++t) {
    if (!alive[t] || first[t] != static_cast<int>(t)) continue;
    kept_as[t] = static_cast<int>(c.mesh.triangles.size());
    Tri f = face[t];
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
  // The same face twice: once, covered by the labels of both (the kept one may come later).
  for (std::size_t t = 0; t < nt; ++t)
    if (alive[t] && first[t] != static_cast<int>(t)) {
      int& s = c.mesh.label_set[kept_as[first[t]]];
      s = sets.index_of(label_union(c.mesh.label_sets[s], label_sets[label_set[t]]));
    }
  c.vertex_of.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) c.vertex_of[v] = index[same[v]];
  return c;
}

}  // namespace arrangements
