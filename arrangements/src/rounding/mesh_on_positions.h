// The triangles of an arrangement placed on rounded vertex positions, cleaned up: shared by
// the passes and last resorts of round_safe (round_ladder.h, round_rerouting.cpp, round_nudged.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

// The mesh, and for each input vertex the vertex of the mesh at its position (-1: on no
// triangle of it).
struct MeshOnPositions {
  RoundedMesh mesh;
  std::vector<int> vertex_of;
};

// The triangles on `position` (one per input vertex): vertices at one position become one
// vertex (the first of them); triangles with repeated corners or collinear ones (an exact
// test) are dropped; triangles on the same three vertices become one, the first, with the
// union of their label sets (appended to label_sets when new). Vertices are numbered in
// first-use order. O(n log n) in the vertices and triangles.
// closed: the triangles bound solids (a Boolean's output), and triangles on the same three
// vertices count with their orientation: opposite ones cancel (a slab rounded to zero
// thickness vanishes instead of leaving one face, which would open the surface); what is
// left of them, if anything, is one triangle facing the majority's way.
MeshOnPositions mesh_on_positions(const std::vector<Vec3>& position, const std::vector<Tri>& triangles,
                                  const std::vector<std::int64_t>& source, const std::vector<int>& label_set,
                                  const std::vector<LabelSet>& label_sets, bool closed = false);

// A rounded mesh cleaned the same way (its own positions): what the exact check and
// arrange_locally take.
inline RoundedMesh mesh_on_positions(const RoundedMesh& m, bool closed = false) {
  return mesh_on_positions(m.vertices, m.triangles, m.source, m.label_set, m.label_sets, closed).mesh;
}

}  // namespace arrangements
