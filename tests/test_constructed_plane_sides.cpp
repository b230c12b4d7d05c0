// tests/test_constructed_plane_sides.cpp
//
// tritri::ConstructedPlaneSides (constructed_plane_sides.h) against an exact oracle that
// does not use the library's predicates: the points' rational coordinates from their
// definitions (support/implicit_recipes.h, exact_point) and rational orient3d
// determinants (support/exact_oracle.h), never tritri::orient3d.
//
// Scenes: 4 to 6 input triangles with double corners (random; integer grid; most on one
// lattice plane; near-coincident planes, z in {0, +-2^-1074} beside random triangles),
// then scaled by 2^-60 or 2^40 (uniformly or per axis) or moved by multiples of 2^20
// when that is exact. Their points: the inputs' corners, the LPI of every input's edge
// with every other input's plane, the TPI of every three input planes, and free explicit
// points. A triangle "on input i" takes three points on i's plane by construction; an
// "unknown" one takes any three points, TPIs and free points, or explicit points only.
// Pairs share 0, 1 or 2 points (the same ImplicitPoint, the same index). Per pair, with
// sides = ConstructedPlaneSides(a, b):
//   1. for each t whose own corners are not collinear, sides(t, k) = sigma_t * (oracle
//      orient3d of t's corners and the other's corner k), one sigma_t = +-1 for all k;
//   2. same_plane() implies that every oracle sign is 0; for proper triangles on input
//      planes it is true exactly when both were built on the same input;
//   3. the constructor given constructed_plane() of both gives the same signs;
//   4. triangles with no known plane (own-corner fallback) or explicit corners only are
//      among those checked in 1;
//   5. separated_by_plane(sides) and meet_only_in_shared_by_sides(ia, ib, sides) answer
//      true exactly when the oracle's signs prove the claim (both triangles proper);
//   6. orientation_in_plane equals sigma_t (0 without a plane), and classify with
//      SourcePlaneKernel gives ImplicitKernel's Result (cross-kernel identity).
// Every branch is counted, printed, and must be hit. TRITRI_TEST_SCALE scales the scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tritri/constructed_plane_sides.h>
#include <tritri/tritri.h>

#include "support/exact_oracle.h"
#include "support/implicit_recipes.h"
#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri_test::Point;
using tritri_test::Recipe;
using tritri_test::Rng;
using tritri_test::Triple;
using Indices = std::array<int, 3>;

constexpr int kMaxReports = 10;      // failures printed in full
constexpr double kTiny = 0x1p-1074;  // the smallest subnormal, about 4.9e-324

// A point of a scene: its recipe, the library's point, its exact reference.
struct Node {
  Recipe recipe;
  ImplicitPoint point;
  tritri_test::Q3 exact;
  tritri_test::ZPoint z;
};

struct Scene {
  std::vector<Triple> inputs;
  std::vector<Node> nodes;
  std::vector<std::vector<int>> on;  // on[i]: the nodes on input i's plane by construction
  std::vector<int> tpis, explicits, free;  // free: explicit points on no input plane
  bool transformed = false;                // scaled or moved
};

// A triangle of scene nodes; src: the input whose plane holds it by construction, or -1.
struct Tri {
  Indices idx;
  int src;
};

Point random_point(Rng& rng) { return {rng.symmetric_unit(), rng.symmetric_unit(), rng.symmetric_unit()}; }

// Modes: 0 random, 1 integer grid, 2 a coplanar sheet (and grid), 3 near-coincident planes.
Triple input_triangle(int mode, const tritri_test::LatticePlane& sheet, Rng& rng) {
  if (mode == 1 || (mode == 2 && rng.percent(35))) return tritri_test::grid_triangle(rng, -3, 3);
  if (mode == 2) return sheet.random_triangle(rng);
  Triple t{random_point(rng), random_point(rng), random_point(rng)};
  if (mode == 3 && rng.percent(60))
    for (Point& p : t) {
      if (rng.percent(50)) p = tritri_test::grid_point(rng, -3, 3);
      p[2] = rng.uniform(-1, 1) * kTiny;
    }
  return t;
}

tritri_test::Transform scene_transform(Rng& rng) {
  tritri_test::Transform t;
  switch (rng.uniform(0, 5)) {
    case 1:
      t.exponent.fill(-60);
      break;
    case 2:
      t.exponent.fill(40);
      break;
    case 3:
      for (double& s : t.shift) s = 0x1p20 * rng.uniform(-2, 2);
      break;
    case 4:
      t.exponent = {-60, 0, 40};
      tritri_test::shuffle(t.exponent.data(), 3, rng);
      break;
    default:
      break;
  }
  return t;
}

