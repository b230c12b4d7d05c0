// tests/test_arrange_upstream_failures.cpp
//
// Known failure modes of the upstream implementation, each passing here: many
// unreferenced vertices, unknown file extensions (a clear InputError), tiny coordinates
// (a power of two: the exact output times 2^k; not one: the same topology), and coplanar
// edge-edge crossings (proper LPIs at the exact rational crossings), for both classifiers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "arrangements/check_arrangement.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/write_mesh.h"
#include "pipeline.h"
#include "support/arrangement_scenes.h"
#include "support/exact_oracle.h"
#include "support/triangulation_checks.h"
#include "support/temp_dir.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::exact;
using tritri_test::Q;
using tritri_test::Q3;
using tritri_test::to_cgal;
namespace fs = std::filesystem;

// Upstream crashes when unreferenced vertices outnumber 3x the triangles.
TEST(Arrange, ManyUnreferencedVerticesAreIgnored) {
  // The two crossing triangles (V 8, F 8 by hand, above) plus 8 disjoint triangles far
  // away (copied as they are: 24 vertices), with 1000 unused vertices interleaved.
  TriangleSoup s = two_triangles_crossing();
  for (int i = 0; i < 8; ++i) {
    const int base = static_cast<int>(s.vertices.size());
    s.vertices.push_back({100.0 + 10 * i, 0, 0});
    s.vertices.push_back({101.0 + 10 * i, 0, 0});
    s.vertices.push_back({100.0 + 10 * i, 1, 0});
    s.triangles.push_back({base, base + 1, base + 2});
    s.label_set.push_back(0);
    s.source.push_back(static_cast<std::int64_t>(s.source.size()));
    for (int j = 0; j < 125; ++j) s.vertices.push_back({-50.0 - i, 0.5 * j, 7.25});
  }
  ASSERT_EQ(s.triangles.size(), 10u);
  ASSERT_EQ(s.vertices.size(), 6u + 8 * 128);
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(s, c);
    EXPECT_EQ(r.stats.in_vertices, s.vertices.size());
    EXPECT_EQ(mesh_counts(r.mesh.triangles), counts(8 + 24, 15 + 24, 8 + 8)) << name_of(c);
    EXPECT_EQ(r.mesh.vertices.size(), 32u);
    for (const ImplicitPoint& v : r.mesh.vertices) EXPECT_GE(tritri::to_double(v)[0], -1.0) << "an unused vertex";
    EXPECT_TRUE(check_arrangement(r.mesh).ok());
  }
}

// Upstream crashes on an unknown extension; here it is a clear InputError.
TEST(Arrange, UnknownExtensionsAreInputErrors) {
  const tritri_test::TempDir dir;
  const fs::path tmp = dir.path();
  const ArrangeResult r = run_arrange(two_triangles_crossing(), Classifier::Tritri);
  for (const char* name : {"out.stlx", "out", "out.obj.bak", "out.xyz"}) {
    const fs::path path = tmp / name;
    try {
      write_mesh(path.string(), r.mesh);
      ADD_FAILURE() << name << ": no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unknown_format) << name << ": " << e.what();
    }
    EXPECT_FALSE(fs::exists(path)) << name;
  }
  // A valid OBJ under unknown names is refused by the loader; under .OBJ it loads.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const char* name : {"in.xyz", "in.obj2", "in"}) {
    std::ofstream(tmp / name) << obj;
    try {
      load_triangle_soup((tmp / name).string());
      ADD_FAILURE() << name << ": no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.kind, InputErrorKind::unknown_format) << name << ": " << e.what();
    }
  }
  std::ofstream(tmp / "in.OBJ") << obj;
  EXPECT_EQ(load_triangle_soup((tmp / "in.OBJ").string()).triangles.size(), 1u);
  // Round trip: what write_mesh writes, load_triangle_soup reads.
  write_mesh((tmp / "out.off").string(), r.mesh);
  EXPECT_EQ(load_triangle_soup((tmp / "out.off").string()).triangles.size(), r.mesh.triangles.size());
}

