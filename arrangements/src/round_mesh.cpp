// round_nearest / round_safe (arrangements/round_mesh.h): rounding the exact arrangement to
// doubles; round_safe runs the ladder of steps of round_ladder.h.
#include "arrangements/round_mesh.h"

#include <limits>

#include "round_ladder.h"
#include "round_to_grid.h"

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

}  // namespace arrangements