bool same_corners(const Triple& a, const Triple& b) {
  for (const Point& p : a)
    if (p != b[0] && p != b[1] && p != b[2]) return false;
  return true;
}

int add_node(Scene& s, const Recipe& r) {
  const auto p = tritri_test::build(r);
  const auto q = tritri_test::exact_point(r);
  if (!p || !q) return -1;  // undefined (test_implicit_point_refusal checks that both agree)
  s.nodes.push_back({r, *p, *q, tritri_test::common_denominator(*q)});
  const int id = static_cast<int>(s.nodes.size()) - 1;
  if (r.kind == ImplicitPoint::Kind::TPI) s.tpis.push_back(id);
  if (r.kind == ImplicitPoint::Kind::Explicit) s.explicits.push_back(id);
  return id;
}

Scene make_scene(Rng& rng, long long (&modes)[4]) {
  Scene s;
  const int mode = rng.uniform(0, 3);
  ++modes[mode];
  const auto sheet = tritri_test::random_lattice_plane(rng);
  const int n = rng.uniform(4, 6);
  for (int tries = 0; static_cast<int>(s.inputs.size()) < n && tries < 200; ++tries) {
    const Triple t = input_triangle(mode, sheet, rng);
    bool fresh = !tritri_test::collinear(tritri_test::exact(t[0]), tritri_test::exact(t[1]), tritri_test::exact(t[2]));
    for (const Triple& u : s.inputs) fresh = fresh && !same_corners(t, u);
    if (fresh) s.inputs.push_back(t);
  }
  const auto transform = scene_transform(rng);
  std::vector<Triple> moved = s.inputs;
  bool exact_map = true;
  for (Triple& t : moved)
    for (Point& p : t) exact_map = exact_map && tritri_test::apply(transform, p, p);
  if (exact_map) s.inputs = moved;  // an exact affine map keeps every incidence
  s.transformed =
      exact_map && (transform.exponent != std::array<int, 3>{0, 0, 0} || !tritri_test::is_zero(transform.shift));
  const auto& in = s.inputs;
  const int m = static_cast<int>(in.size());
  s.on.assign(m, {});
  for (int i = 0; i < m; ++i)
    for (const Point& c : in[i]) s.on[i].push_back(add_node(s, tritri_test::explicit_recipe(c)));
  for (int i = 0; i < m; ++i)  // line of an edge of input j, plane of input i: on both
    for (int j = 0; j < m; ++j)
      for (int e = 0; e < 3 && j != i; ++e) {
        Point p = in[j][e], q = in[j][(e + 1) % 3];
        if (rng.percent(50)) std::swap(p, q);
        const int id = add_node(s, tritri_test::lpi_recipe(p, q, tritri_test::reordered(in[i], rng)));
        if (id < 0) continue;
        s.on[i].push_back(id);
        s.on[j].push_back(id);
      }
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        std::array<Triple, 3> planes{tritri_test::reordered(in[i], rng), tritri_test::reordered(in[j], rng),
                                     tritri_test::reordered(in[k], rng)};
        tritri_test::shuffle(planes.data(), 3, rng);
        const int id = add_node(s, tritri_test::tpi_recipe(planes));
        if (id < 0) continue;
        for (int x : {i, j, k}) s.on[x].push_back(id);
      }
  for (int f = 0; f < 2; ++f) s.free.push_back(add_node(s, tritri_test::explicit_recipe(random_point(rng))));
  return s;
}

bool contains(const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }
bool contains(const Indices& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); }

// Adds `count` entries of `pool` to `tri`, none already in `tri` or in `avoid`; false when
// a few tries do not find them.
bool fill(std::vector<int>& tri, int count, const std::vector<int>& pool, const std::vector<int>& avoid, Rng& rng) {
  for (int tries = 0; count > 0 && tries < 60 && !pool.empty(); ++tries) {
    const int id = pool[rng.uniform(0, static_cast<int>(pool.size()) - 1)];
    if (id >= 0 && !contains(tri, id) && !contains(avoid, id)) {
      tri.push_back(id);
      --count;
    }
  }
  return count == 0;
}

// The nodes a triangle takes: those on input `src`, or (src < 0) any nodes, TPIs and free
// points, or explicit points only (usually with no common plane).
std::vector<int> pool_of(const Scene& s, int src, Rng& rng) {
  if (src >= 0) return s.on[src];
  std::vector<int> pool;
  switch (rng.uniform(0, 2)) {
    case 0:
      pool.resize(s.nodes.size());
      std::iota(pool.begin(), pool.end(), 0);
      break;
    case 1:
      pool = s.tpis;
      pool.insert(pool.end(), s.free.begin(), s.free.end());
      break;
    default:
      pool = s.explicits;
      break;
  }
  return pool;
}

