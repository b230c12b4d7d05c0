// Safe rounding's input steps (issue 14, arrangements/round_mesh.h): when the arrangement
// alone does not settle, round_safe goes back to the input (RoundSafeOptions::input) and
// changes it a little: vertices merged within a distance (round_merged_input.h), nearly
// coplanar layers snapped onto one plane (round_snapped_planes.h). Each step is tested on
// its own (exact, transitive, bounded) and on the class of input it is for, generated
// (rotated, turned and shifted copies) and from the shared meshes, with every check of
// support/safe_rounding_checks.h on the result; a refusal says how close it came.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/round_mesh.h"
#include "rounding/round_merged_input.h"
#include "rounding/round_snapped_planes.h"
#include "support/bounding_box.h"
#include "support/exact_soups.h"
#include "support/mesh_generators.h"
#include "support/safe_rounding_checks.h"
#include "support/shared_meshes.h"
#include "support/test_scale.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;
using tritri_test::rounding::expect_safe_rounding;

TEST(RoundSafeInput, NearlyCoincidentCopiesMergeAtTheirInputVertices) {
  // Three copies rotated by 2 pi / 3 map the sphere's vertices onto each other up to the
  // rounding of the rotation: the layers lie within 1e-16 of each other, and their exact
  // arrangement crosses them wherever the rounding errors change sign. From the
  // arrangement alone round_safe gives up (RoundingError within its pass budget, no growth
  // without bound): at every level the rounded layers cross again. Given the input, its
  // last resort merges the copies' vertices, a few ulps apart; the copies then coincide,
  // so the result is one sphere whose faces carry the labels of all three.
  TriangleSoup soup = rotated_copies(uv_sphere({0.1, 0.2, 0.3}, 1.0, 12, 24), 3);
  const std::size_t per_copy = soup.triangles.size() / 3;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) soup.label_set[t] = static_cast<int>(t / per_copy);
  soup.label_sets = {{0}, {1}, {2}};
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersection_points, 0u);
  // The refusal says how close it came: the fewest crossing pairs a last resort left, in
  // the report and in the message.
  RoundReport refused;
  try {
    round_safe(first.mesh, RoundSafeOptions{}, &refused);
    ADD_FAILURE() << "three copies from the arrangement alone: expected RoundingError";
  } catch (const RoundingError& error) {
    EXPECT_GT(refused.conflicts_left, 0u);
    EXPECT_NE(std::string(error.what()).find("the closest attempt left " + std::to_string(refused.conflicts_left) +
                                             " pairs"),
              std::string::npos)
        << error.what();
  }

  bool nearest_ok = true;
  RoundedMesh r;
  const RoundReport report = expect_safe_rounding(first.mesh, "three copies", nearest_ok, &soup, &r);
  EXPECT_FALSE(nearest_ok);
  EXPECT_GT(report.merged_input, 0u);
  EXPECT_LE(report.max_move_relative, 1e-14);
  // About the area of one copy (the input's third), not of three layers: most of it in
  // faces that all three copies cover (vertices left unmerged at the smallest distance
  // that settles it keep a few faces in two or three layers, within ulps of each other).
  double input_area = 0, rounded_area = 0, shared_area = 0;
  using tritri_test::rounding::triangle_area;
  for (const Tri& f : soup.triangles)
    input_area += triangle_area(soup.vertices[f[0]], soup.vertices[f[1]], soup.vertices[f[2]]);
  for (std::size_t t = 0; t < r.triangles.size(); ++t) {
    const Tri& f = r.triangles[t];
    const double a = triangle_area(r.vertices[f[0]], r.vertices[f[1]], r.vertices[f[2]]);
    rounded_area += a;
    if (r.label_sets[r.label_set[t]].size() == 3) shared_area += a;
  }
  EXPECT_GT(rounded_area, (1 - 1e-9) * input_area / 3);
  EXPECT_LT(rounded_area, 1.1 * input_area / 3);
  EXPECT_GT(shared_area, 0.9 * rounded_area);
  std::printf("three copies: %d passes and rounds, %zu input vertices merged, largest move / diagonal %.3g, "
              "%.4f of the area shared by all three\n",
              report.passes, report.merged_input, report.max_move_relative, shared_area / rounded_area);
}

// `soup` turned by 2 pi / 3 about the diagonal direction (1, 1, 1) through `centre`, then moved
// by `shift`, in doubles: a cube about its centre maps onto itself, its faces an ulp or so
// off their planes.
TriangleSoup turned_about_diagonal(const TriangleSoup& soup, const Vec3& centre, const Vec3& shift) {
  const double k = 1 / std::sqrt(3.0);
  return turned(soup, centre, {k, k, k}, 2 * M_PI / 3, shift);
}

