// The classification stage on whole meshes (candidate pairs, native classifier, global
// deduplication) against a brute-force reference: every pair of triangles whose boxes
// overlap, classified by tritri on exact rationals, with the points built exactly from
// their types. The set of intersection points must be the same, point for point.
#include <gtest/gtest.h>

#include <tritri/tritri.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>

#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "support/mesh_generators.h"
#include "stages/1_preprocess.h"
#include "support/classify_oracle.h"
#include "support/exact_oracle.h"
#include "support/shared_meshes.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using tritri_test::exact;
using EK = tritri_test::ExactKernel;
using EP = EK::Point_3;
using Exact = tritri_test::Q3;

EP ep(const Vec3& v) { return tritri_test::to_cgal<EK>(v); }

bool boxes_overlap(const std::vector<Vec3>& V, const Tri& a, const Tri& b) {
  for (int k = 0; k < 3; ++k) {
    const double alo = std::min({V[a[0]][k], V[a[1]][k], V[a[2]][k]});
    const double ahi = std::max({V[a[0]][k], V[a[1]][k], V[a[2]][k]});
    const double blo = std::min({V[b[0]][k], V[b[1]][k], V[b[2]][k]});
    const double bhi = std::max({V[b[0]][k], V[b[1]][k], V[b[2]][k]});
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
}

using ExactSegment = std::pair<Exact, Exact>;

// Brute force: exact coordinates of every intersection point, the number of pairs that
// intersect beyond shared vertices, and per triangle the segments (as exact endpoints)
// that its pairs imply.
std::set<Exact> reference_points(const std::vector<Vec3>& V, const std::vector<Tri>& F, std::size_t& pairs,
                                 std::vector<std::set<ExactSegment>>& segments) {
  segments.assign(F.size(), {});
  using GK = tritri::CgalKernel<tritri_test::RationalKernel>;
  using GP = GK::Point;
  std::vector<GP> G;
  for (const Vec3& v : V) G.emplace_back(v[0], v[1], v[2]);
  std::set<Exact> out;
  pairs = 0;
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      const Tri &a = F[i], &b = F[j];
      if (!boxes_overlap(V, a, b)) continue;
      const tritri::Result r = tritri::classify<GK>(G[a[0]], G[a[1]], G[a[2]], G[b[0]], G[b[1]], G[b[2]]);
      bool only_shared = true;
      for (const auto& p : r.points) only_shared &= p.type == tritri::Type::VA_ON_VB;
      if (!r.intersects() || only_shared) continue;
      ++pairs;
      const tritri_test::OTriangle ta = {ep(V[a[0]]), ep(V[a[1]]), ep(V[a[2]])};
      const tritri_test::OTriangle tb = {ep(V[b[0]]), ep(V[b[1]]), ep(V[b[2]])};
      std::vector<Exact> pts;
      for (const auto& p : r.points) {
        const EP x = tritri_test::locate(p, ta, tb);  // a vertex, or edge lines / planes meeting
        out.insert(exact(x));
        pts.push_back(exact(x));
      }
      // A segment lying along a triangle's own edge is not a constraint of that triangle.
      auto along_an_edge = [&](const Tri& t, const Exact& p, const Exact& q) {
        auto on = [&](const EP& a, const EP& b, const Exact& x) {
          return EK::Segment_3(a, b).has_on(tritri_test::to_cgal<EK>(x));
        };
        for (int k = 0; k < 3; ++k) {
          const EP a = ep(V[t[k]]), b = ep(V[t[(k + 1) % 3]]);
          if (on(a, b, p) && on(a, b, q)) return true;
        }
        return false;
      };
      for (const auto& g : r.segments) {
        const ExactSegment seg = std::minmax(pts[g.p0], pts[g.p1]);
        if (!along_an_edge(a, seg.first, seg.second)) segments[i].insert(seg);
        if (!along_an_edge(b, seg.first, seg.second)) segments[j].insert(seg);
      }
    }
  return out;
}

