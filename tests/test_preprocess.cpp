// Specification of preprocess (arrangements/src/stages/1_preprocess.h):
// - vertices with identical coordinates (also -0.0 / 0.0) become one, in first-use order;
//   coordinates one ulp apart stay apart; unreferenced vertices are dropped;
// - triangles with repeated positions or exactly collinear corners are removed (also when
//   only some projections are degenerate, a triangle is kept);
// - duplicate triangles (any corner order or orientation) merge into the first, which keeps
//   its corner order and source and gets the union of all label sets (no cap);
// - a naive reference (all-pairs comparisons, integer cross products) agrees on random
//   soups on a small grid;
// - optional scaling by 2^k puts the largest |coordinate| in [2^9, 2^10), exactly, for any
//   magnitude (below 1, subnormal, huge), and leaves the model unscaled when it would round.
// Expected values are written by hand or computed by the naive reference.
#include <gtest/gtest.h>

#include "arrangements/arrange.h"
#include "stages/1_preprocess.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace {

using arrangements::InputError;
using arrangements::InputErrorKind;
using arrangements::LabelSet;
using arrangements::preprocess;
using arrangements::PreprocessOptions;
using arrangements::PreprocessStats;
using arrangements::Tri;
using arrangements::TriangleSoup;
using arrangements::Vec3;

// A soup whose triangle t has label set `sets[t]` (one label set entry per triangle) and
// source 100 + t.
TriangleSoup make_soup(std::vector<Vec3> vertices, std::vector<Tri> triangles, std::vector<LabelSet> sets = {}) {
  TriangleSoup s;
  s.vertices = std::move(vertices);
  s.triangles = std::move(triangles);
  if (sets.empty()) sets.assign(s.triangles.size(), LabelSet{0});
  s.label_sets = std::move(sets);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    s.label_set.push_back(static_cast<int>(t));
    s.source.push_back(100 + static_cast<std::int64_t>(t));
  }
  return s;
}

// The label set of each output triangle.
std::vector<LabelSet> labels_of(const TriangleSoup& s) {
  std::vector<LabelSet> out;
  for (int l : s.label_set) out.push_back(s.label_sets[l]);
  return out;
}

TEST(Preprocess, MergesIdenticalCoordinatesIncludingSignedZerosInFirstUseOrder) {
  const double one_plus_ulp = std::nextafter(1.0, 2.0);
  const TriangleSoup in = make_soup({{-0.0, 0, -0.0},       // 0
                                     {0, 1, 0},             // 1
                                     {1, 0, 0},             // 2
                                     {0.0, -0.0, 0.0},      // 3 == 0
                                     {one_plus_ulp, 0, 0},  // 4 != 2
                                     {0, 1, 0},             // 5 == 1
                                     {7, 7, 7}},            // 6 unused
                                    {{2, 5, 3}, {0, 4, 1}});
  PreprocessStats stats;
  const TriangleSoup out = preprocess(in, {}, stats);
  EXPECT_EQ(out.vertices, (std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {one_plus_ulp, 0, 0}}));
  for (const Vec3& v : out.vertices)
    for (double c : v) EXPECT_FALSE(std::signbit(c)) << "-0.0 is written as +0.0";
  EXPECT_EQ(out.triangles, (std::vector<Tri>{{0, 1, 2}, {2, 3, 1}}));
  EXPECT_EQ(out.source, (std::vector<std::int64_t>{100, 101}));
  EXPECT_EQ(stats.merged_vertices, 2u);
  EXPECT_EQ(stats.unreferenced_vertices, 1u);
  EXPECT_EQ(stats.removed_degenerate, 0u);
  EXPECT_EQ(stats.removed_duplicate, 0u);
  EXPECT_EQ(stats.scale_exponent, 0);
}