// Three unit cubes, the second the first turned about its diagonal and moved along a face,
// the third the second turned again about its own centre and moved: faces of different
// cubes nearly coincide (within ulps, shifted in their planes) and share no vertex.
TriangleSoup turned_cubes() {
  const TriangleSoup a = box({0, 0, 0}, {1, 1, 1});
  const TriangleSoup b = turned_about_diagonal(a, {0.5, 0.5, 0.5}, {0.3, 0.2, 0});
  const TriangleSoup c = turned_about_diagonal(b, {0.8, 0.7, 0.5}, {0.1, 0.3, 0});
  return concatenate({a, b, c});
}

TEST(RoundSafeInput, NearlyCoplanarFacesOfTurnedCubesAreSnappedCoplanar) {
  const TriangleSoup soup = turned_cubes();
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersecting_pairs, 0u);
  ASSERT_EQ(first.stats.coplanar_pairs, 0u);  // nearly, not exactly, coplanar
  // Without the input, only nudging (the last resort) settles the layers that cross
  // wherever the errors change sign: they stay an ulp apart, vertices moved by ulps.
  bool nearest_ok = true;
  const RoundReport alone = expect_safe_rounding(first.mesh, "turned cubes alone", nearest_ok);
  EXPECT_GT(alone.nudged, 0u);
  EXPECT_EQ(alone.snapped_vertices, 0u);
  EXPECT_LE(alone.max_move_relative, 1e-13);
  std::printf("turned cubes, the arrangement alone: %d passes, %zu vertices nudged, largest move / diagonal %.3g\n",
              alone.passes, alone.nudged, alone.max_move_relative);
  const RoundReport report = expect_safe_rounding(first.mesh, "turned cubes", nearest_ok, &soup);
  EXPECT_FALSE(nearest_ok);
  EXPECT_GT(report.snapped_vertices, 0u);
  EXPECT_EQ(report.merged_input, 0u);
  EXPECT_LE(report.max_move_relative, 1e-14);
  std::printf("turned cubes: %d passes, %zu input vertices snapped, largest move / diagonal %.3g\n", report.passes,
              report.snapped_vertices, report.max_move_relative);
}

TEST(RoundSafeInput, SnappingNearlyCoplanarFacesMakesThemExactlyCoplanar) {
  const TriangleSoup soup = turned_cubes();
  const double delta = std::ldexp(1.0, -52 + 2);  // 4 ulps of the largest magnitude (in [1, 2))
  const SnappedPlanes snapped = snap_near_coplanar_faces(soup, delta, 0, false);
  EXPECT_GT(snapped.groups, 0u);
  EXPECT_GT(snapped.moved, 0u);
  // The exact pipeline now finds coplanar overlapping layers where it found none.
  const ExactArrangeResult again = arrange(snapped.soup, ArrangeOptions{});
  EXPECT_GT(again.stats.coplanar_pairs, 0u);
  // Each vertex stays within the reported move, which stays within 64 delta.
  std::size_t moved = 0;
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    const ExactVec3 original = to_exact(soup.vertices[v]);
    if (snapped.soup.vertices[v] == original) continue;
    ++moved;
    CGAL::Gmpq d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const CGAL::Gmpq d = snapped.soup.vertices[v][k] - original[k];
      d2 += d * d;
    }
    EXPECT_LE(d2, CGAL::Gmpq(snapped.max_move) * CGAL::Gmpq(snapped.max_move)) << v;
  }
  EXPECT_EQ(moved, snapped.moved);
  EXPECT_LE(snapped.max_move, 64 * std::sqrt(3.0) * delta);
  EXPECT_EQ(snapped.soup.triangles, soup.triangles);
  EXPECT_EQ(snapped.soup.source, soup.source);
  // A mesh without near-coplanar layers (one cube) is left as it is.
  EXPECT_EQ(snap_near_coplanar_faces(box({0, 0, 0}, {1, 1, 1}), delta, 0, false).moved, 0u);
}

// `soup` and a copy turned by 1e-7 rad about `axis` through its box centre and moved by 1e-9
// of its diagonal along `direction` (bench/round_safe_sweep.py's "shift" variant): layers
// that cross at grazing angles everywhere, each copied vertex about 1e-7 of the size from
// its original.
TriangleSoup with_shifted_copy(TriangleSoup soup, const Vec3& axis, const Vec3& direction) {
  soup.polygon.clear();  // concatenate keeps no polygon ids
  const BoundingBox box = bounding_box(soup.vertices);
  const double diagonal = box.diagonal();
  const Vec3 centre = box.centre();
  const Vec3 shift{1e-9 * diagonal * direction[0], 1e-9 * diagonal * direction[1], 1e-9 * diagonal * direction[2]};
  return concatenate(soup, turned(soup, centre, axis, 1e-7, shift));
}

