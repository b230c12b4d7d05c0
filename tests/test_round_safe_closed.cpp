// Safe rounding of closed solids (RoundSafeOptions::keep_closed, a Boolean's output): the
// cleaning of every pass cancels coincident faces of opposite orientation instead of
// keeping one (hand-made faces, against the plain cleaning, which keeps one with both
// labels), and on EMBER 79741+65004, whose union rerouting used to open (70 unbalanced
// edges, refused), the rounded union is closed and checked exactly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "arrangements/boolean.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/round_mesh.h"
#include "rounding/mesh_on_positions.h"
#include "support/boolean_checks.h"
#include "support/mesh_generators.h"
#include "support/shared_meshes.h"
#include "support/temp_dir.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;

// Triangles over four points (a tetrahedron's corners); label k for the k-th triangle.
MeshOnPositions clean(const std::vector<Tri>& triangles, bool closed) {
  const std::vector<Vec3> P{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<std::int64_t> source;
  std::vector<int> label_set;
  std::vector<LabelSet> label_sets;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    source.push_back(static_cast<std::int64_t>(k));
    label_set.push_back(static_cast<int>(k));
    label_sets.push_back(LabelSet{static_cast<LabelSet::value_type>(k)});
  }
  return mesh_on_positions(P, triangles, source, label_set, label_sets, closed);
}

TEST(RoundSafeClosed, OppositeFacesCancelOnlyInClosedMode) {
  // A face and its reverse: one face with both labels, or nothing.
  const MeshOnPositions plain = clean({{0, 1, 2}, {0, 2, 1}}, false);
  ASSERT_EQ(plain.mesh.triangles.size(), 1u);
  EXPECT_EQ(plain.mesh.label_sets[plain.mesh.label_set[0]], (LabelSet{0, 1}));
  EXPECT_EQ(clean({{0, 1, 2}, {0, 2, 1}}, true).mesh.triangles.size(), 0u);
  // Twice one way and once the other: one face, facing the majority's way, whichever comes
  // first; the other faces of the tetrahedron untouched.
  for (const std::vector<Tri>& faces :
       {std::vector<Tri>{{0, 1, 2}, {1, 2, 0}, {2, 1, 0}, {0, 1, 3}}, std::vector<Tri>{{2, 1, 0}, {0, 1, 2}, {0, 1, 3}, {2, 0, 1}}}) {
    const MeshOnPositions c = clean(faces, true);
    ASSERT_EQ(c.mesh.triangles.size(), 2u);
    int facing = 0;  // of the face on 0, 1, 2: +1 as (0, 1, 2)
    for (const Tri& t : c.mesh.triangles) {
      std::array<Vec3, 3> corners{c.mesh.vertices[t[0]], c.mesh.vertices[t[1]], c.mesh.vertices[t[2]]};
      if (corners[0][2] != 0 || corners[1][2] != 0 || corners[2][2] != 0) continue;  // the side face
      // (0, 1, 2) turns counterclockwise seen from +z.
      const double z = (corners[1][0] - corners[0][0]) * (corners[2][1] - corners[0][1]) -
                       (corners[1][1] - corners[0][1]) * (corners[2][0] - corners[0][0]);
      facing = z > 0 ? 1 : -1;
    }
    EXPECT_EQ(facing, 1);
  }
  // Faces on distinct vertices are never merged or cancelled.
  EXPECT_EQ(clean({{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}}, true).mesh.triangles.size(), 4u);
}

TEST(RoundSafeClosed, EmberUnionStaysClosed) {
  const std::filesystem::path shared = tritri_test::shared_meshes_dir().parent_path();
  const std::filesystem::path script = shared / "tools" / "boolean_pairs" / "make_pairs.py";
  TRITRI_REQUIRE_DATA(script);
  tritri_test::TempDir tmp;
  const std::string command = "python3 '" + script.string() + "' '" + tmp.path().string() + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const TriangleSoup a = load_triangle_soup((tmp.path() / "79741_ember_a.obj").string());
  const TriangleSoup b = load_triangle_soup((tmp.path() / "65004_ember_b.obj").string());
  ArrangeOptions options;
  options.threads = 2;
  const ArrangeResult u = boolean(concatenate(a, b), operation_tree(BooleanOp::Union, 2), options);
  ASSERT_EQ(tritri_test::unbalanced_edges(u.mesh), 0u);
  RoundReport report;
  const RoundedMesh r = round_safe(u.mesh, RoundSafeOptions{.threads = 2, .keep_closed = true}, &report);
  EXPECT_EQ(tritri_test::unbalanced_edges(r), 0u);
  const ArrangementCheck c = check_arrangement(r);
  EXPECT_TRUE(c.ok()) << (c.examples.empty() ? "" : c.examples.front());
  EXPECT_GT(report.rerouted, 0u);  // the step that used to open it
  EXPECT_LE(report.max_move_relative, 1e-14);
  std::printf("EMBER 79741+65004 union: %zu triangles rounded closed in %d passes, %zu rerouted, move %.3g\n",
              r.triangles.size(), report.passes, report.rerouted, report.max_move_relative);
}

}  // namespace
