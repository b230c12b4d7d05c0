// merge_close_input_vertices: the step of round_safe (arrangements/round_mesh.h) that goes
// back to the input (after rerouting, before level 1's grid), for surfaces that nearly
// coincide: copies of one mesh placed by transforms rounded to doubles (instances, rotated
// copies), whose vertices lie a few ulps apart. Their exact arrangement crosses the layers
// wherever the rounding errors change sign, in far more places than the input has
// vertices, and no rounding of those crossings keeps the layers apart. Merged, the copies
// coincide exactly: arranging the merged input gives each shared face once, with the
// union of the labels, and nothing thinner than an ulp is left to round.
#pragma once

#include <cstddef>

#include "arrangements/triangle_soup.h"

namespace arrangements {

struct MergedInput {
  TriangleSoup soup;        // the input with merged vertices, triangles with repeated
                            // corners dropped (provenance of the others unchanged; no
                            // polygon ids: merging may fold a polygon's triangles)
  std::size_t merged = 0;   // input vertices replaced by another one at another position
  double max_move = 0;      // an upper bound of the largest distance a vertex moved
};

// Vertices within `delta` of each other (exact squared distance; delta > 0) are merged,
// transitively, into the one of their cluster with the smallest index. A cluster can be
// wider than delta where vertices chain; max_move reports it. O(n log n) in the vertices
// (a hash grid of cells of size delta, plus the exact tests of the neighbours found).
MergedInput merge_close_input_vertices(const TriangleSoup& input, double delta);

}  // namespace arrangements