TEST(Preprocess, RemovesExactlyTheTrianglesWithRepeatedOrCollinearCorners) {
  const Vec3 a{1, 2, 3}, d{0.5, -0.25, 0.125};
  auto along = [&](double s) { return Vec3{a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2]}; };  // exact
  const TriangleSoup in = make_soup(
      {
          {0, 0, 0},
          {1, 0, 0},
          {0, 1, 0},  // 0-2 a proper triangle
          {0, 0, 0},  // 3 same position as 0
          along(0),
          along(1),
          along(3),  // 4-6 collinear in 3D
          {0, 0, 0},
          {1, 1, 1},
          {2, 2, 2 + std::ldexp(1.0, -50)},  // 7-9 almost collinear
          {0, 0, 0},
          {1, 1, 0},
          {2, 2, 1},  // 10-12 collinear in XY only
          {0, 0, 0},
          {0, 0, 1},
          {1, 0, 0},  // 13-15 vertical: degenerate in XY
          {5, 5, 5},  // 16 used by a degenerate triangle only
      },
      {{0, 1, 2}, {0, 1, 1}, {3, 1, 0}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}, {13, 14, 15}, {16, 16, 16}});
  PreprocessStats stats;
  const TriangleSoup out = preprocess(in, {}, stats);
  EXPECT_EQ(out.source, (std::vector<std::int64_t>{100, 104, 105, 106}));
  EXPECT_EQ(stats.removed_degenerate, 4u);
  EXPECT_EQ(stats.removed_duplicate, 0u);
  // Distinct positions: 0,1,2, a, a+d, a+3d, (1,1,1), (2,2,2+e), (1,1,0), (2,2,1), (0,0,1), (5,5,5):
  // 12 of 17 input vertices; unused: a, a+d, a+3d, (5,5,5).
  EXPECT_EQ(stats.merged_vertices, 5u);
  EXPECT_EQ(stats.unreferenced_vertices, 4u);
  EXPECT_EQ(out.vertices.size(), 8u);
}

TEST(Preprocess, MergesDuplicateTrianglesIntoTheFirstWithTheUnionOfLabels) {
  const TriangleSoup in = make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}},
                                    {
                                        {0, 1, 2},  // kept
                                        {6, 1, 2},  // another triangle
                                        {2, 1, 0},  // opposite orientation
                                        {1, 2, 0},  // rotated
                                        {3, 4, 5},  // same positions through other vertices
                                        {2, 6, 1},  // duplicate of the second, same labels
                                    },
                                    {{3}, {1}, {1, 3}, {0}, {2, 5, 1000}, {1}});
  PreprocessStats stats;
  const TriangleSoup out = preprocess(in, {}, stats);
  EXPECT_EQ(out.triangles, (std::vector<Tri>{{0, 1, 2}, {3, 1, 2}}));
  EXPECT_EQ(labels_of(out), (std::vector<LabelSet>{{0, 1, 2, 3, 5, 1000}, {1}}));
  EXPECT_EQ(out.label_sets.size(), 2u);
  EXPECT_EQ(out.source, (std::vector<std::int64_t>{100, 101}));
  EXPECT_EQ(stats.removed_duplicate, 4u);
  EXPECT_EQ(stats.removed_degenerate, 0u);
}

TEST(Preprocess, KeepsAnyNumberOfLabelsAndSharesEqualLabelSets) {
  std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}};
  std::vector<Tri> t;
  std::vector<LabelSet> sets;
  for (std::uint32_t i = 0; i < 200; ++i) {
    t.push_back(i % 2 ? Tri{2, 1, 0} : Tri{0, 1, 2});
    sets.push_back({199 - i});
  }
  t.push_back({0, 1, 3});  // ends with the same label set as the first triangle
  LabelSet all(200);
  for (std::uint32_t i = 0; i < 200; ++i) all[i] = i;
  sets.push_back(all);
  PreprocessStats stats;
  const TriangleSoup out = preprocess(make_soup(v, t, sets), {}, stats);
  EXPECT_EQ(labels_of(out), (std::vector<LabelSet>{all, all}));
  EXPECT_EQ(out.label_sets.size(), 1u);
  EXPECT_EQ(stats.removed_duplicate, 199u);
}

TEST(Preprocess, HandlesManyMoreUnreferencedVerticesThanTriangles) {
  std::vector<Vec3> v;
  std::mt19937 rng(7);
  for (int i = 0; i < 30000; ++i) v.push_back({double(rng() % 1000), double(rng() % 1000), 2000.0 + i});
  v.push_back({0, 0, 0});
  v.push_back({1, 0, 0});
  v.push_back({0, 1, 0});
  PreprocessStats stats;
  const TriangleSoup out = preprocess(make_soup(v, {{30000, 30001, 30002}}), {true}, stats);
  EXPECT_EQ(out.triangles, (std::vector<Tri>{{0, 1, 2}}));
  EXPECT_EQ(out.vertices, (std::vector<Vec3>{{0, 0, 0}, {512, 0, 0}, {0, 512, 0}}));
  EXPECT_EQ(stats.unreferenced_vertices, 30000u);
  EXPECT_EQ(stats.merged_vertices, 0u);
  EXPECT_EQ(stats.scale_exponent, 9);
}

