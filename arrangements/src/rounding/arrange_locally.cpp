// arrange_locally (rounding/arrange_locally.h).
#include "rounding/arrange_locally.h"

#include <bit>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "arrangements/as_input.h"
#include "support/label_set_table.h"

namespace arrangements {
namespace {

// Positions as hash keys: -0.0 and 0.0 are one position (the pipeline writes 0.0).
struct PositionHash {
  std::size_t operator()(const Vec3& p) const {
    std::uint64_t h = 0;
    for (double x : p) h = (h ^ std::bit_cast<std::uint64_t>(x + 0.0)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

}  // namespace

OutputMesh arrange_locally(const RoundedMesh& m, const std::vector<std::pair<int, int>>& violating,
                           const ArrangeOptions& options, ArrangeStats& stats) {
  const std::size_t nt = m.triangles.size();
  // The sub-soup's triangles in m's order: where coplanar triangles overlap, the
  // arrangement gives the shared region to one of them by their order.
  std::vector<int> sub_index(nt, -1);  // m's triangle -> the sub-soup's
  for (const auto& [i, j] : violating) sub_index[i] = sub_index[j] = 0;
  std::vector<int> of_sub;  // and back
  for (std::size_t t = 0; t < nt; ++t)
    if (sub_index[t] == 0) {
      sub_index[t] = static_cast<int>(of_sub.size());
      of_sub.push_back(static_cast<int>(t));
    }
  // The sub-soup: its triangles on m's vertices, numbered by use; `source` names the
  // sub-soup triangle, so that each piece finds its triangle of m.
  TriangleSoup sub;
  std::vector<int> sub_vertex(m.vertices.size(), -1);
  std::unordered_map<Vec3, int, PositionHash> vertex_at;  // position -> m's vertex
  for (int t : of_sub) {
    Tri f = m.triangles[t];
    for (int& v : f) {
      if (sub_vertex[v] < 0) {
        sub_vertex[v] = static_cast<int>(sub.vertices.size());
        sub.vertices.push_back(m.vertices[v]);
        vertex_at.emplace(m.vertices[v], v);
      }
      v = sub_vertex[v];
    }
    sub.triangles.push_back(f);
    sub.label_set.push_back(m.label_set[t]);
    sub.source.push_back(static_cast<std::int64_t>(sub.triangles.size()) - 1);
  }
  sub.label_sets = m.label_sets;
  ArrangeResult pieces = arrange(sub, options);

  OutputMesh out;
  out.vertices.reserve(m.vertices.size() + pieces.mesh.vertices.size());
  for (const Vec3& v : m.vertices) out.vertices.push_back(tritri::ImplicitPoint::explicit_point(v));
  // The pieces' vertices: a corner of the sub-soup is m's vertex at its position, a new
  // point is appended.
  std::vector<int> vertex_of_piece(pieces.mesh.vertices.size());
  for (std::size_t v = 0; v < pieces.mesh.vertices.size(); ++v) {
    const tritri::ImplicitPoint& p = pieces.mesh.vertices[v];
    if (p.is_explicit()) {
      const auto it = vertex_at.find(p.approx());
      if (it == vertex_at.end()) throw std::logic_error("arrange_locally: a corner of a piece is no vertex of the mesh");
      vertex_of_piece[v] = it->second;
    } else {
      vertex_of_piece[v] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(p);
    }
  }
  // Pieces grouped by their triangle of m, in the order the arrangement gave them.
  std::vector<std::vector<int>> pieces_of(of_sub.size());
  for (std::size_t p = 0; p < pieces.mesh.triangles.size(); ++p)
    pieces_of[static_cast<std::size_t>(pieces.mesh.source[p])].push_back(static_cast<int>(p));
  out.label_sets = m.label_sets;
  LabelSetTable sets(out.label_sets);
  const std::size_t reserve = nt - of_sub.size() + pieces.mesh.triangles.size();
  out.triangles.reserve(reserve);
  out.source.reserve(reserve);
  out.label_set.reserve(reserve);
  for (std::size_t t = 0; t < nt; ++t) {
    if (sub_index[t] < 0) {
      out.triangles.push_back(m.triangles[t]);
      out.source.push_back(m.source[t]);
      out.label_set.push_back(m.label_set[t]);
      continue;
    }
    for (int p : pieces_of[static_cast<std::size_t>(sub_index[t])]) {
      Tri f = pieces.mesh.triangles[p];
      for (int& v : f) v = vertex_of_piece[v];
      out.triangles.push_back(f);
      out.source.push_back(m.source[t]);
      out.label_set.push_back(sets.index_of(pieces.mesh.label_sets[pieces.mesh.label_set[p]]));
    }
  }
  stats = ArrangeStats{};
  stats.intersecting_pairs = violating.size();
  stats.out_vertices = out.vertices.size();
  stats.out_triangles = out.triangles.size();
  return out;
}

}  // namespace arrangements
