// ViolationTracker: the violating pairs of a rounded mesh that changes a little from round
// to round, checked again only where it changed. Shared by the passes and the last resorts
// of round_safe (round_ladder.h, ladder_cycles.h, round_rerouting.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

// Where more than a quarter of a mesh's triangles changed, checking every pair
// (check_arrangement, stage 2's parallel search) costs less than the changed ones' box
// search against all (check_arrangement_touching).
inline bool full_check_costs_less(std::size_t changed, std::size_t triangles) { return changed > triangles / 4; }

class ViolationTracker {
 public:
  // The violating pairs of `mesh` (triangle indices i < j, sorted), as check_arrangement
  // lists them, for any sequence of meshes. Precondition: no degenerate triangle
  // (mesh_on_positions drops them). Where no two vertices share a position and no triangle
  // is repeated (mesh_on_positions makes such meshes; moved vertices may not), whether a
  // pair violates depends only on the positions of its corners, so the first call checks
  // every pair and later ones classify
  // only the pairs with a triangle whose corner positions were no triangle of the previous
  // call's mesh (check_arrangement_touching); the previous violations between triangles
  // found again carry over (any mesh may follow any other: where more than a quarter of
  // the triangles changed, every pair is checked again). A mesh with a repeated position or
  // triangle is checked in full, and so is the one after it. Exact; cost proportional to
  // what changed, plus hashing and sorting the triangles and the positions.
  std::vector<std::pair<int, int>> violations(const RoundedMesh& mesh);

 private:
  using Corners = std::array<Vec3, 3>;  // sorted
  // A triangle's corners hashed (equal corners, equal hash; -0 and 0 alike) and its index;
  // sorted by hash then index, triangles are matched by a merge, their corners compared
  // only where the hashes are equal: no search through the corners themselves.
  struct Keyed {
    std::uint64_t hash;
    int index;
    bool operator<(const Keyed& o) const { return hash < o.hash || (hash == o.hash && index < o.index); }
  };
  bool first_ = true;
  bool previous_ambiguous_ = false;  // the last mesh repeated a position or a triangle
  std::vector<Corners> previous_;     // the last mesh's triangles' corners, by index
  std::vector<Keyed> previous_keys_;  // and their keys, sorted
  std::vector<std::pair<Corners, Corners>> previous_violating_;
};

}  // namespace arrangements
