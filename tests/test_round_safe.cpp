// Safe rounding (issue 14, arrangements/round_mesh.h): the rounded mesh is still an
// arrangement, checked exactly and independently of round_safe's own loop:
//   - check_arrangement on the rounded doubles is clean;
//   - arranging the rounded mesh again finds nothing: no LPI, no TPI, no intersecting pair,
//     nothing merged or removed, the same triangles;
//   - provenance: every triangle keeps a source of the exact arrangement with one of its
//     label sets, and the area per source is that of the exact arrangement (to rounding);
//   - the displacement bound is a few ulps of the model's size.
// On every shared mesh with intersections, on generated rotated copies (near-degenerate
// crossings) and on rational scenes (the exact path). Rounding to nearest must fail the
// check on some of them, or these tests could not tell the two apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/round_mesh.h"
#include "round_merged_input.h"
#include "round_per_vertex.h"
#include "round_snapped_planes.h"
#include "support/exact_soups.h"
#include "support/loadable_meshes.h"
#include "support/mesh_generators.h"
#include "support/shared_meshes.h"
#include "support/temp_dir.h"
#include "support/test_scale.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;

Vec3 as_double(const tritri::ImplicitPoint& p) { return tritri::to_double(p); }
Vec3 as_double(const ExactVec3& p) { return tritri::to_double(p); }
Vec3 as_double(const Vec3& p) { return p; }

// Area of every triangle summed per source (doubles: a measure, not a decision).
template <class Mesh>
std::map<std::int64_t, double> area_per_source(const Mesh& m, double& total) {
  std::vector<Vec3> V;
  for (const auto& p : m.vertices) V.push_back(as_double(p));
  std::map<std::int64_t, double> area;
  total = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Vec3 &a = V[m.triangles[t][0]], &b = V[m.triangles[t][1]], &c = V[m.triangles[t][2]];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    const double at = 0.5 * std::sqrt(x * x + y * y + z * z);
    area[m.source[t]] += at;
    total += at;
  }
  return area;
}

