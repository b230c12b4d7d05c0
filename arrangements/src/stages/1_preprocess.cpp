// Stage 1: exact vertex merge, degenerate / duplicate triangle removal, optional
// power-of-two scaling (see preprocess.h).
#include "stages/1_preprocess.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "models/double_model.h"
#include "models/exact_model.h"
#include "support/label_set_table.h"

namespace arrangements {
namespace {

std::uint64_t hash_corners(const Tri& a) {
  std::uint64_t h = 0;
  for (int x : a) h = DoubleModel::mix(h ^ static_cast<std::uint32_t>(x));
  return h;
}

// first[i]: the smallest j with items[j] == items[i]. Items are sorted by (hash, index) in
// parallel; within a run of equal hashes each item is compared with the distinct items
// met so far in the run (usually one). Deterministic: the order is total.
template <class Item, class Hash>
std::vector<int> first_equal(const std::vector<Item>& items, Hash hash) {
  const std::size_t n = items.size();
  std::vector<std::pair<std::uint64_t, int>> key(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { key[i] = {hash(items[i]), static_cast<int>(i)}; });
  tbb::parallel_sort(key.begin(), key.end());
  std::vector<int> first(n);
  std::vector<int> distinct;
  for (std::size_t s = 0; s < n;) {
    std::size_t e = s + 1;
    while (e < n && key[e].first == key[s].first) ++e;
    distinct.clear();
    for (std::size_t a = s; a < e; ++a) {
      const int i = key[a].second;
      first[i] = i;
      for (int d : distinct)
        if (items[d] == items[i]) {
          first[i] = d;
          break;
        }
      if (first[i] == i) distinct.push_back(i);
    }
    s = e;
  }
  return first;
}

// Collinear iff degenerate in all three axis projections (tritri::projection's test),
// tried from the dominant plane: usually one orient2d that the filter decides (axis-
// aligned CAD faces would otherwise start with an exact zero).
template <class M>
bool collinear(const typename M::Vertex& a, const typename M::Vertex& b, const typename M::Vertex& c) {
  return M::projection(a, b, c).second == 0;
}

// Sorted, without repeats.
LabelSet normalized(LabelSet s) {
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

// k such that max_abs * 2^k is in [2^9, 2^10); 0 for max_abs == 0.
int scale_exponent_for(double max_abs) {
  if (max_abs == 0) return 0;
  int e = 0;
  std::frexp(max_abs, &e);  // max_abs in [2^(e-1), 2^e), also for subnormals
  return 10 - e;
}

// Scales by 2^k if that is exact for every coordinate; false (nothing changed) otherwise.
bool scale_exactly(std::vector<Vec3>& vertices, int k) {
  for (const Vec3& p : vertices)
    for (double c : p)
      if (std::ldexp(std::ldexp(c, k), -k) != c) return false;
  for (Vec3& p : vertices)
    for (double& c : p) c = std::ldexp(c, k);
  return true;
}

}  // namespace

template <class M>
BasicTriangleSoup<typename M::Vertex> preprocess(const BasicTriangleSoup<typename M::Input>& in,
                                                 const PreprocessOptions& options, PreprocessStats& stats) {
  using Vertex = typename M::Vertex;
  stats = PreprocessStats{};

  // Distinct positions, in input order: each position named by its first vertex.
  const std::size_t nv = in.vertices.size();
  std::vector<Vertex> at(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) { at[v] = M::vertex(in.vertices[v]); });
  // the first vertex at the same position
  std::vector<int> first_with = first_equal(at, [](const Vertex& p) { return M::hash(p); });
  std::vector<Vertex> positions;
  std::vector<int> position_of(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    if (first_with[v] == static_cast<int>(v)) {
      position_of[v] = static_cast<int>(positions.size());
      positions.push_back(at[v]);
    } else {
      position_of[v] = position_of[first_with[v]];  // an earlier vertex
    }
  }
  at = {};
  first_with = {};
  stats.merged_vertices = nv - positions.size();

