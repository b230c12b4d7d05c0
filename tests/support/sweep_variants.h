// The sweep's rot2 variant (bench/round_safe_sweep.py, seed 1) built in C++, bit for bit:
// tests that pin down what safe rounding does on one of the sweep's runs start from it.
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "arrangements/triangle_soup.h"
#include "support/bounding_box.h"
#include "support/mesh_generators.h"

namespace tritri_test {

// The mesh and a copy turned by pi about the centre of its bounding box, about the sweep's
// rot2 axis for seed 1 (the same for every mesh), with the sweep's operations in its order
// (the centre added first), so the same doubles; the copy's vertices and triangles follow
// the mesh's. Source i for triangle i (polygon the same where the mesh has one: every face
// of the file a triangle, as arrange reads it), one label set.
inline arrangements::TriangleSoup sweep_rot2(const arrangements::TriangleSoup& mesh) {
  using namespace arrangements;
  const RotationMatrix R =
      rotation_matrix({-0x1.f2e5f53200134p-1, -0x1.abd2510642aebp-3, 0x1.53e34acd01f7bp-4}, std::numbers::pi);
  const Vec3 centre = bounding_box(mesh.vertices).centre();
  TriangleSoup out;
  out.vertices = mesh.vertices;
  for (const Vec3& p : mesh.vertices) {
    const Vec3 d = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = centre[k] + R[k][0] * d[0] + R[k][1] * d[1] + R[k][2] * d[2] + 0.0;
    out.vertices.push_back(q);
  }
  out.triangles = mesh.triangles;
  const int n = static_cast<int>(mesh.vertices.size());
  for (const Tri& f : mesh.triangles) out.triangles.push_back({f[0] + n, f[1] + n, f[2] + n});
  for (std::size_t i = 0; i < out.triangles.size(); ++i) out.source.push_back(static_cast<std::int64_t>(i));
  if (!mesh.polygon.empty()) out.polygon = out.source;
  out.label_set.assign(out.triangles.size(), 0);
  out.label_sets = {{0}};
  return out;
}

}  // namespace tritri_test