// Every fact above for the safe rounding of `exact` (an OutputMesh or ExactOutputMesh; of
// `input`, passed to round_safe when given). Returns the report; `nearest_ok` receives
// whether rounding to nearest alone was valid, `rounded` (when given) the rounded mesh.
template <class Mesh>
RoundReport expect_safe_rounding(const Mesh& exact, const std::string& name, bool& nearest_ok,
                                 const TriangleSoup* input = nullptr, RoundedMesh* rounded = nullptr) {
  RoundReport report;
  const RoundedMesh r = round_safe(exact, RoundSafeOptions{.input = input}, &report);
  EXPECT_GE(report.passes, 1) << name;
  const ArrangementCheck c = check_arrangement(r);
  EXPECT_TRUE(c.ok()) << name << ": " << (c.examples.empty() ? "" : c.examples.front());

  const ArrangeResult again = arrange(arrangements::as_input(r), ArrangeOptions{});
  const ArrangeStats& s = again.stats;
  EXPECT_EQ(s.intersection_points, 0u) << name;
  EXPECT_EQ(s.tpi, 0u) << name;
  EXPECT_EQ(s.intersecting_pairs, 0u) << name;
  EXPECT_EQ(s.merged_vertices + s.removed_degenerate + s.removed_duplicate, 0u) << name;
  EXPECT_EQ(s.out_triangles, r.triangles.size()) << name;
  EXPECT_EQ(s.out_vertices, r.vertices.size()) << name;

  // Provenance: (source, label set) pairs of the rounded mesh are those of the exact one;
  // on a coarser grid or with merged input vertices, layers merged into one carry the
  // union of their labels.
  const bool layers_may_merge =
      report.grid > 0 || report.merged_input > 0 || report.reroute_cycles > 0 || report.snapped_vertices > 0;
  std::set<std::pair<std::int64_t, LabelSet>> exact_provenance;
  std::set<std::uint32_t> exact_labels;
  for (std::size_t t = 0; t < exact.triangles.size(); ++t) {
    const LabelSet& labels = exact.label_sets[exact.label_set[t]];
    exact_provenance.insert({exact.source[t], labels});
    exact_labels.insert(labels.begin(), labels.end());
  }
  for (std::size_t t = 0; t < r.triangles.size(); ++t) {
    const LabelSet& labels = r.label_sets[r.label_set[t]];
    const bool ok = !layers_may_merge ? exact_provenance.count({r.source[t], labels}) > 0
                                      : std::all_of(labels.begin(), labels.end(),
                                                   [&](std::uint32_t l) { return exact_labels.count(l) > 0; });
    if (!ok) {
      ADD_FAILURE() << name << ": rounded triangle " << t << " has provenance the exact arrangement lacks";
      break;
    }
  }
  double total_exact = 0, total_rounded = 0;
  const auto ae = area_per_source(exact, total_exact);
  const auto ar = area_per_source(r, total_rounded);
  // Rounded to nearest doubles, every input triangle keeps its area (to rounding); on a
  // coarser grid, layers thinner than a cell may merge into one (the region keeps one
  // source), so a source may lose area but never gains any.
  int sources_off = 0;
  for (const auto& [source, area] : ae) {
    const auto it = ar.find(source);
    const double rounded = it == ar.end() ? 0.0 : it->second;
    const bool ok = !layers_may_merge ? std::abs(rounded - area) <= 1e-9 * total_exact
                                      : rounded <= area + 1e-9 * total_exact;
    if (!ok && sources_off++ < 3)
      ADD_FAILURE() << name << ": source " << source << " has area " << rounded << ", exact " << area;
  }
  for (const auto& [source, area] : ar)
    EXPECT_TRUE(ae.count(source)) << name << ": source " << source << " is new";
  // The coarsest level's grid is 2^32 ulps of the largest magnitude (about 5e-7 of it).
  EXPECT_LE(report.max_move_relative, 1e-6) << name;
  EXPECT_EQ(report.max_move == 0, report.max_move_relative == 0) << name;

  nearest_ok = check_arrangement(round_nearest(exact)).ok();
  if (!nearest_ok) {
    EXPECT_GT(report.passes, 1) << name << ": rounding to nearest was not valid";
  }
  if (rounded) *rounded = r;
  return report;
}

TEST(RoundSafe, EverySharedMeshWithIntersectionsStaysAnArrangement) {
  const fs::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  const double scale = tritri_test::test_scale();
  const std::size_t every = scale < 1 ? static_cast<std::size_t>(std::lround(1 / scale)) : 1;
  std::size_t index = 0;
  int rounded = 0, more_than_one_pass = 0, coarser_grid = 0, last_resort = 0, rerouted = 0, nearest_invalid = 0;
  int max_passes = 0;
  double max_relative = 0;
  std::string max_relative_mesh;
  tritri_test::for_each_loadable_mesh(dir, [&](const fs::path& f, const TriangleSoup& input) {
    const ArrangeResult first = arrange(input, ArrangeOptions{});
    if (first.stats.intersection_points + first.stats.tpi == 0) return;
    if (index++ % every != 0) return;
    bool nearest_ok = true;
    const RoundReport report = expect_safe_rounding(first.mesh, f.string(), nearest_ok);
    ++rounded;
    more_than_one_pass += report.passes > 1;
    coarser_grid += report.grid > 0;
    last_resort += report.coarsened > 0;
    rerouted += report.rerouted > 0;
    nearest_invalid += !nearest_ok;
    max_passes = std::max(max_passes, report.passes);
    if (report.max_move_relative > max_relative) {
      max_relative = report.max_move_relative;
      max_relative_mesh = f.string();
    }
  });
  EXPECT_GT(rounded, 0);
  if (scale >= 1) {
    EXPECT_GT(nearest_invalid, 0) << "rounding to nearest was valid everywhere: the test tells nothing";
  }
  std::printf("rounded %d shared meshes with intersections: %d needed more than one pass (at most %d), %d a "
              "coarser grid (%d rounding per vertex), %d were rerouted, %d were invalid rounded to nearest; largest "
              "move / bounding-box diagonal %.3g (%s)\n",
              rounded, more_than_one_pass, max_passes, coarser_grid, last_resort, rerouted, nearest_invalid,
              max_relative, max_relative_mesh.c_str());
}