// The shifted copy settles either by merging the input (each copied vertex into its
// original, within at most 256 ulps), or with the two layers kept apart, every vertex within 1e-12 of the diagonal
// (a few thousand ulps at most, where nudging's cycles arranged again; the merge moves them
// by 1e-8): the copy's corners snapped onto nearly coplanar faces or not, what rerouting
// leaves nudged.
// Returns whether it was the second.
bool expect_shifted_copy_settled(const TriangleSoup& soup, const std::string& name) {
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  EXPECT_GT(first.stats.intersecting_pairs, 0u) << name;
  bool nearest_ok = true;
  const RoundReport report = expect_safe_rounding(first.mesh, name, nearest_ok, &soup);
  EXPECT_FALSE(nearest_ok) << name;
  const bool merged = report.merged_input >= soup.vertices.size() / 2;  // every copied vertex
  const bool kept_apart = report.merged_input == 0 && report.max_move_relative <= 1e-12;
  EXPECT_TRUE(merged || kept_apart) << name << ": " << report.merged_input << " input vertices merged, move "
                                    << report.max_move_relative;
  EXPECT_LE(report.max_move_relative, 1e-6) << name;
  std::printf("%s: %d passes, %zu input vertices merged, %zu snapped, %zu nudged, grid %.3g, largest move / "
              "diagonal %.3g\n",
              name.c_str(), report.passes, report.merged_input, report.snapped_vertices, report.nudged, report.grid,
              report.max_move_relative);
  return kept_apart && report.nudged > 0;
}

TEST(RoundSafeInput, ShiftedCopiesOfSpheresSettle) {
  // No grid up to 2^32 ulps holds the crossings (levels that coarse were tried once).
  const Vec3 axis{0.3 / std::sqrt(0.98), 0.5 / std::sqrt(0.98), 0.8 / std::sqrt(0.98)}, direction{0.6, 0.0, 0.8};
  std::vector<std::pair<int, int>> sizes = {{20, 40}, {30, 60}};
  if (tritri_test::scaled_down()) sizes.pop_back();  // the sanitizer build: minutes each
  for (const auto& [rings, segments] : sizes)
    expect_shifted_copy_settled(with_shifted_copy(uv_sphere({0.5, 1.0, 1.5}, 1.0, rings, segments), axis, direction),
                                "sphere " + std::to_string(rings) + " x " + std::to_string(segments) + " shifted");
}

TEST(RoundSafeInput, ShiftedCopiesOfQuickCsgMeshesSettle) {
  // QuickCSG's t1_0 and t1_48 (refused before coarse merges; t1_48 then settled on the
  // coarsest grid only) and cylinder cyl1, with the sweep's axis and direction (seed 1).
  // Nudging keeps the layers apart on each (it merged them at 1e-7 of the size before).
  const Vec3 axis{0.045609566428869625, 0.46022821167165107, 0.8866283103035254};
  const Vec3 direction{0.03177729554885592, 0.989647738007784, 0.13995555774486879};
  const fs::path dir = tritri_test::shared_meshes_dir() / "thingicsg" / "QuickCSG";
  int nudged_apart = 0;
  std::vector<fs::path> files = {dir / "T1" / "t1_0.off", dir / "T1" / "t1_48.off", dir / "TwoCylinders" / "cyl1.off"};
  if (tritri_test::scaled_down()) files.pop_back();  // the sanitizer build: cyl1 takes 85% of the time
  for (const fs::path& file : files) {
    TRITRI_REQUIRE_DATA(file);
    nudged_apart += expect_shifted_copy_settled(with_shifted_copy(load_triangle_soup(file.string()), axis, direction),
                                                file.filename().string() + " shifted");
  }
  EXPECT_GT(nudged_apart, 0);
}

TEST(RoundSafeInput, MergingInputVerticesIsExactAndTransitive) {
  // delta = 2^-40: every coordinate below is a double, every distance known exactly.
  const double d = std::ldexp(1.0, -40);
  TriangleSoup s;
  s.vertices = {{1, 0, 0},          // 0
                {1 + d, 0, 0},      // 1: delta from 0, merged
                {1 + 2 * d, 0, 0},  // 2: delta from 1, 2 delta from 0: merged through 1
                {1, d + d * std::ldexp(1.0, -20), 0},  // 3: just beyond delta of 0 and 1: kept
                {1, 0, d},          // 4: exactly delta from 0: merged
                {5, 5, 5}};         // 5
  s.triangles = {{0, 1, 5}, {3, 4, 5}, {2, 3, 5}};
  s.label_set = {0, 0, 0};
  s.label_sets = {{0}};
  s.source = {0, 1, 2};
  const MergedInput m = merge_close_input_vertices(s, d);
  EXPECT_EQ(m.merged, 3u);
  ASSERT_EQ(m.soup.triangles.size(), 2u);  // (0, 1, 5) collapsed
  EXPECT_EQ(m.soup.triangles[0], (Tri{3, 0, 5}));
  EXPECT_EQ(m.soup.triangles[1], (Tri{0, 3, 5}));
  EXPECT_EQ(m.soup.source, (std::vector<std::int64_t>{1, 2}));
  EXPECT_GE(m.max_move, 2 * d);
  EXPECT_LE(m.max_move, 2 * d * (1 + 1e-12));
  EXPECT_EQ(merge_close_input_vertices(s, d / 2).merged, 0u);
}

}  // namespace