// ---- naive reference on random grid soups --------------------------------------------

struct Reference {
  std::vector<Vec3> vertices;
  std::vector<Tri> triangles;
  std::vector<LabelSet> labels;
  std::vector<std::int64_t> source;
  std::size_t degenerate = 0, duplicate = 0, merged = 0;
};

// Coordinates are small integers: cross products are exact in long long.
bool collinear_on_grid(const Vec3& a, const Vec3& b, const Vec3& c) {
  const long long u[3] = {(long long)(b[0] - a[0]), (long long)(b[1] - a[1]), (long long)(b[2] - a[2])};
  const long long w[3] = {(long long)(c[0] - a[0]), (long long)(c[1] - a[1]), (long long)(c[2] - a[2])};
  return u[1] * w[2] - u[2] * w[1] == 0 && u[2] * w[0] - u[0] * w[2] == 0 && u[0] * w[1] - u[1] * w[0] == 0;
}

Reference naive_preprocess(const TriangleSoup& in) {
  Reference r;
  std::vector<Vec3> distinct;
  for (const Vec3& p : in.vertices)
    if (std::find(distinct.begin(), distinct.end(), p) == distinct.end()) distinct.push_back(p);
  r.merged = in.vertices.size() - distinct.size();
  std::vector<std::array<Vec3, 3>> kept;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const std::array<Vec3, 3> p = {in.vertices[in.triangles[t][0]], in.vertices[in.triangles[t][1]],
                                   in.vertices[in.triangles[t][2]]};
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2] || collinear_on_grid(p[0], p[1], p[2])) {
      ++r.degenerate;
      continue;
    }
    const LabelSet& labels = in.label_sets[in.label_set[t]];
    bool duplicate = false;
    for (std::size_t k = 0; k < kept.size() && !duplicate; ++k) {
      std::array<Vec3, 3> a = kept[k], b = p;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a == b) {
        duplicate = true;
        std::set<std::uint32_t> u(r.labels[k].begin(), r.labels[k].end());
        u.insert(labels.begin(), labels.end());
        r.labels[k].assign(u.begin(), u.end());
      }
    }
    if (duplicate) {
      ++r.duplicate;
      continue;
    }
    kept.push_back(p);
    r.labels.push_back(labels);
    r.source.push_back(in.source[t]);
  }
  for (const auto& p : kept) {
    Tri tri;
    for (int i = 0; i < 3; ++i) {
      auto it = std::find(r.vertices.begin(), r.vertices.end(), p[i]);
      if (it == r.vertices.end()) it = r.vertices.insert(r.vertices.end(), p[i]);
      tri[i] = static_cast<int>(it - r.vertices.begin());
    }
    r.triangles.push_back(tri);
  }
  return r;
}

