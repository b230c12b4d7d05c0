// round_to_grid: one rounding of a mesh (an arrangement, exact or implicit, or a rounded
// mesh arranged again) to a grid, with snap rounding's rule for new points; the step that
// round_safe's passes (round_ladder.h) and cycles repeat.
#pragma once

#include <tbb/parallel_for.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/output_mesh.h"
#include "arrangements/round_mesh.h"
#include "support/cell_grid.h"
#include "rounding/rounding_grid.h"
#include "support/vertex_coordinates.h"

namespace arrangements::detail {

// The coordinates of a vertex that is a double already (is_double): explicit points only.
inline Vec3 double_coordinates(const tritri::ImplicitPoint& p) { return p.approx(); }
inline Vec3 double_coordinates(const ExactVec3&) { return {}; }  // never asked

// Every vertex of `mesh` (an arrangement), exactly and at its nearest double.
template <class Mesh>
void exact_and_nearest(const Mesh& mesh, std::vector<ExactVec3>& exact, std::vector<Vec3>& nearest) {
  exact.resize(mesh.vertices.size());
  nearest.resize(exact.size());
  tbb::parallel_for(std::size_t{0}, exact.size(), [&](std::size_t v) {
    if (is_double(mesh.vertices[v])) {
      nearest[v] = double_coordinates(mesh.vertices[v]);
      exact[v] = to_exact(nearest[v]);
    } else {
      exact[v] = exact_coordinates(mesh.vertices[v]);
      nearest[v] = tritri::to_double(exact[v]);
    }
  });
}

// The mesh with every vertex rounded to the grid of spacing h, except that a vertex that
// is not a double and lies within `snap` of a double vertex (exact squared distance) is
// merged into the nearest one. Triangles that collapse to an edge or a point are dropped;
// vertices are renumbered in first-use order. `max_move` receives the largest distance a
// vertex moved. When the double vertices alone move by more than `move_limit` (a grid too
// coarse for the model), it stops there: an empty mesh, with max_move above the limit.
template <class Mesh>
RoundedMesh round_to_grid(const Mesh& mesh, double h, double snap, double& max_move,
                          double move_limit = std::numeric_limits<double>::infinity()) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<char> fixed(nv);
  std::vector<Vec3> position(nv);
  std::vector<double> move(nv, 0.0);
  // The doubles first: only a coarser grid moves them, and the rationals are needed only then.
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) {
    fixed[v] = is_double(mesh.vertices[v]);
    if (!fixed[v]) return;
    const Vec3 d = double_coordinates(mesh.vertices[v]);
    position[v] = round_point(d, h);
    move[v] = position[v] == d ? 0.0 : distance_bound(to_exact(d), position[v]);
  });
  max_move = nv == 0 ? 0.0 : *std::max_element(move.begin(), move.end());
  if (max_move > move_limit) return {};
  std::vector<ExactVec3> exact(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) {
    if (!fixed[v]) exact[v] = exact_coordinates(mesh.vertices[v]);
  });
  auto nearest_of = [&](std::size_t v) {
    return fixed[v] ? double_coordinates(mesh.vertices[v]) : tritri::to_double(exact[v]);
  };
  // The nearest double vertex within `snap` of each other vertex. Candidates from a grid of
  // cells of size 2 * snap over the double vertices: a vertex is within snap / 2 of its
  // nearest double (snap >= an ulp of the largest magnitude), so each candidate lies in
  // the 27 cells around it; the cell indices stay below 2^53.
  std::vector<int> target(nv, -1);
  if (snap > 0) {
    detail::CellGrid grid(2 * snap);
    for (std::size_t v = 0; v < nv; ++v)
      if (fixed[v]) grid.add(double_coordinates(mesh.vertices[v]), static_cast<int>(v));
    grid.finish();
    const CGAL::Gmpq limit = CGAL::Gmpq(snap) * CGAL::Gmpq(snap);
    tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t i) {
      if (fixed[i]) return;
      CGAL::Gmpq best;
      grid.for_each_near(nearest_of(i), [&](int w_index) {
        const Vec3 w = double_coordinates(mesh.vertices[w_index]);
        CGAL::Gmpq d2 = 0;
        for (int j = 0; j < 3; ++j) {
          const CGAL::Gmpq d = exact[i][j] - CGAL::Gmpq(w[j]);
          d2 += d * d;
        }
        if (d2 <= limit && (target[i] < 0 || d2 < best || (d2 == best && w_index < target[i]))) {
          target[i] = w_index;
          best = d2;
        }
      });
    });
  }
  std::vector<int> representative(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t v) {
    representative[v] = target[v] >= 0 ? target[v] : static_cast<int>(v);
    if (target[v] >= 0) {
      move[v] = distance_bound(exact[v], double_coordinates(mesh.vertices[target[v]]));
      return;
    }
    if (!fixed[v]) position[v] = round_point(nearest_of(v), h);
    for (double c : position[v])
      if (!std::isfinite(c))
        throw RoundingError("round: vertex " + std::to_string(v) + " rounds beyond the double range");
    if (!fixed[v]) move[v] = distance_bound(exact[v], position[v]);
  });
  max_move = nv == 0 ? 0.0 : *std::max_element(move.begin(), move.end());

  RoundedMesh out;
  std::vector<int> index(nv, -1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Tri f;
    for (int k = 0; k < 3; ++k) f[k] = representative[mesh.triangles[t][k]];
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
    for (int& i : f) {
      if (index[i] < 0) {
        index[i] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(position[i]);
      }
      i = index[i];
    }
    out.triangles.push_back(f);
    out.source.push_back(mesh.source[t]);
    out.label_set.push_back(mesh.label_set[t]);
  }
  out.label_sets = mesh.label_sets;
  return out;
}

}  // namespace arrangements::detail
