// ViolationTracker: the violating pairs of a rounded mesh that changes a little from round
// to round, checked again only where it changed. Shared by the last resorts of round_safe
// (round_rerouting.cpp, round_per_vertex.cpp).
#pragma once

#include <array>
#include <cstddef>
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
  // changed, plus hashing the triangles.
  std::vector<std::pair<int, int>> violations(const RoundedMesh& mesh);

 private:
  using Corners = std::array<Vec3, 3>;  // sorted
  using Entry = std::pair<Corners, int>;  // a triangle's corners and its index
  bool first_ = true;
  // The last mesh's triangles, sorted by corners only when the next call needs to look them
  // up (a first check that finds nothing pays for no sort); flat vectors, no hashing.
  std::vector<Entry> previous_;
  bool previous_sorted_ = false;
  std::vector<std::pair<Corners, Corners>> previous_violating_;
};

}  // namespace arrangements