void expect_matches_reference(const TriangleSoup& input, const std::string& name) {
  for (Classifier classifier : {Classifier::Native, Classifier::Tritri}) {
    const std::string what = name + (classifier == Classifier::Native ? " (native)" : " (tritri)");
    PreprocessStats stats;
    const TriangleSoup soup = preprocess(input, PreprocessOptions{}, stats);
    const auto& V = soup.vertices;
    const auto& F = soup.triangles;
    const auto records = classify_pairs(V, F, candidate_pairs(V, F), classifier);
    IntersectionGraph g = build_intersection_graph(V, F, records);

    std::size_t reference_pairs = 0;
    std::vector<std::set<ExactSegment>> expected_segments;
    const std::set<Exact> expected = reference_points(V, F, reference_pairs, expected_segments);
    // Per triangle, the constraint segments: its own, plus segments that coplanar sharing
    // copied from a coplanar partner (each one is that partner's own segment).
    for (std::size_t t = 0; t < F.size(); ++t) {
      std::set<ExactSegment> got_segments;
      for (const auto& seg : g.triangle_segments[t])
        got_segments.insert(std::minmax(exact(g.points[seg[0]]), exact(g.points[seg[1]])));
      for (const ExactSegment& seg : expected_segments[t])
        EXPECT_EQ(got_segments.count(seg), 1u) << what << " triangle " << t << ": a segment is missing";
      for (const ExactSegment& seg : got_segments) {
        if (expected_segments[t].count(seg)) continue;
        bool from_partner = false;
        for (int u : g.coplanar_partners[t]) from_partner = from_partner || expected_segments[u].count(seg) > 0;
        EXPECT_TRUE(from_partner) << what << " triangle " << t << ": a segment of no coplanar partner";
      }
    }
    std::set<Exact> got;
    for (const auto& rec : records)
      for (const auto& p : rec.points) {
        const int id = p.vertex >= 0 ? p.vertex : -1;
        if (id >= 0) got.insert(exact(g.points[id]));
      }
    // New points: every point of the graph beyond the input vertices.
    for (std::size_t i = V.size(); i < g.points.size(); ++i) got.insert(exact(g.points[i]));
    EXPECT_EQ(reference_pairs, g.intersecting_pairs) << what;
    EXPECT_EQ(expected.size(), got.size()) << what;
    EXPECT_TRUE(expected == got) << what;

    // New points are pairwise distinct and distinct from every input vertex (exact dedup).
    std::set<Exact> vertices;
    for (const Vec3& v : V) vertices.insert(exact(v));
    std::set<Exact> fresh;
    for (std::size_t i = V.size(); i < g.points.size(); ++i) {
      const Exact e = exact(g.points[i]);
      EXPECT_EQ(vertices.count(e), 0u) << what;
      EXPECT_TRUE(fresh.insert(e).second) << what;
    }
    // Every recorded point lies where it is recorded: inside its triangle or edge.
    for (std::size_t t = 0; t < F.size(); ++t) {
      const EK::Triangle_3 tri(ep(V[F[t][0]]), ep(V[F[t][1]]), ep(V[F[t][2]]));
      for (int x : g.triangle_points[t]) {
        const EP p = tritri_test::to_cgal<EK>(exact(g.points[x]));
        EXPECT_TRUE(tri.has_on(p)) << what << " triangle " << t;
        for (int k = 0; k < 3; ++k)
          EXPECT_FALSE(EK::Segment_3(tri.vertex(k), tri.vertex((k + 1) % 3)).has_on(p)) << what;
      }
    }
    for (std::size_t e = 0; e < g.edges.size(); ++e)
      for (int x : g.edge_points[e]) {
        const EP p = tritri_test::to_cgal<EK>(exact(g.points[x]));
        const EP a = ep(V[g.edges[e][0]]), b = ep(V[g.edges[e][1]]);
        EXPECT_TRUE(EK::Segment_3(a, b).has_on(p) && p != a && p != b) << what << " edge " << e;
      }
  }
}

TEST(IntersectionGraph, TwoSpheres) {
  expect_matches_reference(concatenate(uv_sphere({0, 0, 0}, 1.0, 10, 16), uv_sphere({0.7, 0.3, 0.2}, 0.8, 9, 14)),
                           "two spheres");
}

TEST(IntersectionGraph, CubeThroughCube) {
  expect_matches_reference(concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, -1, 0.5}, {3, 3, 1.5})), "cube through cube");
}

TEST(IntersectionGraph, CoplanarOverlappingGrids) {
  // Same plane, shifted by half a cell and by a third: many coplanar crossings.
  expect_matches_reference(concatenate(grid(6, 1.0, 0.0), grid(5, 1.0, 0.0, 0.5, 0.25)), "coplanar grids");
  expect_matches_reference(concatenate(grid(4, 1.0, 0.0), grid(4, 1.0, 0.0, 1.0, 0.0)), "grids sharing cells");
}

TEST(IntersectionGraph, GridThroughSpheres) {
  expect_matches_reference(concatenate(grid(8, 0.25, 0.0, -1, -1), uv_sphere({0, 0, 0}, 0.9, 8, 12)),
                           "grid through sphere");
}

TEST(IntersectionGraph, SmallSharedMeshes) {
  const std::filesystem::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  int checked = 0;
  for (const char* name : {"cherchi_arrangements/two_spheres.stl", "cherchi_arrangements/three_cubes.stl",
                           "cgal_data/mask_cone.off", "trimesh/soup.stl"}) {
    if (!std::filesystem::exists(dir / name)) continue;
    expect_matches_reference(load_triangle_soup((dir / name).string()), name);
    ++checked;
  }
  // The 2- and 3-triangle configurations.
  for (const auto& entry : std::filesystem::directory_iterator(dir / "cherchi_arrangements")) {
    if (entry.path().extension() != ".off") continue;
    expect_matches_reference(load_triangle_soup(entry.path().string()), entry.path().filename().string());
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// Every file of the shared collection loads and goes through the classification stage
// without an error other than InputError (meshes above a size limit that scales with
// TRITRI_TEST_SCALE are skipped, so that sanitizer runs stay short).
TEST(IntersectionGraph, EverySharedMeshLoadsAndClassifies) {
  const std::filesystem::path dir = tritri_test::shared_meshes_dir();
  TRITRI_REQUIRE_DATA(dir);
  const std::size_t max_triangles = static_cast<std::size_t>(130000 * tritri_test::test_scale());
  int classified = 0, refused = 0, skipped = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".ply") continue;
    TriangleSoup input;
    try {
      input = load_triangle_soup(entry.path().string());
    } catch (const InputError&) {
      ++refused;
      continue;
    }
    if (input.triangles.size() > max_triangles) {
      ++skipped;
      continue;
    }
    PreprocessStats stats;
    const TriangleSoup soup = preprocess(input, PreprocessOptions{}, stats);
    const auto records = classify_pairs(soup.vertices, soup.triangles, candidate_pairs(soup.vertices, soup.triangles),
                                        Classifier::Native);
    IntersectionGraph g = build_intersection_graph(soup.vertices, soup.triangles, records);
    EXPECT_EQ(g.intersecting_pairs, records.size()) << entry.path();
    EXPECT_EQ(g.points.size(), soup.vertices.size() + g.new_points) << entry.path();
    ++classified;
  }
  EXPECT_GT(classified, 0);
  std::printf("classified %d, refused %d, skipped (size) %d\n", classified, refused, skipped);
}

}  // namespace