TEST(RoundSafe, RotatedCopiesOfASphere) {
  // Copies rotated about one axis cross at grazing angles near the poles: many LPIs and
  // TPIs within an ulp of other vertices and triangles. k = 2 rotates by pi, so the copies
  // are two layers about 1e-16 apart (sin(pi) is not 0 in doubles): rounding must merge
  // them (a coarser grid, or rerouting in cycles whose arrangements merge them).
  // k = 5 spends about 12 s (Release) in rerouting before a coarser grid settles it: not
  // at reduced test scale (the sanitizer run).
  std::vector<int> copies{2, 5};
  if (tritri_test::test_scale() < 1) copies.pop_back();
  for (int k : copies) {
    const TriangleSoup soup = rotated_copies(uv_sphere({0.1, 0.2, 0.3}, 1.0, 12, 24), k);
    const ArrangeResult first = arrange(soup, ArrangeOptions{});
    ASSERT_GT(first.stats.intersection_points, 0u);
    bool nearest_ok = true;
    const RoundReport report = expect_safe_rounding(first.mesh, "rotated copies k = " + std::to_string(k), nearest_ok);
    EXPECT_FALSE(nearest_ok) << k;
    // Nearest doubles and their passes alone do not settle these.
    EXPECT_TRUE(report.grid > 0 || report.rerouted > 0 || report.merged_input > 0) << k;
    std::printf("rotated copies k = %d: %d passes, grid %.3g, %zu rerouted, %d cycles, largest move / diagonal %.3g\n",
                k, report.passes, report.grid, report.rerouted, report.reroute_cycles, report.max_move_relative);
  }
}

TEST(RoundSafe, TwoCopiesRotatedByPiNeedTheLastResort) {
  // An odd number of segments: the copy rotated by pi (sin(pi) is not 0 in doubles) has
  // its meridians between the original's, and the two cross along curves at grazing
  // angles near the poles, where the passes of rounding and arranging keep making new
  // crossings at every level. Rerouting in cycles (or rounding per vertex: coarser grids
  // only at the conflicts) settles it: few vertices move, by a few ulps.
  for (int segments : {19, 39}) {
    const TriangleSoup soup = rotated_copies(uv_sphere({0, 0, 0}, 1.0, (segments + 1) / 2, segments), 2);
    const ArrangeResult first = arrange(soup, ArrangeOptions{});
    ASSERT_GT(first.stats.intersection_points, 0u);
    const std::string name = "two copies, " + std::to_string(segments) + " segments";
    bool nearest_ok = true;
    const RoundReport report = expect_safe_rounding(first.mesh, name, nearest_ok);
    EXPECT_FALSE(nearest_ok) << name;
    EXPECT_GT(report.coarsened + report.rerouted, 0u)
        << name << ": the passes alone settled it; the test tells nothing";
    EXPECT_LT(report.coarsened, first.mesh.vertices.size() / 10) << name;
    EXPECT_LE(report.max_move_relative, 1e-12) << name;
    std::printf("%s: %d passes, %zu vertices on coarser grids (coarsest %.3g), %zu rerouted, %d cycles, largest "
                "move / diagonal %.3g\n",
                name.c_str(), report.passes, report.coarsened, report.grid, report.rerouted, report.reroute_cycles,
                report.max_move_relative);
  }
}

