#include "booleans/operand_weights.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <tuple>

#include "models/double_model.h"
#include "models/exact_model.h"

namespace arrangements {
namespace {

// Sorts (row, operand, count) triples and sums equal (row, operand) keys into a table of
// `rows` rows, zero sums dropped.
OperandWeights table_of(std::vector<std::array<int, 3>> entries, std::size_t rows) {
  std::sort(entries.begin(), entries.end());
  OperandWeights w;
  w.begin.assign(rows + 1, 0);
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i;
    int sum = 0;
    for (; j < entries.size() && entries[j][0] == entries[i][0] && entries[j][1] == entries[i][1]; ++j)
      sum += entries[j][2];
    if (sum != 0) {
      w.items.emplace_back(entries[i][1], sum);
      ++w.begin[entries[i][0] + 1];
    }
    i = j;
  }
  for (std::size_t r = 0; r < rows; ++r) w.begin[r + 1] += w.begin[r];
  return w;
}

// +1 when soup triangle u runs the same way as soup triangle t (coplanar with it), else -1.
template <class M>
int same_way(const BasicTriangleSoup<typename M::Vertex>& soup, int t, int u) {
  if (t == u) return 1;
  const auto& a = soup.vertices;
  const Tri& x = soup.triangles[t];
  const Tri& y = soup.triangles[u];
  const auto [plane, orientation] = M::projection(a[x[0]], a[x[1]], a[x[2]]);
  const int other = tritri::to_int(M::orient2d(a[y[0]], a[y[1]], a[y[2]], plane));
  return orientation * other > 0 ? 1 : -1;
}

}  // namespace

OperandWeights soup_weights(const std::vector<int>& kept_as, const std::vector<int>& input_label_set,
                            const std::vector<LabelSet>& input_label_sets, std::size_t soup_triangles) {
  std::vector<std::array<int, 3>> entries;
  entries.reserve(kept_as.size());
  for (std::size_t t = 0; t < kept_as.size(); ++t) {
    if (kept_as[t] < 0) continue;  // degenerate: bounds nothing
    const int row = kept_as[t] / 2, sign = kept_as[t] % 2 ? -1 : 1;
    for (std::uint32_t label : input_label_sets[input_label_set[t]])
      entries.push_back({row, static_cast<int>(label), sign});
  }
  return table_of(std::move(entries), soup_triangles);
}

template <class M>
OperandWeights output_deltas(const BasicTriangleSoup<typename M::Vertex>& soup, const OperandWeights& weights,
                             const std::vector<int>& emitted_by, const std::vector<int>& cover_of,
                             const std::vector<std::vector<int>>& covers) {
  // The cover sets' own deltas (relative to the triangle that emits their region).
  std::vector<int> owner(covers.size(), -1);
  for (std::size_t f = 0; f < cover_of.size(); ++f)
    if (cover_of[f] >= 0) owner[cover_of[f]] = emitted_by[f];
  std::vector<std::vector<std::array<int, 3>>> cover_entries(covers.size());
  tbb::parallel_for(std::size_t{0}, covers.size(), [&](std::size_t c) {
    if (owner[c] < 0) return;
    for (int u : covers[c]) {
      const int s = same_way<M>(soup, owner[c], u);
      for (auto it = weights.row_begin(u); it != weights.row_end(u); ++it)
        cover_entries[c].push_back({0, it->first, s * it->second});
    }
  });
  std::vector<OperandWeights> cover_delta(covers.size());
  tbb::parallel_for(std::size_t{0}, covers.size(),
                    [&](std::size_t c) { cover_delta[c] = table_of(std::move(cover_entries[c]), 1); });

  const std::size_t n = emitted_by.size();
  OperandWeights out;
  out.begin.assign(n + 1, 0);
  auto row_of = [&](std::size_t f) {
    return cover_of[f] < 0 ? std::make_pair(weights.row_begin(emitted_by[f]), weights.row_end(emitted_by[f]))
                           : std::make_pair(cover_delta[cover_of[f]].row_begin(0), cover_delta[cover_of[f]].row_end(0));
  };
  for (std::size_t f = 0; f < n; ++f) {
    const auto [b, e] = row_of(f);
    out.begin[f + 1] = out.begin[f] + static_cast<std::size_t>(e - b);
  }
  out.items.resize(out.begin[n]);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t f) {
    const auto [b, e] = row_of(f);
    std::copy(b, e, out.items.begin() + static_cast<std::ptrdiff_t>(out.begin[f]));
  });
  return out;
}

template OperandWeights output_deltas<DoubleModel>(const TriangleSoup&, const OperandWeights&, const std::vector<int>&,
                                                   const std::vector<int>&, const std::vector<std::vector<int>>&);
template OperandWeights output_deltas<ExactModel>(const BasicTriangleSoup<ExactModel::Vertex>&, const OperandWeights&,
                                                  const std::vector<int>&, const std::vector<int>&,
                                                  const std::vector<std::vector<int>>&);

}  // namespace arrangements