TEST(Preprocess, AgreesWithANaiveReferenceOnRandomGridSoups) {
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 200; ++trial) {
    const int grid = 1 + trial % 4;  // coordinates in [-grid, grid]: many duplicates
    const int nv = 3 + static_cast<int>(rng() % 40), nf = 1 + static_cast<int>(rng() % 60);
    std::vector<Vec3> v;
    for (int i = 0; i < nv; ++i) {
      Vec3 p;
      for (double& c : p) c = static_cast<double>(static_cast<int>(rng() % (2 * grid + 1)) - grid);
      if (rng() % 5 == 0) p[0] = -p[0] * 0.0;  // sometimes -0.0
      v.push_back(p);
    }
    std::vector<Tri> t;
    std::vector<LabelSet> sets;
    for (int f = 0; f < nf; ++f) {
      t.push_back({static_cast<int>(rng() % nv), static_cast<int>(rng() % nv), static_cast<int>(rng() % nv)});
      LabelSet s;
      for (std::uint32_t l = 0; l < 40; ++l)
        if (rng() % 8 == 0) s.push_back(l);
      sets.push_back(s);
    }
    const TriangleSoup in = make_soup(v, t, sets);
    Reference ref = naive_preprocess(in);
    for (Vec3& p : ref.vertices)
      for (double& c : p) c += 0.0;  // the output writes -0.0 as +0.0
    PreprocessStats stats;
    const TriangleSoup out = preprocess(in, {}, stats);
    ASSERT_EQ(out.vertices, ref.vertices) << trial;
    ASSERT_EQ(out.triangles, ref.triangles) << trial;
    ASSERT_EQ(labels_of(out), ref.labels) << trial;
    ASSERT_EQ(out.source, ref.source) << trial;
    ASSERT_EQ(stats.removed_degenerate, ref.degenerate) << trial;
    ASSERT_EQ(stats.removed_duplicate, ref.duplicate) << trial;
    ASSERT_EQ(stats.merged_vertices, ref.merged) << trial;
    ASSERT_EQ(stats.unreferenced_vertices, in.vertices.size() - ref.merged - ref.vertices.size()) << trial;
    std::set<LabelSet> distinct(out.label_sets.begin(), out.label_sets.end());
    ASSERT_EQ(distinct.size(), out.label_sets.size()) << "label sets are stored once";
  }
}

// ---- scaling ------------------------------------------------------------------------------

// One triangle (0,0,0), (m,0,0), (0,m/2,0) with max |coordinate| m.
TriangleSoup triangle_of_size(double m) { return make_soup({{0, 0, 0}, {m, 0, 0}, {0, m / 2, -m / 4}}, {{0, 1, 2}}); }

TEST(Preprocess, ScalingPutsTheLargestCoordinateInTwoToTheNineToTen) {
  struct Case {
    double m;
    int k;  // by hand: m = f 2^e, f in [1/2, 1), k = 10 - e
  };
  const Case cases[] = {
      {0.3, 11},                                              // 0.3 = 0.6 * 2^-1
      {3.0, 8},                                               // the upstream shift overflowed below ~5
      {4.9, 7},                                               // 0.6125 * 2^3
      {1000.0, 0},                                            // already in [512, 1024)
      {1024.0, -1},                                           // 0.5 * 2^11
      {512.0, 0},                                             // 0.5 * 2^10: already in range
      {1e-300, 1006},                                         // 1e-300 = 0.6696... * 2^-996
      {1e300, -987},                                          // 1e300 = 0.7466... * 2^997
      {std::numeric_limits<double>::denorm_min() * 4, 1081},  // 2^-1072 = 0.5 * 2^-1071
  };
  for (const Case& c : cases) {
    PreprocessStats stats;
    const TriangleSoup out = preprocess(triangle_of_size(c.m), {true}, stats);
    EXPECT_EQ(stats.scale_exponent, c.k) << c.m;
    ASSERT_EQ(out.vertices.size(), 3u);
    const double scaled = out.vertices[1][0];
    EXPECT_EQ(scaled, std::ldexp(c.m, c.k)) << c.m;
    EXPECT_TRUE(scaled >= 512 && scaled < 1024) << c.m << " -> " << scaled;
    EXPECT_EQ(out.vertices[2][1], std::ldexp(c.m / 2, c.k)) << c.m;
    EXPECT_EQ(out.vertices[2][2], std::ldexp(-c.m / 4, c.k)) << c.m;
  }
}

TEST(Preprocess, ScalesTheSmallestSubnormalTriangleExactly) {
  const double tiny = std::numeric_limits<double>::denorm_min();  // 2^-1074
  PreprocessStats stats;
  const TriangleSoup out = preprocess(make_soup({{0, 0, 0}, {tiny, 0, 0}, {0, tiny, 0}}, {{0, 1, 2}}), {true}, stats);
  EXPECT_EQ(stats.removed_degenerate, 0u) << "orient2d is exact on subnormals";
  EXPECT_EQ(stats.scale_exponent, 1083);
  EXPECT_EQ(out.vertices, (std::vector<Vec3>{{0, 0, 0}, {512, 0, 0}, {0, 512, 0}}));
}