  // Kept triangles (corners as position ids), their input label-set indices, and the
  // labels their duplicates add (appended, sorted once at the end: merging k copies with
  // distinct labels stays linear in the number of labels). Degenerate triangles are found
  // in parallel; of triangles with the same corner set the first is kept.
  const std::size_t nf = in.triangles.size();
  std::vector<Tri> corners(nf), key(nf);
  std::vector<char> degenerate(nf);
  tbb::parallel_for(std::size_t{0}, nf, [&](std::size_t t) {
    const Tri& tri = in.triangles[t];
    const Tri p = {position_of[tri[0]], position_of[tri[1]], position_of[tri[2]]};
    corners[t] = key[t] = p;
    std::sort(key[t].begin(), key[t].end());
    degenerate[t] = p[0] == p[1] || p[1] == p[2] || p[0] == p[2] ||
                    collinear<M>(positions[p[0]], positions[p[1]], positions[p[2]]);
  });
  // The first non-degenerate triangle with the same corners (degenerate ones get distinct
  // keys, so they match nothing).
  for (std::size_t t = 0; t < nf; ++t)
    if (degenerate[t]) key[t] = {-1, -1, -1 - static_cast<int>(t)};
  const std::vector<int> first_copy = first_equal(key, hash_corners);
  key = {};
  std::vector<Tri> kept;
  std::vector<int> kept_set;
  std::vector<std::int64_t> kept_source, kept_polygon;
  std::unordered_map<int, std::vector<std::uint32_t>> added_labels;
  {
    std::vector<int> kept_index(nf, -1);
    if (options.kept_as) options.kept_as->assign(nf, -1);
    for (std::size_t t = 0; t < nf; ++t) {
      if (degenerate[t]) {
        ++stats.removed_degenerate;
        continue;
      }
      if (first_copy[t] != static_cast<int>(t)) {
        ++stats.removed_duplicate;
        const int k = kept_index[first_copy[t]];  // kept earlier
        if (options.kept_as) {
          const Tri& a = kept[k];
          const Tri& b = corners[t];
          const int i = a[0] == b[0] ? 0 : a[1] == b[0] ? 1 : 2;  // b[0] in a
          (*options.kept_as)[t] = 2 * k + (a[(i + 1) % 3] == b[1] ? 0 : 1);
        }
        if (in.label_set[t] != kept_set[k]) {
          const LabelSet& labels = in.label_sets[in.label_set[t]];
          std::vector<std::uint32_t>& added = added_labels[k];
          added.insert(added.end(), labels.begin(), labels.end());
        }
        continue;
      }
      kept_index[t] = static_cast<int>(kept.size());
      if (options.kept_as) (*options.kept_as)[t] = 2 * kept_index[t];
      kept.push_back(corners[t]);
      kept_set.push_back(in.label_set[t]);
      kept_source.push_back(in.source[t]);
      if (!in.polygon.empty()) kept_polygon.push_back(in.polygon[t]);
    }
  }

  // Output vertices and label sets in first-use order.
  BasicTriangleSoup<Vertex> out;
  std::vector<int> out_vertex(positions.size(), -1);
  std::vector<int> out_set_of_input_set(in.label_sets.size(), -1);
  LabelSetTable out_sets(out.label_sets);  // equal sets are stored once
  auto out_set_of = [&](LabelSet labels) { return out_sets.index_of(std::move(labels)); };
  out.triangles.reserve(kept.size());
  out.label_set.reserve(kept.size());
  for (std::size_t t = 0; t < kept.size(); ++t) {
    Tri tri;
    for (int i = 0; i < 3; ++i) {
      int& id = out_vertex[kept[t][i]];
      if (id < 0) {
        id = static_cast<int>(out.vertices.size());
        out.vertices.push_back(positions[kept[t][i]]);
      }
      tri[i] = id;
    }
    out.triangles.push_back(tri);
    const auto added = added_labels.find(static_cast<int>(t));
    if (added != added_labels.end()) {
      LabelSet labels = in.label_sets[kept_set[t]];
      labels.insert(labels.end(), added->second.begin(), added->second.end());
      out.label_set.push_back(out_set_of(normalized(std::move(labels))));
    } else {
      int& set = out_set_of_input_set[kept_set[t]];
      if (set < 0) set = out_set_of(normalized(in.label_sets[kept_set[t]]));
      out.label_set.push_back(set);
    }
  }
  out.source = std::move(kept_source);
  out.polygon = std::move(kept_polygon);
  stats.unreferenced_vertices = positions.size() - out.vertices.size();

  if constexpr (M::kCanScale) {
    if (options.scale) {
      double max_abs = 0;
      for (const Vec3& p : out.vertices)
        for (double c : p) max_abs = std::max(max_abs, std::fabs(c));
      stats.scale_exponent = scale_exponent_for(max_abs);
      if (!scale_exactly(out.vertices, stats.scale_exponent)) stats.scale_exponent = 0;  // valid input: kept as is
    }
  }
  return out;
}

template TriangleSoup preprocess<DoubleModel>(const TriangleSoup&, const PreprocessOptions&, PreprocessStats&);
template BasicTriangleSoup<ExactModel::Vertex> preprocess<ExactModel>(const ExactTriangleSoup&,
                                                                      const PreprocessOptions&, PreprocessStats&);

}  // namespace arrangements
