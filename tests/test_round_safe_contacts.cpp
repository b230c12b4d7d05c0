// Safe rounding of contacts that transforms rounded to doubles broke (issue 14,
// arrangements/round_mesh.h): an edge or a vertex of one part lay exactly on a face of another
// (Cherchi's sc2: an edge of B in A's plane); turned in doubles, it lies 1e-17 off that plane,
// and the exact arrangement cuts slivers 1e-17 wide that no rounding holds. Given the input,
// round_safe's contacts step (snap_near_coplanar_faces with contacts, round_snapped_planes.h)
// moves the touching corners back onto the touched planes (exact rationals). Tested on its
// own (the corner lands exactly on the plane, within the reported move; a corner near the
// plane far from the triangle stays; a corner at the position of another's corner touches
// none of its triangles) and on generated inputs (turned copies of sc2, an apex
// on a box's face turned as one body), with every check of support/safe_rounding_checks.h.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/round_mesh.h"
#include "rounding/round_snapped_planes.h"
#include "support/bounding_box.h"
#include "support/exact_oracle.h"
#include "support/mesh_generators.h"
#include "support/random_turns.h"
#include "support/safe_rounding_checks.h"

namespace {

using namespace arrangements;
using tritri_test::rounding::expect_safe_rounding;
using Q = CGAL::Gmpq;
using tritri_test::unit_axis;

// Cherchi's sc2 (cherchi_arrangements/sc2.off, its vertex and triangle order): A =
// (0,0,0), (1,0,0), (1,1,0) and B = (1.2,0.5,0), (0,0,0), (1,1,1), whose edge from (0,0,0)
// to (1.2,0.5,0) lies in A's plane, partly outside A. The file gives (0,0,0) twice, once per
// triangle; `shared`: once, a corner of both.
TriangleSoup sc2(bool shared) {
  TriangleSoup s;
  s.vertices = {{1.2, 0.5, 0}, {0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  s.triangles = {{3, 4, 5}, {0, 1, 2}};
  if (shared) {
    s.vertices.erase(s.vertices.begin() + 1);
    s.triangles = {{2, 3, 4}, {0, 2, 1}};
  }
  s.label_set = {0, 0};
  s.label_sets = {{0}};
  s.source = {0, 1};
  return s;
}

Vec3 box_centre(const TriangleSoup& s) { return bounding_box(s.vertices).centre(); }

// `soup` and copies turned by 2 pi i / k about `axis` through its box centre (the copy at 0
// untouched), copy i labelled {i}: bench/round_safe_sweep.py's rot3 for k = 3, with `turned`.
TriangleSoup turned_copies(const TriangleSoup& soup, const Vec3& axis, int k) {
  std::vector<TriangleSoup> parts{soup};
  for (int i = 1; i < k; ++i)
    parts.push_back(turned(soup, box_centre(soup), axis, 2 * std::numbers::pi * i / k, {0, 0, 0}));
  return concatenate(parts);
}

// Figures of a family of cases: how many rounding to nearest did not settle, how many of
// those the input was snapped for (plain or contacts), the largest move / diagonal.
struct Tally {
  int cases = 0, not_nearest = 0, snapped = 0;
  double max_move_relative = 0;
  void add(const TriangleSoup& soup, const std::string& name) {
    ++cases;
    const ArrangeResult first = arrange(soup, ArrangeOptions{});
    bool nearest_ok = true;
    RoundReport report;
    try {
      report = expect_safe_rounding(first.mesh, name, nearest_ok, &soup);
    } catch (const RoundingError& error) {
      ADD_FAILURE() << name << ": refused: " << error.what();
      return;
    }
    EXPECT_LE(report.max_move_relative, 1e-14) << name;
    not_nearest += !nearest_ok;
    snapped += !nearest_ok && report.snapped_vertices > 0;
    max_move_relative = std::max(max_move_relative, report.max_move_relative);
  }
  void print(const char* name) const {
    std::printf("%s: %d cases, %d not settled by rounding to nearest, %d of those snapped, largest move %.3g\n", name,
                cases, not_nearest, snapped, max_move_relative);
  }
};

TEST(RoundSafeContacts, TurnedCopiesOfAnEdgeOnAFaceSettleBySnappingContacts) {
  // The sweep's rot3 of sc2 (seed 1) as it writes it: its rotation sums the terms in another
  // order than `turned`, which gives other last bits (with turned's, the passes alone settle
  // it), and these are the ones that were refused. The unit axis is unit_vector(1, "rot3").
  const Vec3 axis{-0.24647932653624932, 0.7223249341106984, 0.6461382446134978};
  TriangleSoup rot3 = turned_copies(sc2(false), axis, 3);
  // Copy 0 is sc2 itself, untouched; copies 1 and 2:
  const std::vector<Vec3> sweep = {
      {0.16134577074163092, 0.21873893067606143, -0.08178576644371499},
      {1.0653067551750028, -0.2735939192429226, 0.7122311751342969},
      {0.21646762730206814, 1.2150909413945117, 0.46065708922555476},
      {1.0653067551750028, -0.2735939192429226, 0.7122311751342969},
      {0.6564348427896476, 0.018920969999131898, -0.15221014666496255},
      {-0.17019453635224369, 0.3015509356561692, 0.3344151424972362},
      {0.7868975134684162, -0.2392902720662342, 0.6688763248284277},
      {1.1312863637098163, 0.6113500000755165, -0.2518882744259173},
      {0.15048801876725493, 0.5539758757528617, 1.1745558416950552},
      {1.1312863637098163, 0.6113500000755165, -0.2518882744259173},
      {0.7224144513244602, -0.21527937906637457, 0.13477388922839417},
      {1.0149293405665145, 0.06735058659066256, 1.048313894966737}};
  ASSERT_EQ(rot3.vertices.size(), 6 + sweep.size());
  for (std::size_t v = 0; v < sweep.size(); ++v)
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(rot3.vertices[6 + v][k], sweep[v][k], 1e-15) << v;  // the same rotation
  std::copy(sweep.begin(), sweep.end(), rot3.vertices.begin() + 6);
  {
    const ArrangeResult first = arrange(rot3, ArrangeOptions{});
    ASSERT_GT(first.stats.intersecting_pairs, 0u);
    // From the arrangement alone, only nudging (the last resort) holds the slivers 1e-17
    // wide along B's edge: a few vertices moved by ulps, the edge still 1e-17 off the face.
    bool nearest_ok = true;
    const RoundReport alone = expect_safe_rounding(first.mesh, "sc2 rot3 alone", nearest_ok);
    EXPECT_GT(alone.nudged, 0u);
    EXPECT_LE(alone.max_move_relative, 1e-13);
    std::printf("sc2 rot3 (sweep), the arrangement alone: %d passes, %zu vertices nudged, largest move / diagonal "
                "%.3g\n",
                alone.passes, alone.nudged, alone.max_move_relative);
    const RoundReport report = expect_safe_rounding(first.mesh, "sc2 rot3", nearest_ok, &rot3);
    EXPECT_FALSE(nearest_ok);
    EXPECT_GT(report.snapped_vertices, 0u);
    EXPECT_LE(report.max_move_relative, 1e-14);
    std::printf("sc2 rot3 (sweep): %d passes, %zu input vertices snapped, largest move / diagonal %.3g\n",
                report.passes, report.snapped_vertices, report.max_move_relative);
  }
  // The class: three copies about other axes, each putting B's edge an ulp or so off the
  // turned A's plane (or on it, where the errors cancel), as in the file (a duplicate
  // (0,0,0)) and with (0,0,0) shared.
  std::mt19937 rng(20240614);
  Tally file, shared;
  for (int i = 0; i < 40; ++i) {
    const Vec3 a = unit_axis(rng);
    const std::string name = "sc2 turned copies " + std::to_string(i);
    for (bool is_shared : {false, true}) {
      const TriangleSoup soup = turned_copies(sc2(is_shared), a, 3);
      (is_shared ? shared : file).add(soup, name + (is_shared ? " shared" : ""));
    }
  }
  file.print("sc2 turned copies");
  shared.print("sc2 turned copies, (0,0,0) shared");
  EXPECT_GT(file.not_nearest, 0);
  EXPECT_GT(shared.not_nearest, 0);
  EXPECT_GT(shared.snapped, 0);  // the contacts step, not only the passes and rerouting
}

TEST(RoundSafeContacts, ContactsAreMadeExact) {
  // T: the plane z = x / 2 + y / 4 (normal (-1/2, -1/4, 1)), every coordinate below a
  // double. Each other triangle has one or two corners 2^-50 or 2^-51 off T's plane
  // (vertically), its other corners far from it.
  const double e = std::ldexp(1.0, -50), delta = std::ldexp(1.0, -46);
  TriangleSoup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0.5}, {0, 1, 0.25},                           // 0-2: T
                {0.25, 0.25, 0.1875 + e}, {0.25, 0.25, 1}, {0.5, 0.25, 1},         // 3-5: U, apex 3 in T's box
                {1.5, 0.5, 0.875 + e}, {0.5, 0.25, 0.3125 - e / 2}, {0.5, 0.5, 3},  // 6-8: X, edge 6-7 on T
                {3, 3, 2.25 + e}, {0.2, 0.2, -1}, {0.3, 0.1, -1}};                  // 9-11: W, 9 outside T's box
  s.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  s.label_set = {0, 0, 0, 0};
  s.label_sets = {{0}};
  s.source = {0, 1, 2, 3};
  const ExactTriangleSoup original = to_exact(s);
  // The exact side of T's plane: 0 on it.
  const auto off_plane = [&](const ExactVec3& p) {
    using tritri_test::exact;
    return tritri_test::orient3d(exact(original.vertices[0]), exact(original.vertices[1]),
                                 exact(original.vertices[2]), exact(p));
  };
  for (int v : {3, 6, 7, 9}) ASSERT_NE(off_plane(original.vertices[v]), 0) << v;

  // Without contacts nothing moves: no two triangles lie within delta of each other's planes.
  EXPECT_EQ(snap_near_coplanar_faces(s, delta, 0, false).moved, 0u);

  // With contacts: U's apex (in T's box) and both ends of X's edge (6 lies outside T's box,
  // on an edge whose other end is near the plane too) land exactly on T's plane; W's corner
  // 9 is near the plane only far from T (its box overlaps T's, the corner is outside) and
  // stays, and T, touched, is flat already.
  const SnappedPlanes snapped = snap_near_coplanar_faces(s, delta, 0, true);
  EXPECT_EQ(snapped.moved, 3u);
  EXPECT_LE(snapped.max_move, 64 * std::sqrt(3.0) * delta);
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    const ExactVec3& p = snapped.soup.vertices[v];
    const bool touching = v == 3 || v == 6 || v == 7;
    EXPECT_EQ(p != original.vertices[v], touching) << v;
    if (!touching) continue;
    EXPECT_EQ(off_plane(p), 0) << v;  // exactly on T's plane
    Q d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (p[k] - original.vertices[v][k]) * (p[k] - original.vertices[v][k]);
    EXPECT_LE(d2, Q(snapped.max_move) * Q(snapped.max_move)) << v;
    EXPECT_GT(d2, 0) << v;
  }
  EXPECT_EQ(snapped.soup.triangles, s.triangles);
  EXPECT_EQ(snapped.soup.source, s.source);
}