std::optional<std::pair<Tri, Tri>> make_pair(const Scene& s, Rng& rng) {
  const int m = static_cast<int>(s.inputs.size());
  const int src_a = rng.percent(80) ? rng.uniform(0, m - 1) : -1;
  std::vector<int> a;
  if (!fill(a, 3, pool_of(s, src_a, rng), {}, rng)) return std::nullopt;
  const int src_b = rng.percent(15) ? -1 : (src_a >= 0 && rng.percent(30) ? src_a : rng.uniform(0, m - 1));
  const std::vector<int> pool_b = pool_of(s, src_b, rng);
  std::vector<int> shareable;
  for (int id : a)
    if (contains(pool_b, id)) shareable.push_back(id);
  tritri_test::shuffle(shareable.data(), static_cast<int>(shareable.size()), rng);
  const int shared = std::min(rng.uniform(0, 2), static_cast<int>(shareable.size()));
  std::vector<int> b(shareable.begin(), shareable.begin() + shared);
  if (!fill(b, 3 - shared, pool_b, a, rng)) return std::nullopt;
  tritri_test::shuffle(b.data(), 3, rng);
  return std::pair{Tri{{a[0], a[1], a[2]}, src_a}, Tri{{b[0], b[1], b[2]}, src_b}};
}

std::string describe_pair(const Scene& s, const Tri& a, const Tri& b) {
  std::string out;
  for (const Tri* t : {&a, &b}) {
    out += std::string(t == &a ? "a" : "b") + " (on input " + std::to_string(t->src) + "):\n";
    for (int id : t->idx) out += "  [" + std::to_string(id) + "] " + tritri_test::describe(s.nodes[id].recipe) + "\n";
  }
  return out;
}

struct Counts {
  long long modes[4] = {}, scenes = 0, transformed = 0, nodes = 0, tiny = 0;
  long long pairs = 0, shared[3] = {}, degenerate_pairs = 0;
  long long defining_plane = 0, explicit_corners = 0, own_corners = 0, degenerate = 0;  // sides(t, .) checked
  long long zero_signs = 0, nonzero_signs = 0, sigma_plus = 0, sigma_minus = 0, all_zero = 0;
  long long same_true = 0, same_false = 0, same_unknown_true = 0;
  long long separated[2] = {}, meet[3][2] = {};  // [answer]; [shared corners][answer]
  long long orientation_checked = 0, classified = 0, substituted = 0;
};

