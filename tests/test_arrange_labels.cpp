// tests/test_arrange_labels.cpp
//
// Labels and provenance of the arrangement: a coplanar overlap of two labelled triangles
// is emitted once with both labels, owned by the triangle listed first; overlapping
// squares and duplicate grid cells merge their labels; sources map back to the input.
// Areas are exact (rationals), for both classifiers.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "support/arrangement_scenes.h"
#include "support/exact_oracle.h"
#include "support/triangulation_checks.h"

namespace {

using namespace tritri_test::arrangement;
using tritri_test::area2;
using tritri_test::exact;
using tritri_test::Q;

struct Region {
  std::size_t triangles = 0;
  Q area2 = 0;  // XY projection, absolute
  std::set<std::int64_t> sources;
};

// Output triangles grouped by label set.
std::map<LabelSet, Region> regions_by_labels(const OutputMesh& m) {
  std::map<LabelSet, Region> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    Region& r = out[m.label_sets.at(m.label_set[t])];
    ++r.triangles;
    const Tri& T = m.triangles[t];
    r.area2 += abs(area2(exact(m.vertices[T[0]]), exact(m.vertices[T[1]]), exact(m.vertices[T[2]]), 2));
    r.sources.insert(m.source[t]);
  }
  return out;
}

TEST(Arrange, CoplanarOverlapOfTwoLabelledTrianglesIsEmittedOnceWithBothLabels) {
  for (bool t1_first : {false, true})
    for (Classifier c : kClassifiers) {
      const std::string what = std::string(name_of(c)) + (t1_first ? ", T1 first" : "");
      const ArrangeResult r = run_arrange(overlapping_triangles(t1_first), c);
      EXPECT_EQ(r.mesh.label_sets.size(), 3u) << what;
      const auto regions = regions_by_labels(r.mesh);
      ASSERT_EQ(regions.size(), 3u) << what;
      // Overlap: the triangle (1,1) (3,1) (1,3), area 2, owned by the triangle listed first.
      const Region& both = regions.at({0, 1});
      EXPECT_EQ(both.triangles, 1u) << what;
      EXPECT_EQ(both.area2, Q(4)) << what;
      EXPECT_EQ(both.sources, std::set<std::int64_t>{t1_first ? 200 : 100}) << what;
      // T0 alone: the hexagon (0,0) (4,0) (3,1) (1,1) (1,3) (0,4), 4 triangles, area 8 - 2.
      const Region& zero = regions.at({0});
      EXPECT_EQ(zero.triangles, 4u) << what;
      EXPECT_EQ(zero.area2, Q(12)) << what;
      EXPECT_EQ(zero.sources, std::set<std::int64_t>{100}) << what;
      // T1 alone: the quadrilateral (3,1) (5,1) (1,5) (1,3), 2 triangles, area 8 - 2.
      const Region& one = regions.at({1});
      EXPECT_EQ(one.triangles, 2u) << what;
      EXPECT_EQ(one.area2, Q(12)) << what;
      EXPECT_EQ(one.sources, std::set<std::int64_t>{200}) << what;
    }
}

TEST(Arrange, OverlappingSquaresLabelsAndSources) {
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(overlapping_squares(), c);
    const auto regions = regions_by_labels(r.mesh);
    ASSERT_EQ(regions.size(), 3u) << name_of(c);
    // The overlap [1,2]^2 is cut by the common diagonal: one half in each triangle of the
    // first square (sources 100 and 101), both covered by the second square too.
    EXPECT_EQ(regions.at({0, 1}).triangles, 2u);
    EXPECT_EQ(regions.at({0, 1}).area2, Q(2));
    EXPECT_EQ(regions.at({0, 1}).sources, (std::set<std::int64_t>{100, 101}));
    // The rest of each square: two quadrilaterals of area 3/2, two triangles each.
    EXPECT_EQ(regions.at({0}).triangles, 4u);
    EXPECT_EQ(regions.at({0}).area2, Q(6));
    EXPECT_EQ(regions.at({0}).sources, (std::set<std::int64_t>{100, 101}));
    EXPECT_EQ(regions.at({1}).triangles, 4u);
    EXPECT_EQ(regions.at({1}).area2, Q(6));
    EXPECT_EQ(regions.at({1}).sources, (std::set<std::int64_t>{200, 201}));
  }
}

// Duplicate triangles (the shared cells of the grids) merge their labels: those cells get
// {0, 1}; the cells of one grid only keep its label.
TEST(Arrange, DuplicateCellsMergeLabels) {
  for (Classifier c : kClassifiers) {
    const ArrangeResult r = run_arrange(grids_sharing_cells(), c);
    const auto regions = regions_by_labels(r.mesh);
    ASSERT_EQ(regions.size(), 3u) << name_of(c);
    EXPECT_EQ(regions.at({0, 1}).area2, Q(2 * 12));  // [1,4] x [0,4]
    EXPECT_EQ(regions.at({0}).area2, Q(2 * 4));      // [0,1] x [0,4]
    EXPECT_EQ(regions.at({1}).area2, Q(2 * 4));      // [4,5] x [0,4]
    // The shared cells come from the first grid (its triangles are numbered first).
    for (std::int64_t s : regions.at({0, 1}).sources) EXPECT_LT(s, 32) << name_of(c);
    for (std::int64_t s : regions.at({1}).sources) EXPECT_GE(s, 32) << name_of(c);
  }
}

}  // namespace