TEST(Preprocess, LeavesTheModelUnscaledWhenScalingWouldRoundACoordinate) {
  // k = -987 (largest 1e300): 3 * 2^-40 becomes 3 * 2^-1027, still exact (subnormal);
  // (1 + 2^-52) * 2^-40 would need bits down to 2^-1079: rounded, refused.
  const TriangleSoup fine = make_soup({{1e300, 0, 0}, {0, 3 * std::ldexp(1.0, -40), 0}, {0, 0, 1}}, {{0, 1, 2}});
  PreprocessStats stats;
  EXPECT_EQ(preprocess(fine, {true}, stats).vertices[1][1], 3 * std::ldexp(1.0, -1027));
  const double fine_grained = std::ldexp(std::nextafter(1.0, 2.0), -40);
  const TriangleSoup rounding = make_soup({{1e300, 0, 0}, {0, fine_grained, 0}, {0, 0, 1}}, {{0, 1, 2}});
  EXPECT_EQ(preprocess(rounding, {true}, stats).vertices[1][1], fine_grained);  // valid input, never refused
  EXPECT_EQ(stats.scale_exponent, 0);
  const TriangleSoup underflow = make_soup({{1e300, 0, 0}, {0, 1e-300, 0}, {0, 0, 1}}, {{0, 1, 2}});
  EXPECT_EQ(preprocess(underflow, {true}, stats).vertices[1][1], 1e-300);
  EXPECT_EQ(stats.scale_exponent, 0);
  EXPECT_EQ(preprocess(rounding, {false}, stats).vertices[1][1], fine_grained);
  EXPECT_EQ(stats.scale_exponent, 0);
}

TEST(Preprocess, ScalingChangesNothingButTheCoordinates) {
  std::mt19937 rng(99);
  std::vector<Vec3> v;
  for (int i = 0; i < 60; ++i)
    v.push_back({double(rng() % 5) * 0.125, double(rng() % 5) * 0.125, double(rng() % 3) * 0.125});
  v.push_back({0, 0, 0});
  v.push_back({0.5, 0, 0});  // the largest coordinate: 0.5 = 0.5 * 2^0, so k = 10
  v.push_back({0, 0.125, 0});
  std::vector<Tri> t = {{60, 61, 62}};
  for (int f = 0; f < 80; ++f) t.push_back({int(rng() % 60), int(rng() % 60), int(rng() % 60)});
  const TriangleSoup in = make_soup(v, t);
  PreprocessStats plain_stats, scaled_stats;
  const TriangleSoup plain = preprocess(in, {false}, plain_stats);
  const TriangleSoup scaled = preprocess(in, {true}, scaled_stats);
  EXPECT_EQ(scaled_stats.scale_exponent, 10);
  EXPECT_EQ(plain_stats.scale_exponent, 0);
  EXPECT_EQ(plain.triangles, scaled.triangles);
  EXPECT_EQ(plain.label_set, scaled.label_set);
  EXPECT_EQ(plain.source, scaled.source);
  ASSERT_EQ(plain.vertices.size(), scaled.vertices.size());
  for (std::size_t i = 0; i < plain.vertices.size(); ++i)
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(scaled.vertices[i][a], std::ldexp(plain.vertices[i][a], scaled_stats.scale_exponent));
}

// The pipeline checks a soup once, at arrange(): validate_soup (the stages assume it).
TEST(ValidateSoup, RefusesIllFormedSoupsWithInvalidArgument) {
  std::vector<TriangleSoup> bad;
  bad.push_back(make_soup({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}));
  bad.push_back(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, -1}}));
  bad.push_back(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  bad.back().label_set[0] = 3;
  bad.push_back(make_soup({{0, 0, 0}, {1, NAN, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  bad.push_back(make_soup({{0, 0, 0}, {1, INFINITY, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  bad.push_back(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  bad.back().source.clear();
  bad.push_back(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  bad.back().polygon = {0, 0};
  for (std::size_t i = 0; i < bad.size(); ++i) {
    EXPECT_THROW(arrangements::validate_soup(bad[i]), std::invalid_argument) << i;
    EXPECT_THROW(arrangements::arrange(bad[i], arrangements::ArrangeOptions{}), std::invalid_argument) << i;
  }
  EXPECT_NO_THROW(arrangements::validate_soup(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}})));
}

}  // namespace
