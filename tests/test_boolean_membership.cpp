// Boolean membership: at thousands of random points per scene, the winding number of the
// Boolean's output (an independent exact ray cast in rationals: tests/support/
// boolean_checks.h) is 1 where the operation of the operands' memberships (winding
// number not 0, by the same independent ray cast on the input) says inside, 0 elsewhere.
// Scenes: crossing spheres (one turned), a box through a sphere, a self-intersecting
// operand, nested boxes (a cavity), three operands in a CSG tree, the exact path.
#include <gtest/gtest.h>

#include <random>

#include "arrangements/boolean.h"
#include "support/boolean_checks.h"
#include "support/exact_soups.h"
#include "support/mesh_generators.h"
#include "support/test_scale.h"

namespace {

using namespace arrangements;
using tritri_test::kAllLabels;
using tritri_test::Q;
using tritri_test::Q3;
using tritri_test::RayWinding;

// Evaluates the tree on per-operand memberships (written independently of csg_select).
bool member(const CsgNode& n, const std::vector<bool>& in) {
  if (n.operand >= 0) return in[n.operand];
  int count = 0;
  for (const CsgNode& c : n.children) count += member(c, in);
  const int k = static_cast<int>(n.children.size());
  switch (n.op) {
    case BooleanOp::Union: return count > 0;
    case BooleanOp::Intersection: return count == k;
    case BooleanOp::Difference: {
      if (!member(n.children[0], in)) return false;
      return count == 1;
    }
    case BooleanOp::Xor: return count % 2 == 1;
  }
  return false;
}

template <class Soup, class Mesh>
void expect_membership(const Soup& input, int operands, const CsgNode& tree, const Mesh& output, int points,
                       std::uint64_t seed) {
  std::vector<Q3> v = tritri_test::exact_vertices(input);
  Q3 lo = v[0], hi = v[0];
  for (const Q3& p : v)
    for (int k = 0; k < 3; ++k) {
      if (p[k] < lo[k]) lo[k] = p[k];
      if (p[k] > hi[k]) hi[k] = p[k];
    }
  std::vector<RayWinding> operand;
  for (int o = 0; o < operands; ++o) operand.emplace_back(input, static_cast<std::uint32_t>(o));
  const RayWinding result(output, kAllLabels);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> step(-64, 1024 + 64);
  int tested = 0, inside = 0;
  for (int i = 0; i < points; ++i) {
    Q3 p;
    for (int k = 0; k < 3; ++k) p[k] = lo[k] + (hi[k] - lo[k]) * Q(step(rng), 1024);
    std::vector<bool> in(operands);
    bool degenerate = false;
    for (int o = 0; o < operands && !degenerate; ++o) {
      const auto w = operand[o].at(p);
      degenerate = !w;
      if (w) in[o] = *w != 0;
    }
    const auto out = result.at(p);
    if (degenerate || !out) continue;
    ++tested;
    const bool expected = member(tree, in);
    inside += expected;
    ASSERT_EQ(*out, expected ? 1 : 0) << "point " << p[0] << " " << p[1] << " " << p[2];
  }
  EXPECT_GT(tested, points / 2);
  EXPECT_GT(inside, 0);
}

int points() { return static_cast<int>(tritri_test::scaled_count(1500)); }

ArrangeOptions two_threads() {
  ArrangeOptions o;
  o.threads = 2;
  return o;
}

const BooleanOp kOps[] = {BooleanOp::Union, BooleanOp::Intersection, BooleanOp::Difference, BooleanOp::Xor};

TEST(BooleanMembership, TurnedSpheres) {
  const TriangleSoup a = uv_sphere({0, 0, 0}, 1, 8, 10);
  const TriangleSoup both = concatenate(a, turned(a, {0, 0, 0}, {0.6, 0, 0.8}, 0.5, {0.5, 0.25, 0}));
  for (BooleanOp op : kOps) {
    const CsgNode tree = operation_tree(op, 2);
    expect_membership(both, 2, tree, boolean(both, tree, two_threads()).mesh, points(), 11 + static_cast<int>(op));
  }
}

TEST(BooleanMembership, BoxThroughSphere) {
  const TriangleSoup both = concatenate(box({-2, -0.25, -0.25}, {2, 0.5, 0.5}), uv_sphere({0, 0, 0}, 1, 8, 10));
  for (BooleanOp op : kOps) {
    const CsgNode tree = operation_tree(op, 2);
    expect_membership(both, 2, tree, boolean(both, tree, two_threads()).mesh, points(), 21 + static_cast<int>(op));
  }
}

TEST(BooleanMembership, SelfIntersectingOperandAndCavity) {
  TriangleSoup twice = concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}));
  twice.label_set.assign(twice.triangles.size(), 0);
  twice.label_sets = {{0}};
  const TriangleSoup scene = concatenate(twice, box({0.5, 0.5, 0.5}, {2.5, 1.5, 1.5}));
  for (BooleanOp op : kOps) {
    const CsgNode tree = operation_tree(op, 2);
    expect_membership(scene, 2, tree, boolean(scene, tree, two_threads()).mesh, points(), 31 + static_cast<int>(op));
  }
  const TriangleSoup nested = concatenate(box({0, 0, 0}, {3, 3, 3}), box({1, 1, 1}, {2, 2, 2}));
  const CsgNode diff = operation_tree(BooleanOp::Difference, 2);
  expect_membership(nested, 2, diff, boolean(nested, diff, two_threads()).mesh, points(), 41);
}

TEST(BooleanMembership, ThreeOperandTreeAndExactPath) {
  const TriangleSoup scene = concatenate({uv_sphere({0, 0, 0}, 1, 8, 10), box({-0.5, -0.5, -2}, {0.5, 0.5, 2}),
                                          box({-2, -0.25, -0.25}, {2, 0.25, 0.25})});
  // (sphere minus the z bar) union the x bar
  const CsgNode tree = CsgNode::of(
      BooleanOp::Union,
      {CsgNode::of(BooleanOp::Difference, {CsgNode::leaf(0), CsgNode::leaf(1)}), CsgNode::leaf(2)});
  expect_membership(scene, 3, tree, boolean(scene, tree, two_threads()).mesh, points(), 51);
  const ExactTriangleSoup exact = tritri_test::with_vertices<ExactVec3>(
      scene, [](const Vec3& p) { return ExactVec3{Q(p[0]), Q(p[1]), Q(p[2])}; });
  expect_membership(exact, 3, tree, boolean(exact, tree, two_threads()).mesh, points() / 3, 52);
}

}  // namespace