TEST(RoundSafe, EmberPairsAreReroutedAtTheirSlivers) {
  // Two operands placed in contact by transforms rounded to doubles: the exact arrangement
  // has about 1,500 slivers whose apex lies within an ulp of the opposite edge. Rounded to
  // nearest they fold over their neighbours; the passes of rounding and arranging make new
  // ones at every level. Rerouting (round_rerouting.h) settles them with every vertex at
  // its nearest double: nothing on a coarser grid, the surface moved by an ulp per round at most.
  const fs::path script = tritri_test::shared_meshes_dir().parent_path() / "tools" / "make_ember_pairs.py";
  TRITRI_REQUIRE_DATA(script);
  tritri_test::TempDir tmp;
  const std::string command = "python3 '" + script.string() + "' '" + tmp.path().string() + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::vector<std::string> names{"ember-1063852-72214", "ember-88566-58011"};
  if (tritri_test::test_scale() < 1) names.resize(1);
  for (const std::string& name : names) {
    const ArrangeResult first = arrange(load_triangle_soup((tmp.path() / (name + ".off")).string()), ArrangeOptions{});
    ASSERT_GT(first.stats.intersection_points, 0u) << name;
    bool nearest_ok = true;
    const RoundReport report = expect_safe_rounding(first.mesh, name, nearest_ok);
    EXPECT_FALSE(nearest_ok) << name;
    EXPECT_GT(report.rerouted, 0u) << name << ": the passes alone settled it; the test tells nothing";
    EXPECT_EQ(report.coarsened, 0u) << name;
    EXPECT_EQ(report.grid, 0) << name;
    EXPECT_LE(report.max_move_relative, 1e-15) << name;
    std::printf("%s: %d passes and rounds, %zu vertices put on an edge or a face, largest move / diagonal %.3g\n",
                name.c_str(), report.passes, report.rerouted, report.max_move_relative);
  }
}

TEST(RoundSafe, NearlyCoincidentCopiesMergeAtTheirInputVertices) {
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
  EXPECT_THROW(round_safe(first.mesh), RoundingError);

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
  auto area = [](const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return 0.5 * std::hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]);
  };
  for (const Tri& f : soup.triangles) input_area += area(soup.vertices[f[0]], soup.vertices[f[1]], soup.vertices[f[2]]);
  for (std::size_t t = 0; t < r.triangles.size(); ++t) {
    const Tri& f = r.triangles[t];
    const double a = area(r.vertices[f[0]], r.vertices[f[1]], r.vertices[f[2]]);
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

TEST(RoundSafe, GrazingLayersOfThreeCopiesSettleByReroutingInCycles) {
  // Three copies of a sphere with 19 meridians rotated by 2 pi / 3 about the centre of its
  // bounding box: no vertex maps onto another (nothing to merge), and the layers cross at
  // grazing angles all over. Rerouting alone stalls (70 conflicts left); arranging its
  // best mesh again and rerouting that, in cycles, settles it within a few ulps per
  // rerouting round of the exact surface (every check of expect_safe_rounding: arranging the result again
  // changes nothing, provenance kept).
  const TriangleSoup soup = rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 19), 3);
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersection_points, 0u);
  bool nearest_ok = true;
  const RoundReport report = expect_safe_rounding(first.mesh, "grazing copies 10 x 19", nearest_ok, &soup);
  EXPECT_FALSE(nearest_ok);
  EXPECT_EQ(report.merged_input, 0u);
  EXPECT_EQ(report.grid, 0.0);
  EXPECT_GT(report.rerouted, 0u);
  EXPECT_LE(report.max_move_relative, 1e-14);
  std::printf("grazing copies 10 x 19: %d passes and rounds, %zu rerouted, largest move / diagonal %.3g\n",
              report.passes, report.rerouted, report.max_move_relative);
}

TEST(RoundSafe, GrazingLayersOfThreeCopiesAreRefusedCleanly) {
  // The known limit: the same with 21 meridians. Every last resort leaves conflicts, and
  // the cycles of rerouting and arranging grow them; round_safe gives up with
  // RoundingError within its budget (no growth without bound); `arrange --round safe`
  // exits with status 4.
  const TriangleSoup soup = rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 21), 3);
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersection_points, 0u);
  RoundReport report;
  EXPECT_THROW(round_safe(first.mesh, RoundSafeOptions{.input = &soup}, &report), RoundingError);
  EXPECT_EQ(report.merged_input, 0u);
  EXPECT_LE(report.passes, RoundSafeOptions{}.max_passes);
}