// Upstream computes its scale with an int shift and gets coordinates below 1 wrong. Scaling
// by 2^k changes no predicate, so the output is the unscaled output times 2^k exactly,
// also with options.scale (arrange.h: the output is in the input's frame).
TEST(Arrange, TinyCoordinatesPowerOfTwo) {
  for (const auto& [name, soup] :
       std::vector<std::pair<std::string, TriangleSoup>>{{"cube through cube", cube_through_cube()},
                                                         {"star of David", kRationalStar.soup()},
                                                         {"two triangles crossing", two_triangles_crossing()}})
    for (Classifier c : kClassifiers) {
      const ArrangeResult ref = run_arrange(soup, c);
      for (int k : {-60, -1000})
        for (bool scale : {false, true}) {
          const std::string what = name + " (" + name_of(c) + ") 2^" + std::to_string(k) + (scale ? " scaled" : "");
          const ArrangeResult r = run_arrange(scaled_pow2(soup, k), c, 0, scale);
          EXPECT_EQ(mesh_counts(r.mesh.triangles), mesh_counts(ref.mesh.triangles)) << what;
          EXPECT_EQ(r.mesh.triangles, ref.mesh.triangles) << what;
          EXPECT_EQ(r.mesh.source, ref.mesh.source) << what;
          ASSERT_EQ(r.mesh.vertices.size(), ref.mesh.vertices.size()) << what;
          // The factor: from the first vertex with a non-zero coordinate, then checked for
          // every coordinate of every vertex.
          Q factor = 0;
          std::size_t mismatches = 0;
          for (std::size_t i = 0; i < ref.mesh.vertices.size(); ++i) {
            const Q3 a = exact(ref.mesh.vertices[i]), b = exact(r.mesh.vertices[i]);
            for (int d = 0; d < 3; ++d) {
              if (sgn(factor) == 0 && sgn(a[d]) != 0) factor = b[d] / a[d];
              mismatches += b[d] != a[d] * factor;
            }
          }
          EXPECT_EQ(mismatches, 0u) << what;
          EXPECT_EQ(factor, Q(std::ldexp(1.0, k))) << what;
        }
    }
}

// Coordinates around 1e-7 (not a power of two: the geometry changes by rounding, but not
// its combinatorics here, which are far from degenerate): still a valid arrangement with
// the same topology.
TEST(Arrange, TinyCoordinatesNotAPowerOfTwo) {
  for (const auto& [name, soup, euler] :
       std::vector<std::tuple<std::string, TriangleSoup, long long>>{{"cube through cube", cube_through_cube(), 4},
                                                                     {"two spheres", two_spheres(), 4},
                                                                     {"rational star", kRationalStar.soup(), 1}})
    for (Classifier c : kClassifiers)
      for (bool scale : {false, true}) {
        const std::string what = name + " (" + name_of(c) + ")" + (scale ? " scaled" : "");
        const ArrangeResult r = run_arrange(scaled(soup, 1e-7), c, 0, scale);
        const ArrangementCheck check = check_arrangement(r.mesh);
        EXPECT_TRUE(check.ok()) << what << ": " << (check.examples.empty() ? "" : check.examples.front());
        EXPECT_EQ(r.stats.euler, euler) << what;
        EXPECT_EQ(mesh_counts(r.mesh.triangles), mesh_counts(run_arrange(soup, c).mesh.triangles)) << what;
      }
}