TEST(RoundSafeContacts, CornersAtOnePositionDoNotTouch) {
  // L1 and L2 overlap in z = 0 (one layered group, L2's plane: L2 is larger), except L1's
  // corner v = (0.5, 0.5, e), an e = 2^-50 above. A fan of three triangles with distinct planes
  // has its apex w at v's position (another index, as files give it), the rest far above. v
  // lies on every fan plane but touches none: a corner at the position of one of the other's
  // corners only meets it there. So v has one plane and lands on z = 0, where w, touching L2,
  // lands too. (Counted as touches, v had four planes and stayed, and w moved: a crack.)
  const double e = std::ldexp(1.0, -50), delta = std::ldexp(1.0, -46);
  TriangleSoup s;
  s.vertices = {{0.5, 0.5, e}, {0.9, 0.2, 0}, {0.2, 0.9, 0},  // 0-2: L1, corner 0 is v
                {0, 0, 0}, {1.5, 0.1, 0}, {0.1, 1.5, 0},    // 3-5: L2
                {0.5, 0.5, e},                              // 6: w
                {0.2, 0.3, 1}, {0.9, 0.4, 1.5}, {0.4, 1.1, 2}};
  s.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {6, 8, 9}, {6, 9, 7}};
  s.label_set = {0, 0, 0, 0, 0};
  s.label_sets = {{0}};
  s.source = {0, 1, 2, 3, 4};
  const SnappedPlanes snapped = snap_near_coplanar_faces(s, delta, 0, true);
  const ExactVec3 on_floor = to_exact(Vec3{0.5, 0.5, 0});
  EXPECT_EQ(snapped.soup.vertices[0], on_floor);
  EXPECT_EQ(snapped.soup.vertices[6], on_floor);
  for (int v = 1; v < 10; ++v) {
    if (v == 6) continue;
    EXPECT_EQ(snapped.soup.vertices[v], to_exact(s.vertices[v])) << v;
  }
}