void check_pair(const Scene& s, const Tri& a, const Tri& b, Counts& c, long long& failures) {
  auto fail = [&](const std::string& what) {
    if (++failures <= kMaxReports) ADD_FAILURE() << what << "\n" << describe_pair(s, a, b);
  };
  using Triangle = tritri::ConstructedPlaneSides::Triangle;
  const Tri* tri[2] = {&a, &b};
  const Triangle ta{s.nodes[a.idx[0]].point, s.nodes[a.idx[1]].point, s.nodes[a.idx[2]].point};
  const Triangle tb{s.nodes[b.idx[0]].point, s.nodes[b.idx[1]].point, s.nodes[b.idx[2]].point};
  const Triangle* own_points[2] = {&ta, &tb};
  const tritri::ConstructedPlaneSides sides(ta, tb);
  const tritri::ConstructedPlane planes[2] = {tritri::constructed_plane(ta[0], ta[1], ta[2]),
                                              tritri::constructed_plane(tb[0], tb[1], tb[2])};
  const tritri::ConstructedPlaneSides given(ta, tb, planes[0], planes[1]);
  ++c.pairs;
  int oracle[2][3], got[2][3];
  bool degenerate[2], all_zero = true;
  for (int t = 0; t < 2; ++t) {
    const Indices& own = tri[t]->idx;
    const Node &n0 = s.nodes[own[0]], &n1 = s.nodes[own[1]], &n2 = s.nodes[own[2]];
    degenerate[t] = tritri_test::collinear(n0.exact, n1.exact, n2.exact);
    for (int k = 0; k < 3; ++k) {
      oracle[t][k] = tritri_test::orient3d(n0.z, n1.z, n2.z, s.nodes[tri[1 - t]->idx[k]].z);
      got[t][k] = tritri::to_int(sides(t, k));
      all_zero = all_zero && oracle[t][k] == 0;
      if (tritri::to_int(given(t, k)) != got[t][k])
        fail("side(" + std::to_string(t) + ", " + std::to_string(k) + ") differs with the planes given");
    }
    if (degenerate[t]) {  // the oracle is 0 for every k; the constructed plane may not be
      ++c.degenerate;
      continue;
    }
    bool all_explicit = true;
    for (const ImplicitPoint& p : *own_points[t]) all_explicit = all_explicit && p.is_explicit();
    ++(!planes[t] ? c.own_corners : (all_explicit ? c.explicit_corners : c.defining_plane));
    int k0 = 0;
    while (k0 < 3 && oracle[t][k0] == 0) ++k0;
    const int sigma = k0 < 3 ? got[t][k0] * oracle[t][k0] : 0;
    bool ok = k0 == 3 || sigma != 0;
    for (int k = 0; k < 3; ++k) {
      ok = ok && got[t][k] == sigma * oracle[t][k];
      ++(oracle[t][k] == 0 ? c.zero_signs : c.nonzero_signs);
    }
    ++(k0 == 3 ? c.all_zero : (sigma > 0 ? c.sigma_plus : c.sigma_minus));
    // orientation_in_plane: the sign relating t's own orient3d to its plane's, as sigma
    // (0 only without a plane).
    const Triangle& o = *own_points[t];
    const int orientation = tritri::orientation_in_plane(planes[t], o[0], o[1], o[2]);
    if (k0 < 3 && orientation != (planes[t] ? sigma : 0))
      fail("orientation_in_plane(" + std::to_string(t) + ") = " + std::to_string(orientation) + ", oracle " +
           std::to_string(planes[t] ? sigma : 0));
    c.orientation_checked += k0 < 3;
    if (!ok)
      fail("side(" + std::to_string(t) + ", .) = " + std::to_string(got[t][0]) + " " + std::to_string(got[t][1]) +
           " " + std::to_string(got[t][2]) + " is not one sign times the oracle's " + std::to_string(oracle[t][0]) +
           " " + std::to_string(oracle[t][1]) + " " + std::to_string(oracle[t][2]));
  }
  const bool same = sides.same_plane();
  if (given.same_plane() != same) fail("same_plane() differs with the planes given");
  if (same && !all_zero) fail("same_plane(), but the oracle has a nonzero sign");
  if (a.src >= 0 && b.src >= 0 && !degenerate[0] && !degenerate[1]) {
    if (same != (a.src == b.src)) fail(std::string("same_plane() is ") + (same ? "true" : "false"));
    ++(same ? c.same_true : c.same_false);
  } else if (same) {
    ++c.same_unknown_true;
  }
  int shared = 0;
  for (int id : a.idx) shared += contains(b.idx, id);
  ++c.shared[shared];
  if (degenerate[0] || degenerate[1]) {  // the oracle's plane of a segment is not defined
    ++c.degenerate_pairs;
    return;
  }
  // What the oracle's signs prove. Separated: the other's three corners strictly on one
  // side of t's plane. One shared corner u: the other's two free corners strictly on one
  // side of t's plane (then all of it but u is). Two: the other's free corner off the plane.
  bool separated = false, meet = false;
  for (int t = 0; t < 2; ++t) {
    separated = separated || (oracle[t][0] != 0 && oracle[t][1] == oracle[t][0] && oracle[t][2] == oracle[t][0]);
    int free_sign[2], n = 0;
    for (int k = 0; k < 3; ++k)
      if (!contains(tri[t]->idx, tri[1 - t]->idx[k]) && n < 2) free_sign[n++] = oracle[t][k];
    if (shared == 1) meet = meet || (free_sign[0] != 0 && free_sign[0] == free_sign[1]);
    if (shared == 2) meet = meet || free_sign[0] != 0;
  }
  const bool got_separated = tritri::separated_by_plane(sides);
  const bool got_meet = tritri::meet_only_in_shared_by_sides(a.idx, b.idx, sides);
  if (got_separated != separated)
    fail(got_separated ? "separated_by_plane: true, but the oracle's signs do not separate"
                       : "separated_by_plane: false, but the oracle's signs separate");
  if (got_meet != meet)
    fail(got_meet ? "meet_only_in_shared_by_sides: true, but the oracle's signs do not prove it"
                  : "meet_only_in_shared_by_sides: false, but the oracle's signs prove it");
  ++c.separated[got_separated];
  ++c.meet[shared][got_meet];
  // SourcePlaneKernel inside classify: the same Result as ImplicitKernel's (its plane signs
  // of either triangle's own corners replaced by the source plane's times the orientation).
  const tritri::SourcePlane sp[2] = {tritri::source_plane(ta[0], ta[1], ta[2]), tritri::source_plane(tb[0], tb[1], tb[2])};
  const tritri::ConstructedPlaneSides fresh(ta, tb, sp[0].corners, sp[1].corners);
  const tritri::SourcePlaneKernel k{&fresh, {sp[0].orientation, sp[1].orientation}};
  const tritri::Result want = tritri::classify<tritri::ImplicitKernel>(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]);
  const tritri::Result got_result = tritri::classify(k, ta[0], ta[1], ta[2], tb[0], tb[1], tb[2]);
  ++c.classified;
  c.substituted += sp[0].orientation != 0 && sp[1].orientation != 0;
  if (!(got_result == want)) fail("classify with SourcePlaneKernel differs from ImplicitKernel's");
}