TEST(RoundSafe, RoundingPerVertexSettlesGrazingCopiesOnCoarserGridsAtTheConflicts) {
  // The last resort on its own (round_safe reaches it only when rerouting and its cycles
  // fail, which no input here does): two copies of a 10 x 19 sphere turned by pi about its
  // box centre, from the nearest doubles of the exact arrangement. It settles with a few
  // vertices on coarser grids, a few ulps off, and the result is an arrangement.
  const ArrangeResult first = arrange(rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 19), 2), ArrangeOptions{});
  const OutputMesh& m = first.mesh;
  std::vector<ExactVec3> exact;
  std::vector<Vec3> nearest;
  double largest = 0;
  for (const tritri::ImplicitPoint& p : m.vertices) {
    exact.push_back(tritri::to_exact(p));
    nearest.push_back(tritri::to_double(exact.back()));
    for (double c : nearest.back()) largest = std::max(largest, std::abs(c));
  }
  ASSERT_FALSE(check_arrangement(RoundedMesh{nearest, m.triangles, m.source, m.label_set, m.label_sets}).ok());
  const std::optional<PerVertexRounding> per =
      round_per_vertex(exact, nearest, m.triangles, m.source, m.label_set, m.label_sets, largest, 64);
  ASSERT_TRUE(per.has_value());
  EXPECT_TRUE(check_arrangement(per->mesh).ok());
  const ArrangeStats s = arrange(as_input(per->mesh), ArrangeOptions{}).stats;
  EXPECT_EQ(s.intersection_points + s.intersecting_pairs + s.merged_vertices + s.removed_degenerate, 0u);
  EXPECT_EQ(s.out_triangles, per->mesh.triangles.size());
  EXPECT_GT(per->coarsened, 0u);
  EXPECT_LT(per->coarsened, nearest.size() / 10);
  EXPECT_GT(per->grid, 0.0);
  EXPECT_LE(per->max_move, std::ldexp(largest, -40));  // a few ulps: 2^-40 of the size is 2^12 ulps
  std::printf("rounding per vertex, two copies 10 x 19: %d rounds, %zu vertices coarsened, move %.3g\n", per->rounds,
              per->coarsened, per->max_move);
}

// `soup` turned by 2 pi / 3 about the diagonal direction (1, 1, 1) through `centre`, then moved
// by `shift`, in doubles: a cube about its centre maps onto itself, its faces an ulp or so
// off their planes.
TriangleSoup turned_about_diagonal(TriangleSoup soup, const Vec3& centre, const Vec3& shift) {
  const double c = std::cos(2 * M_PI / 3), s = std::sin(2 * M_PI / 3), k = 1 / std::sqrt(3.0), t = 1 - c;
  const double R[3][3] = {{c + k * k * t, k * k * t - k * s, k * k * t + k * s},
                          {k * k * t + k * s, c + k * k * t, k * k * t - k * s},
                          {k * k * t - k * s, k * k * t + k * s, c + k * k * t}};
  for (Vec3& v : soup.vertices) {
    const Vec3 p{v[0] - centre[0], v[1] - centre[1], v[2] - centre[2]};
    for (int i = 0; i < 3; ++i) v[i] = R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2] + centre[i] + shift[i];
  }
  return soup;
}

// Three unit cubes, the second the first turned about its diagonal and moved along a face,
// the third the second turned again about its own centre and moved: faces of different
// cubes nearly coincide (within ulps, shifted in their planes) and share no vertex.
TriangleSoup turned_cubes() {
  const TriangleSoup a = box({0, 0, 0}, {1, 1, 1});
  const TriangleSoup b = turned_about_diagonal(a, {0.5, 0.5, 0.5}, {0.3, 0.2, 0});
  const TriangleSoup c = turned_about_diagonal(b, {0.8, 0.7, 0.5}, {0.1, 0.3, 0});
  return concatenate(concatenate(a, b), c);
}

TEST(RoundSafe, NearlyCoplanarFacesOfTurnedCubesAreSnappedCoplanar) {
  const TriangleSoup soup = turned_cubes();
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersecting_pairs, 0u);
  ASSERT_EQ(first.stats.coplanar_pairs, 0u);  // nearly, not exactly, coplanar
  // Without the input, no step settles the layers that cross wherever the errors change sign.
  EXPECT_THROW(round_safe(first.mesh), RoundingError);
  bool nearest_ok = true;
  const RoundReport report = expect_safe_rounding(first.mesh, "turned cubes", nearest_ok, &soup);
  EXPECT_FALSE(nearest_ok);
  EXPECT_GT(report.snapped_vertices, 0u);
  EXPECT_EQ(report.merged_input, 0u);
  EXPECT_LE(report.max_move_relative, 1e-14);
  std::printf("turned cubes: %d passes, %zu input vertices snapped, largest move / diagonal %.3g\n", report.passes,
              report.snapped_vertices, report.max_move_relative);
}

