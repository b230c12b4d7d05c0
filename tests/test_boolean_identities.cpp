// Exact Booleans (arrangements/boolean.h) on generated solids: the exact volumes of the
// results against values known by hand and against the inclusion-exclusion identities,
// in rationals; every output closed and consistently oriented, each triangle inside its
// source triangle; coplanar contacts (faces,
// edges, corners shared), identical, nested and self-intersecting operands; the exact
// path; 1 and 2 threads byte-identical; an open operand refused.
#include <gtest/gtest.h>

#include "arrangements/boolean.h"
#include "support/boolean_checks.h"
#include "support/exact_soups.h"
#include "support/mesh_generators.h"

namespace {

using namespace arrangements;
using tritri_test::Q;
using tritri_test::unbalanced_edges;
using tritri_test::volume;

ArrangeOptions threads(int n) {
  ArrangeOptions o;
  o.threads = n;
  return o;
}

// The result of op on (a, b), checked closed; its exact volume.
Q boolean_volume(const TriangleSoup& a, const TriangleSoup& b, BooleanOp op, int n_threads = 2) {
  const TriangleSoup both = concatenate(a, b);
  const ArrangeResult r = boolean(both, operation_tree(op, 2), threads(n_threads));
  EXPECT_EQ(unbalanced_edges(r.mesh), 0u);
  EXPECT_EQ(tritri_test::outside_source(r.mesh, both), 0u);
  return volume(r.mesh);
}

struct Volumes {
  Q a, b, uni, inter, diff, sym;
};

Volumes all_volumes(const TriangleSoup& a, const TriangleSoup& b) {
  Volumes v;
  v.a = volume(a);
  v.b = volume(b);
  v.uni = boolean_volume(a, b, BooleanOp::Union);
  v.inter = boolean_volume(a, b, BooleanOp::Intersection);
  v.diff = boolean_volume(a, b, BooleanOp::Difference);
  v.sym = boolean_volume(a, b, BooleanOp::Xor);
  return v;
}

void expect_identities(const Volumes& v) {
  EXPECT_EQ(v.uni + v.inter, v.a + v.b);
  EXPECT_EQ(v.diff + v.inter, v.a);
  EXPECT_EQ(v.sym, v.uni - v.inter);
  EXPECT_GE(v.inter, 0);
}

TEST(BooleanIdentities, CrossingCubesByHand) {
  const Volumes v = all_volumes(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}));
  EXPECT_EQ(v.a, 8);
  EXPECT_EQ(v.uni, 15);
  EXPECT_EQ(v.inter, 1);
  EXPECT_EQ(v.diff, 7);
  EXPECT_EQ(v.sym, 14);
  expect_identities(v);
}

TEST(BooleanIdentities, BoxesSharingAFaceUniteWithoutInnerFace) {
  const TriangleSoup a = box({0, 0, 0}, {1, 1, 1}), b = box({1, 0, 0}, {2, 1, 1});
  const ArrangeResult u = boolean(concatenate(a, b), operation_tree(BooleanOp::Union, 2), threads(2));
  EXPECT_EQ(volume(u.mesh), 2);
  EXPECT_EQ(unbalanced_edges(u.mesh), 0u);
  for (const Tri& t : u.mesh.triangles) {
    bool all_on_shared_plane = true;
    for (int v : t) all_on_shared_plane &= tritri::to_double(u.mesh.vertices[v])[0] == 1.0;
    EXPECT_FALSE(all_on_shared_plane) << "a triangle of the shared face is left inside the union";
  }
  const Volumes v = all_volumes(a, b);
  EXPECT_EQ(v.inter, 0);
  EXPECT_EQ(v.diff, 1);
  EXPECT_EQ(v.sym, 2);
  expect_identities(v);
}

TEST(BooleanIdentities, BoxesSharingAnEdgeOrACorner) {
  for (const Vec3 lo : {Vec3{1, 1, 0}, Vec3{1, 1, 1}, Vec3{1, 0.5, 0.25}}) {
    const Volumes v = all_volumes(box({0, 0, 0}, {1, 1, 1}), box(lo, {lo[0] + 1, lo[1] + 1, lo[2] + 1}));
    EXPECT_EQ(v.inter, 0) << lo[0] << " " << lo[1] << " " << lo[2];
    EXPECT_EQ(v.uni, 2);
    expect_identities(v);
  }
}

TEST(BooleanIdentities, IdenticalOperands) {
  const TriangleSoup a = uv_sphere({0, 0, 0}, 1, 8, 12);
  const Volumes v = all_volumes(a, a);
  EXPECT_GT(v.a, 0);
  EXPECT_EQ(v.uni, v.a);
  EXPECT_EQ(v.inter, v.a);
  EXPECT_EQ(v.diff, 0);
  EXPECT_EQ(v.sym, 0);
  const ArrangeResult d = boolean(concatenate(a, a), operation_tree(BooleanOp::Difference, 2), threads(2));
  EXPECT_TRUE(d.mesh.triangles.empty());
}

TEST(BooleanIdentities, NestedOperands) {
  const TriangleSoup outer = box({0, 0, 0}, {3, 3, 3}), inner = box({1, 1, 1}, {2, 2, 2});
  const Volumes v = all_volumes(outer, inner);
  EXPECT_EQ(v.uni, 27);
  EXPECT_EQ(v.inter, 1);
  EXPECT_EQ(v.diff, 26);
  expect_identities(v);
  EXPECT_EQ(boolean_volume(inner, outer, BooleanOp::Difference), 0);
  // a cavity: both shells are kept
  const ArrangeResult d = boolean(concatenate(outer, inner), operation_tree(BooleanOp::Difference, 2), threads(2));
  EXPECT_EQ(d.mesh.triangles.size(), 24u);
}