TEST(ConstructedPlaneSides, SignsMatchExactOracle) {
  Counts c;
  long long failures = 0;
  Rng rng(tritri_test::seed_for(0x5eed));
  const long long scenes = tritri_test::scaled_count(400);
  for (long long n = 0; n < scenes; ++n) {
    const Scene s = make_scene(rng, c.modes);
    ++c.scenes;
    c.nodes += static_cast<long long>(s.nodes.size());
    c.transformed += s.transformed;
    for (const Node& node : s.nodes) c.tiny += node.point.tiny_scale();
    for (int p = 0; p < 40; ++p)
      if (const auto pair = make_pair(s, rng)) check_pair(s, pair->first, pair->second, c, failures);
  }
  std::printf("[ cases    ] %lld scenes (random %lld, grid %lld, sheet %lld, near-coincident %lld; %lld scaled or "
              "moved), %lld points (%lld with subnormal defining coordinates)\n",
              c.scenes, c.modes[0], c.modes[1], c.modes[2], c.modes[3], c.transformed, c.nodes, c.tiny);
  std::printf("[ cases    ] %lld pairs sharing 0 / 1 / 2 corners: %lld / %lld / %lld; %lld with a collinear triangle\n",
              c.pairs, c.shared[0], c.shared[1], c.shared[2], c.degenerate_pairs);
  std::printf("[ cases    ] side(t, .) checked: %lld on a defining plane, %lld on explicit corners, %lld on own "
              "corners (no plane known); %lld collinear skipped\n",
              c.defining_plane, c.explicit_corners, c.own_corners, c.degenerate);
  std::printf("[ cases    ] oracle signs %lld zero, %lld nonzero; sigma +1 %lld, -1 %lld, all zero %lld\n",
              c.zero_signs, c.nonzero_signs, c.sigma_plus, c.sigma_minus, c.all_zero);
  std::printf("[ cases    ] same_plane true %lld, false %lld (proper, on inputs); true otherwise %lld\n", c.same_true,
              c.same_false, c.same_unknown_true);
  std::printf("[ cases    ] separated_by_plane true %lld, false %lld; meet_only_in_shared true / false: "
              "0 shared %lld / %lld, 1 shared %lld / %lld, 2 shared %lld / %lld\n",
              c.separated[1], c.separated[0], c.meet[0][1], c.meet[0][0], c.meet[1][1], c.meet[1][0], c.meet[2][1],
              c.meet[2][0]);
  std::printf("[ cases    ] orientation_in_plane checked %lld; classify with SourcePlaneKernel %lld (both "
              "orientations known %lld)\n",
              c.orientation_checked, c.classified, c.substituted);
  EXPECT_EQ(failures, 0);
  for (long long mode : c.modes) EXPECT_GT(mode, 0);
  EXPECT_GT(c.transformed, 0);
  EXPECT_GT(c.tiny, 0);
  for (long long shared : c.shared) EXPECT_GT(shared, 0);
  const std::pair<const char*, long long> branches[] = {
      {"defining plane", c.defining_plane}, {"explicit corners", c.explicit_corners},
      {"own corners", c.own_corners},       {"collinear", c.degenerate},
      {"zero sign", c.zero_signs},          {"nonzero sign", c.nonzero_signs},
      {"sigma +1", c.sigma_plus},           {"sigma -1", c.sigma_minus},
      {"all zero", c.all_zero},             {"same_plane true", c.same_true},
      {"same_plane false", c.same_false},   {"separated false", c.separated[0]},
      {"separated true", c.separated[1]},   {"meet false, 1 shared", c.meet[1][0]},
      {"meet true, 1 shared", c.meet[1][1]}, {"meet false, 2 shared", c.meet[2][0]},
      {"meet true, 2 shared", c.meet[2][1]}, {"orientation checked", c.orientation_checked},
      {"substituted in classify", c.substituted}};
  for (const auto& [name, n] : branches) EXPECT_GT(n, 0) << name << ": never taken";
}

}  // namespace
