// round_nearest / round_safe (arrangements/round_mesh.h): rounding the exact arrangement to
// doubles; round_safe runs the ladder of steps of round_ladder.h.
#include "arrangements/round_mesh.h"

#include "support/mesh_counts.h"

#include <limits>

#include "rounding/ladder_cycles.h"
#include "rounding/round_ladder.h"
#include "rounding/round_to_grid.h"

namespace arrangements {

using detail::Ladder;
using detail::round_to_grid;

RoundedMesh round_nearest(const OutputMesh& mesh) {
  double move = 0;
  return round_to_grid(mesh, 0, 0, move);
}

RoundedMesh round_nearest(const ExactOutputMesh& mesh) {
  double move = 0;
  return round_to_grid(mesh, 0, 0, move);
}

RoundedMesh round_safe(const OutputMesh& mesh, const RoundSafeOptions& options, RoundReport* report) {
  return Ladder<OutputMesh>(mesh, options, std::numeric_limits<double>::infinity(), 0, detail::kLevels).run(report);
}

RoundedMesh round_safe(const ExactOutputMesh& mesh, const RoundSafeOptions& options, RoundReport* report) {
  return Ladder<ExactOutputMesh>(mesh, options, std::numeric_limits<double>::infinity(), 0, detail::kLevels)
      .run(report);
}

void add_round_report(const RoundReport& report, const RoundedMesh& written, ArrangeStats& stats) {
  stats.round_passes = report.passes;
  stats.round_max_move = report.max_move;
  stats.round_max_move_rel = report.max_move_relative;
  stats.round_rerouted = report.rerouted;
  stats.round_merged_input = report.merged_input;
  stats.round_snapped_vertices = report.snapped_vertices;
  stats.round_nudged = report.nudged;
  const MeshCounts c = mesh_counts(written.triangles);
  stats.out_vertices = c.vertices;
  stats.out_edges = c.edges;
  stats.out_triangles = c.triangles;
  stats.euler = c.euler;
}

}  // namespace arrangements