// A bug of the authors' tri-tri tool: coplanar edge-edge crossings built as undefined LPIs.
// Here each crossing of the star is an LPI at the exact rational crossing of the two edges
// (computed here in 2D by Cramer's rule, then lifted to the plane), strictly inside both.
TEST(Arrange, CoplanarEdgeCrossingsAreProperLPIs) {
  for (const Star* star : {&kIntegerStar, &kRationalStar}) {
    // The expected crossings: every pair (edge of A, edge of B) whose segments cross
    // properly in 2D (exact signs), at the exact intersection point.
    std::set<Q3> expected;
    std::vector<std::array<Q3, 4>> expected_edges;  // per crossing: its two edges
    auto q2 = [&](int i) { return std::array<Q, 2>{Q(star->corners[i][0]), Q(star->corners[i][1])}; };
    auto o2 = [](const std::array<Q, 2>& a, const std::array<Q, 2>& b, const std::array<Q, 2>& c) {
      return sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    };
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const auto p = q2(i), q = q2((i + 1) % 3), r = q2(3 + j), s = q2(3 + (j + 1) % 3);
        if (o2(p, q, r) * o2(p, q, s) >= 0 || o2(r, s, p) * o2(r, s, q) >= 0) continue;
        // p + t (q - p) on line rs: t = cross(r - p, s - r) / cross(q - p, s - r).
        const Q den = (q[0] - p[0]) * (s[1] - r[1]) - (q[1] - p[1]) * (s[0] - r[0]);
        const Q t = ((r[0] - p[0]) * (s[1] - r[1]) - (r[1] - p[1]) * (s[0] - r[0])) / den;
        const Q x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]);
        const Q3 X{x, y, Q(star->cz) + Q(star->ax) * x + Q(star->ay) * y};
        expected.insert(X);
        auto lift = [&](int k) { return exact(star->lift(star->corners[k])); };
        expected_edges.push_back({lift(i), lift((i + 1) % 3), lift(3 + j), lift(3 + (j + 1) % 3)});
      }
    ASSERT_EQ(expected.size(), 6u) << "the scene is not a star";
    if (star == &kIntegerStar) {  // the derivation agrees with the crossings read off by hand
      EXPECT_TRUE(expected.count({Q(4), Q(0), Q(4)}) && expected.count({Q(8), Q(8), Q(24)}) &&
                  expected.count({Q(2), Q(4), Q(10)}) && expected.count({Q(10), Q(4), Q(18)}));
    }
    for (Classifier c : kClassifiers) {
      ArrangeOptions o;
      o.classifier = c;
      PipelineInternals kept;
      const ArrangeResult r = run_pipeline(star->soup(), o, &kept);
      const IntersectionGraph& g = kept.graph;
      ASSERT_EQ(g.points.size() - g.num_input_vertices, 6u) << name_of(c);
      std::set<Q3> got;
      for (std::size_t i = g.num_input_vertices; i < g.points.size(); ++i) {
        EXPECT_EQ(g.points[i].kind(), ImplicitPoint::Kind::LPI) << name_of(c);
        got.insert(exact(g.points[i]));
      }
      EXPECT_EQ(got, expected) << name_of(c);
      auto inside = [](const Q3& x, const Q3& a, const Q3& b) {  // strictly inside segment ab
        using K = tritri_test::ExactKernel;
        return tritri_test::in_open_segment(to_cgal<K>(x), to_cgal<K>(a), to_cgal<K>(b));
      };
      for (const auto& e : expected_edges) {
        // The crossing of these two edges is strictly inside both.
        int found = 0;
        for (const Q3& x : got) found += inside(x, e[0], e[1]) && inside(x, e[2], e[3]);
        EXPECT_EQ(found, 1) << name_of(c);
      }
      // Every output vertex is an input corner or one of the crossings.
      std::set<Q3> allowed = expected;
      for (const auto& corner : star->corners) allowed.insert(exact(star->lift(corner)));
      for (const ImplicitPoint& v : r.mesh.vertices) EXPECT_EQ(allowed.count(exact(v)), 1u) << name_of(c);
      EXPECT_EQ(r.mesh.vertices.size(), 12u) << name_of(c);
    }
  }
}

}  // namespace