TEST(RoundSafe, SnappingNearlyCoplanarFacesMakesThemExactlyCoplanar) {
  const TriangleSoup soup = turned_cubes();
  const double delta = std::ldexp(1.0, -52 + 2);  // 4 ulps of the largest magnitude (in [1, 2))
  const SnappedPlanes snapped = snap_near_coplanar_faces(soup, delta, 0);
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
  EXPECT_EQ(snap_near_coplanar_faces(box({0, 0, 0}, {1, 1, 1}), delta, 0).moved, 0u);
}

TEST(RoundSafe, ACopyMovedBy1e9AndTurnedBy1e7SettlesOnTheCoarsestGrid) {
  // QuickCSG's t1_48 and a copy turned by 1e-7 rad about its box centre and moved by 1e-9 of
  // its diagonal (bench/round_safe_sweep.py's "shift" variant, seed 1): layers crossing at
  // grazing angles everywhere. Only the coarsest grid, 2^32 ulps, puts the copies on one
  // grid; its 4th pass still drops duplicate triangles without finding an intersection,
  // and the 5th settles (a pass that finds none makes no new point).
  const fs::path file = tritri_test::shared_meshes_dir() / "thingicsg" / "QuickCSG" / "T1" / "t1_48.off";
  TRITRI_REQUIRE_DATA(file);
  TriangleSoup mesh = load_triangle_soup(file.string());
  mesh.polygon.clear();  // concatenate keeps no polygon ids
  const Vec3 axis{0.045609566428869625, 0.46022821167165107, 0.8866283103035254};
  const Vec3 direction{0.03177729554885592, 0.989647738007784, 0.13995555774486879};
  const double diagonal = 330.09472127857964, angle = 1e-7;
  Vec3 lo = mesh.vertices[0], hi = mesh.vertices[0];
  for (const Vec3& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis[0], y = axis[1], z = axis[2];
  const double R[3][3] = {{c + x * x * t, x * y * t - z * s, x * z * t + y * s},
                          {y * x * t + z * s, c + y * y * t, y * z * t - x * s},
                          {z * x * t - y * s, z * y * t + x * s, c + z * z * t}};
  TriangleSoup copy = mesh;
  for (Vec3& v : copy.vertices) {
    const Vec3 d{v[0] - (lo[0] + hi[0]) / 2, v[1] - (lo[1] + hi[1]) / 2, v[2] - (lo[2] + hi[2]) / 2};
    for (int i = 0; i < 3; ++i)
      v[i] = (lo[i] + hi[i]) / 2 + R[i][0] * d[0] + R[i][1] * d[1] + R[i][2] * d[2] + 1e-9 * diagonal * direction[i];
  }
  const TriangleSoup soup = concatenate(mesh, copy);
  const ArrangeResult first = arrange(soup, ArrangeOptions{});
  ASSERT_GT(first.stats.intersecting_pairs, 0u);
  // expect_safe_rounding's area and move limits are for finer grids: on 2^32 ulps a source may
  // gain area (by about the grid's size over its length) and the passes' moves add up.
  RoundReport report;
  const RoundedMesh r = round_safe(first.mesh, RoundSafeOptions{.input = &soup}, &report);
  EXPECT_TRUE(check_arrangement(r).ok());
  const ArrangeStats again = arrange(arrangements::as_input(r), ArrangeOptions{}).stats;
  EXPECT_EQ(again.intersecting_pairs + again.tpi + again.merged_vertices + again.removed_degenerate +
                again.removed_duplicate,
            0u);
  EXPECT_EQ(again.out_triangles, r.triangles.size());
  EXPECT_GT(report.grid, 0.0);
  EXPECT_LE(report.max_move_relative, 1e-5);
  for (std::size_t i = 0; i < r.triangles.size(); ++i)
    ASSERT_LT(r.source[i], static_cast<std::int64_t>(soup.triangles.size()));
  std::printf("t1_48 and its shifted copy: %d passes, grid %.3g, largest move / diagonal %.3g\n", report.passes,
              report.grid, report.max_move_relative);
}

TEST(RoundSafe, MergingInputVerticesIsExactAndTransitive) {
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

TEST(RoundSafe, RationalScenesOnTheExactPath) {
  // A grid in the plane z = 1/3 crossed by a tilted grid with coordinates in sevenths:
  // every vertex and every new point rational, none a double.
  auto q = [](long n, long d) { return CGAL::Gmpq(n, d); };
  for (int tilt : {1, 3, 7}) {
    ExactTriangleSoup s = arrangements::to_exact(grid(4, 1.0, 0.0));
    for (auto& v : s.vertices) v[2] = q(1, 3);
    ExactTriangleSoup t = arrangements::to_exact(grid(4, 1.0, 0.0));
    for (auto& v : t.vertices) {
      // x' = x/7 + 1/11, z' = x * tilt / 7 - 1/5 (a plane through the first grid)
      const CGAL::Gmpq x = v[0];
      v[0] = x / q(7, 1) + q(1, 11);
      v[2] = x * q(tilt, 7) - q(1, 5);
      v[1] = v[1] + q(1, 13);
    }
    const std::size_t offset = s.vertices.size();
    for (auto& v : t.vertices) s.vertices.push_back(v);
    for (auto f : t.triangles) {
      for (int& i : f) i += static_cast<int>(offset);
      s.triangles.push_back(f);
      s.label_set.push_back(1);
      s.source.push_back(static_cast<std::int64_t>(s.source.size()));
    }
    s.label_sets = {{0}, {1}};
    const ExactArrangeResult first = arrange(s, ArrangeOptions{});
    ASSERT_GT(first.stats.intersection_points, 0u);
    bool nearest_ok = true;
    const RoundReport report =
        expect_safe_rounding(first.mesh, "rational grids, tilt " + std::to_string(tilt), nearest_ok);
    EXPECT_GT(report.max_move, 0);  // no vertex is a double
  }
}

TEST(RoundSafe, AnArrangementOfDoublesIsKeptAsItIs) {
  const TriangleSoup soup = concatenate(box({0, 0, 0}, {1, 1, 1}), box({2, 0, 0}, {3, 1, 1}));
  const ArrangeResult a = arrange(soup, ArrangeOptions{});
  RoundReport report;
  const RoundedMesh r = round_safe(a.mesh, RoundSafeOptions{}, &report);
  EXPECT_EQ(report.passes, 1);
  EXPECT_EQ(report.max_move, 0);
  ASSERT_EQ(r.vertices.size(), a.mesh.vertices.size());
  for (std::size_t v = 0; v < r.vertices.size(); ++v) EXPECT_EQ(r.vertices[v], a.mesh.vertices[v].approx());
  EXPECT_EQ(r.triangles, a.mesh.triangles);
  EXPECT_EQ(r.source, a.mesh.source);
  EXPECT_EQ(r.label_set, a.mesh.label_set);
}

TEST(RoundSafe, PassLimit) {
  // Two copies of a 10 x 19 sphere turned by pi about its box centre: passes, rerouting and
  // a cycle of it (11 passes and rounds), in half a second.
  const ArrangeResult a = arrange(rotated_copies(uv_sphere({0, 0, 0}, 1.0, 10, 19), 2), ArrangeOptions{});
  EXPECT_THROW(round_safe(a.mesh, RoundSafeOptions{.max_passes = 0}), std::invalid_argument);
  RoundReport report;
  round_safe(a.mesh, RoundSafeOptions{}, &report);
  ASSERT_GT(report.passes, 1);
  ASSERT_GT(report.reroute_cycles, 0);
  EXPECT_THROW(round_safe(a.mesh, RoundSafeOptions{.max_passes = report.passes - 1}), RoundingError);
  EXPECT_NO_THROW(round_safe(a.mesh, RoundSafeOptions{.max_passes = report.passes}));
}

}  // namespace
