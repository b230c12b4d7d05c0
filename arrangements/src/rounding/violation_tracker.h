// ViolationTracker: the violating pairs of a rounded mesh that changes a little from round
// to round, checked again only where it changed. Shared by the last resorts of round_safe
// (round_rerouting.cpp, round_per_vertex.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

class ViolationTracker {
 public:
  // The violating pairs of `mesh` (triangle indices i < j, sorted), as check_arrangement
  // lists them. Precondition: no degenerate triangle (mesh_on_positions drops them).
  // Whether a pair violates depends only on the positions of its corners (vertices at one
  // position are one vertex), so the first call checks every pair and later ones classify
  // only the pairs with a triangle whose corner positions were no triangle of the previous
  // call's mesh (check_arrangement_touching); the previous violations between triangles
  // found again carry over (any mesh may follow any other: where more than a quarter of
  // the triangles changed, every pair is checked again). Exact; cost proportional to what
  // changed, plus hashing the triangles and sorting their hashes.
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
  std::vector<Corners> previous_;     // the last mesh's triangles' corners, by index
  std::vector<Keyed> previous_keys_;  // and their keys, sorted
  std::vector<std::pair<Corners, Corners>> previous_violating_;
};

}  // namespace arrangements