// A unit box and a tetrahedron above it whose apex touches the box's top face: at (0.5, 0.5,
// 1), on the diagonal that splits the face, or at (u, v, 1) inside one of its triangles.
TriangleSoup apex_on_box(double u, double v) {
  TriangleSoup tetra;
  tetra.vertices = {{u, v, 1}, {0.2, 0.2, 1.6}, {0.8, 0.3, 1.6}, {0.5, 0.8, 1.6}};
  tetra.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}};
  tetra.label_set = {0, 0, 0, 0};
  tetra.label_sets = {{0}};
  tetra.source = {0, 1, 2, 3};
  return concatenate({box({0, 0, 0}, {1, 1, 1}), tetra});
}

TEST(RoundSafeContacts, ApexOnAFaceTurned) {
  // Turned as one body in doubles, the apex lies an ulp or so above or below the turned
  // face: below, the exact arrangement cuts the face around a point 1e-17 deep. With a
  // second body (moved, turned about another axis), real crossings too. Measured: the passes
  // and rerouting settle these (a pierced point, not slivers along a whole edge).
  std::mt19937 rng(7);
  Tally alone, pairs;
  for (int i = 0; i < 24; ++i) {
    const TriangleSoup body = i % 2 == 0 ? apex_on_box(0.5, 0.5) : apex_on_box(0.375 + 0.0625 * (i % 3), 0.625);
    const Vec3 axis = unit_axis(rng);
    const double angle = tritri_test::turn_angle(rng);
    const TriangleSoup one = turned(body, box_centre(body), axis, angle, {0, 0, 0});
    alone.add(one, "apex on a face " + std::to_string(i));
    if (i % 2 == 1) {
      const TriangleSoup other = turned(body, box_centre(body), unit_axis(rng), angle / 2, {0.3, 0.2, 0.1});
      pairs.add(concatenate({one, other}), "two apexes on faces " + std::to_string(i));
    }
  }
  alone.print("apex on a face, one body");
  pairs.print("apex on a face, two bodies");
  EXPECT_GT(alone.not_nearest, 0);  // some apexes pierce their face
  EXPECT_GT(pairs.not_nearest, 0);
}

}  // namespace