TEST(BooleanIdentities, SelfIntersectingOperand) {
  // One operand made of two overlapping cubes (winding number 2 where they overlap): its
  // solid is where the winding number is not 0, 15 units.
  TriangleSoup twice = concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}));
  twice.label_set.assign(twice.triangles.size(), 0);
  twice.label_sets = {{0}};
  const ArrangeResult alone = boolean(twice, operation_tree(BooleanOp::Union, 1), threads(2));
  EXPECT_EQ(volume(alone.mesh), 15);
  EXPECT_EQ(unbalanced_edges(alone.mesh), 0u);
  const Volumes v = all_volumes(twice, box({2, 2, 2}, {4, 4, 4}));
  EXPECT_EQ(v.inter, 1);
  EXPECT_EQ(v.uni, 15 + 8 - 1);
}

TEST(BooleanIdentities, RotatedCopiesAndSpheres) {
  const TriangleSoup a = uv_sphere({0, 0, 0}, 1, 10, 14);
  const TriangleSoup b = turned(a, {0, 0, 0}, {0.6, 0.8, 0}, 0.3, {0.4, 0.1, -0.2});
  const Volumes v = all_volumes(a, b);
  EXPECT_GT(v.inter, 0);
  EXPECT_LT(v.inter, v.a);
  expect_identities(v);
  const Volumes w = all_volumes(box({-0.5, -0.5, -0.5}, {0.5, 0.5, 2}), a);
  expect_identities(w);
}

TEST(BooleanIdentities, TouchingAtTheExtremeCorner) {
  // The first cube's largest corner (1, 1, 1) is the second's smallest: the cell just
  // beyond it along +x lies inside the second cube, the first cube's outside does not.
  const Volumes v = all_volumes(box({0, 0, 0}, {1, 1, 1}), box({1, 1, 1}, {2, 2, 2}));
  EXPECT_EQ(v.uni, 2);
  EXPECT_EQ(v.diff, 1);
  const Volumes w = all_volumes(box({1, 1, 1}, {2, 2, 2}), box({0, 0, 0}, {1, 1, 1}));
  EXPECT_EQ(w.uni, 2);
  EXPECT_EQ(w.diff, 1);
}

TEST(BooleanIdentities, ExactPathAgrees) {
  const TriangleSoup a = box({0, 0, 0}, {2, 2, 2}), b = uv_sphere({1.5, 1.2, 1.1}, 1, 6, 8);
  const TriangleSoup both = concatenate(a, b);
  const ExactTriangleSoup exact = tritri_test::with_vertices<ExactVec3>(
      both, [](const Vec3& p) { return ExactVec3{Q(p[0]), Q(p[1]), Q(p[2])}; });
  for (BooleanOp op : {BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference}) {
    const ArrangeResult d = boolean(both, operation_tree(op, 2), threads(2));
    const ExactArrangeResult e = boolean(exact, operation_tree(op, 2), threads(2));
    EXPECT_EQ(volume(d.mesh), volume(e.mesh));
    EXPECT_EQ(d.mesh.triangles.size(), e.mesh.triangles.size());
    EXPECT_EQ(unbalanced_edges(e.mesh), 0u);
  }
}

TEST(BooleanIdentities, OneAndTwoThreadsIdentical) {
  const TriangleSoup a = uv_sphere({0, 0, 0}, 1, 10, 14);
  const TriangleSoup both = concatenate(a, turned(a, {0, 0, 0}, {0, 0.6, 0.8}, 0.7, {0.3, 0, 0}));
  const ArrangeResult one = boolean(both, operation_tree(BooleanOp::Union, 2), threads(1));
  const ArrangeResult two = boolean(both, operation_tree(BooleanOp::Union, 2), threads(2));
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
  EXPECT_EQ(one.mesh.source, two.mesh.source);
  EXPECT_EQ(tritri_test::exact_vertices(one.mesh), tritri_test::exact_vertices(two.mesh));
}

TEST(BooleanIdentities, OpenOperandRefused) {
  TriangleSoup open = box({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  open.source.pop_back();
  open.label_set.pop_back();
  try {
    boolean(concatenate(box({0.5, 0.5, 0.5}, {2, 2, 2}), open), operation_tree(BooleanOp::Union, 2), threads(2));
    FAIL() << "an open operand was accepted";
  } catch (const OpenOperandError& e) {
    EXPECT_EQ(e.operand, 1);
    EXPECT_GE(e.open_edges, 3u);
    EXPECT_NE(std::string(e.what()).find("operand 1 is not closed"), std::string::npos) << e.what();
  }
}

TEST(BooleanIdentities, InvertedOperandIsStillASolid) {
  // Turned inside out, an operand's winding number is -1 inside: still inside.
  TriangleSoup inverted = box({1, 1, 1}, {3, 3, 3});
  for (Tri& t : inverted.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(volume(inverted), -8);
  EXPECT_EQ(boolean_volume(box({0, 0, 0}, {2, 2, 2}), inverted, BooleanOp::Union), 15);
}

}  // namespace
