// ViolationTracker (arrangements/src/rounding/violation_tracker.h): after every call of a
// sequence, exactly the violating pairs of the full check, check_arrangement(mesh, 0), as
// sorted (i < j) pairs: small steps on crossing terrains (the incremental path), steps
// changing more than a quarter of the triangles (the full path), renumbered triangles and
// vertices, zeros written -0.0, a vertex moved onto another's position; wherever the pairs
// change, the previous answer is rejected (a tracker ignoring changes fails). Each test
// asserts what it exercised. The last test: meshes whose check depends on vertex identities
// (two vertices at one position, a triangle twice).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <tritri/double_kernel.h>
#include <tritri/projection.h>

#include "arrangements/check_arrangement.h"
#include "arrangements/output_mesh.h"
#include "rounding/violation_tracker.h"

namespace {

using namespace arrangements;
using Pairs = std::vector<std::pair<int, int>>;
using Corners = std::array<Vec3, 3>;

// One source and one label set for every triangle.
void finish(RoundedMesh& m) {
  m.source.assign(m.triangles.size(), 0);
  m.label_set.assign(m.triangles.size(), 0);
  m.label_sets = {{0}};
}

bool any_degenerate(const RoundedMesh& m) {
  for (const Tri& f : m.triangles)
    if (tritri::projection(tritri::DoubleKernel{}, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]).second == 0)
      return true;
  return false;
}

// An (n+1)^2 grid over [0,1]^2 at height z0 + [-amp, amp], cells split on random diagonals.
void add_terrain(RoundedMesh& m, std::mt19937& rng, int n, double z0, double amp) {
  std::uniform_real_distribution<double> dz(-amp, amp);
  const int base = static_cast<int>(m.vertices.size());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) m.vertices.push_back({double(i) / n, double(j) / n, amp == 0 ? z0 : z0 + dz(rng)});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = base + i * (n + 1) + j, b = a + 1, d = a + n + 1, c = d + 1;
      const bool ac = rng() & 1;
      m.triangles.insert(m.triangles.end(), {ac ? Tri{a, b, c} : Tri{a, b, d}, ac ? Tri{a, c, d} : Tri{b, c, d}});
    }
}

// Terrains 0.03 apart with +-0.04 relief (crossing in many places), `smalls` small triangles.
RoundedMesh scene(unsigned seed, int layers, int n, int smalls) {
  std::mt19937 rng(seed);
  RoundedMesh m;
  for (int l = 0; l < layers; ++l) add_terrain(m, rng, n, 0.03 * l, 0.04);
  std::uniform_real_distribution<double> u(0, 1), h(-0.05, 0.15), e(-0.08, 0.08);
  for (int k = 0; k < smalls; ++k) {
    const Vec3 c{u(rng), u(rng), h(rng)};
    const int base = static_cast<int>(m.vertices.size());
    for (int i = 0; i < 3; ++i) m.vertices.push_back({c[0] + e(rng), c[1] + e(rng), c[2] + e(rng)});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  finish(m);
  return m;
}

// `count` triangles far from the rest (so that changing few triangles is a small step).
void add_far(RoundedMesh& m, int count) {
  for (int k = 0; k < count; ++k) {
    const int base = static_cast<int>(m.vertices.size());
    const double x = 10 + 2 * k;
    m.vertices.insert(m.vertices.end(), {Vec3{x, 0, 0}, Vec3{x + 1, 0, 0}, Vec3{x, 1, 0}});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  finish(m);
}

// Puts vertex v at p unless a triangle would degenerate; whether it did.
bool place(RoundedMesh& m, std::size_t v, const Vec3& p) {
  const Vec3 old = m.vertices[v];
  m.vertices[v] = p;
  const bool ok = !any_degenerate(m);
  if (!ok) m.vertices[v] = old;
  return ok;
}

// Moves up to `count` random vertices by up to `size` per coordinate, where none degenerates.
void move_vertices(RoundedMesh& m, std::mt19937& rng, int count, double size) {
  std::uniform_int_distribution<std::size_t> pick(0, m.vertices.size() - 1);
  std::uniform_real_distribution<double> e(-size, size);
  for (int k = 0; k < count; ++k) {
    const std::size_t v = pick(rng);
    place(m, v, {m.vertices[v][0] + e(rng), m.vertices[v][1] + e(rng), m.vertices[v][2] + e(rng)});
  }
}

// The triangles of `after` on corner positions of no triangle of `before` (-0 == 0).
std::size_t changed_triangles(const RoundedMesh& before, const RoundedMesh& after) {
  auto corners = [](const RoundedMesh& m, const Tri& f) {
    Corners c{m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]};
    std::sort(c.begin(), c.end());
    return c;
  };
  std::set<Corners> old;
  for (const Tri& f : before.triangles) old.insert(corners(before, f));
  std::size_t n = 0;
  for (const Tri& f : after.triangles) n += !old.count(corners(after, f));
  return n;
}

Pairs sorted_pairs(Pairs p) {
  for (auto& [i, j] : p)
    if (i > j) std::swap(i, j);
  std::sort(p.begin(), p.end());
  return p;
}

Pairs oracle(const RoundedMesh& m) { return sorted_pairs(check_arrangement(m, 0).violating_pairs); }

// A tracker run against the oracle: every call compared, what the run exercised counted.
struct TrackerRun {
  ViolationTracker tracker;
  Pairs last;  // the oracle's previous answer
  int calls = 0, with_violations = 0, set_changes = 0;

  Pairs check(const RoundedMesh& m, const std::string& what) {
    EXPECT_FALSE(any_degenerate(m)) << what;  // the tracker's precondition
    const Pairs raw = tracker.violations(m), expected = oracle(m), got = sorted_pairs(raw);
    EXPECT_TRUE(std::adjacent_find(raw.begin(), raw.end(), [](auto& p, auto& q) { return !(p < q); }) == raw.end() &&
                std::all_of(raw.begin(), raw.end(), [](auto& p) { return p.first < p.second; }))
        << what << ": not sorted (i < j) pairs";
    EXPECT_EQ(got, expected) << what << " (" << m.triangles.size() << " triangles)";
    with_violations += !expected.empty();
    if (calls > 0 && expected != last) {
      ++set_changes;
      EXPECT_NE(got, last) << what << ": the previous mesh's answer, stale";  // the mutation check
    }
    last = expected;
    ++calls;
    return got;
  }
};

TEST(ViolationTracker, SmallStepsOnCrossingTerrainsMatchTheFullCheck) {
  std::mt19937 rng(101);
  RoundedMesh m = scene(7, 3, 8, 40);
  TrackerRun run;
  ASSERT_GT(run.check(m, "start").size(), 100u);
  std::uniform_int_distribution<int> how_many(1, 5);
  int incremental = 0;
  for (int step = 0; step < 40; ++step) {
    const RoundedMesh before = m;
    move_vertices(m, rng, how_many(rng), 0.02);
    const std::size_t changed = changed_triangles(before, m);
    ASSERT_LE(changed, m.triangles.size() / 4) << "step " << step;
    incremental += changed > 0;
    run.check(m, "small step " + std::to_string(step));
  }
  EXPECT_GE(incremental, 30);
  EXPECT_EQ(run.with_violations, run.calls);
  EXPECT_GE(run.set_changes, 20);
}

TEST(ViolationTracker, LargeChangesBetweenSmallStepsMatchTheFullCheck) {
  std::mt19937 rng(202);
  RoundedMesh m = scene(11, 3, 8, 40);
  TrackerRun run;
  run.check(m, "start");
  int large = 0, small = 0;
  for (int step = 0; step < 36; ++step) {
    const RoundedMesh before = m;
    const bool meant_large = step % 3 == 0;
    if (step % 6 == 0)  // most vertices moved
      move_vertices(m, rng, static_cast<int>(m.vertices.size()), 0.01);
    else if (step % 6 == 3)  // another scene, of another size
      m = scene(1000 + step, 2 + step % 2, 6 + step % 4, 20 + step);
    else
      move_vertices(m, rng, 3, 0.02);
    const std::size_t changed = changed_triangles(before, m), nt = m.triangles.size();
    const std::string name = "step " + std::to_string(step) + (meant_large ? " (large)" : " (small)");
    ASSERT_EQ(changed > nt / 4, meant_large) << name << ": " << changed << " of " << nt << " changed";
    large += meant_large;
    small += !meant_large && changed > 0;
    run.check(m, name);
  }
  // Any mesh may follow any other: nothing, one triangle, nothing, the scene twice.
  RoundedMesh empty, one;
  add_far(empty, 0);
  add_far(one, 1);
  run.check(empty, "empty");
  run.check(one, "one triangle");
  run.check(empty, "empty again");
  run.check(m, "the last scene again");
  run.check(m, "the last scene unchanged");
  EXPECT_EQ(large, 12);
  EXPECT_GE(small, 20);
  EXPECT_GE(run.with_violations, 30);
  EXPECT_GE(run.set_changes, 20);
}

// The same geometry renumbered: vertices and triangles permuted, corners rotated in each.
RoundedMesh renumbered(const RoundedMesh& m, std::mt19937& rng) {
  std::vector<int> vperm(m.vertices.size()), tperm(m.triangles.size());
  std::iota(vperm.begin(), vperm.end(), 0);
  std::iota(tperm.begin(), tperm.end(), 0);
  std::shuffle(vperm.begin(), vperm.end(), rng);
  std::shuffle(tperm.begin(), tperm.end(), rng);
  RoundedMesh out{std::vector<Vec3>(m.vertices.size()), std::vector<Tri>(m.triangles.size()), {}, {}, {}};
  for (std::size_t v = 0; v < m.vertices.size(); ++v) out.vertices[vperm[v]] = m.vertices[v];
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const int r = static_cast<int>(rng() % 3);
    for (int k = 0; k < 3; ++k) out.triangles[tperm[t]][k] = vperm[m.triangles[t][(k + r) % 3]];
  }
  finish(out);
  return out;
}

TEST(ViolationTracker, RenumberedTrianglesAndVerticesMatchTheFullCheck) {
  std::mt19937 rng(303);
  RoundedMesh m = scene(13, 3, 8, 40);
  TrackerRun run;
  run.check(m, "start");
  int renumbered_only = 0, pairs_renumbered = 0;
  for (int step = 0; step < 30; ++step) {
    const RoundedMesh before = m;
    m = renumbered(m, rng);
    const bool also_move = step % 2 == 1;
    if (also_move) move_vertices(m, rng, 3, 0.02);
    ASSERT_LE(changed_triangles(before, m), also_move ? m.triangles.size() / 4 : 0) << "step " << step;
    const Pairs previous = run.last;
    const Pairs now = run.check(m, "step " + std::to_string(step) + (also_move ? " (renumbered, moved)" : ""));
    if (!also_move) {  // the same number of pairs, under other indices
      ++renumbered_only;
      EXPECT_EQ(now.size(), previous.size()) << "step " << step;
      pairs_renumbered += !now.empty() && now != previous;
    }
  }
  EXPECT_EQ(renumbered_only, 15);
  EXPECT_EQ(pairs_renumbered, 15);
  EXPECT_EQ(run.with_violations, run.calls);
}

// Zeros written as -0.0 with probability 1/2 (`positive`: as 0.0); how many are negative.
int sign_zeros(RoundedMesh& m, std::mt19937& rng, bool positive = false) {
  int negative = 0;
  for (Vec3& p : m.vertices)
    for (double& x : p)
      if (x == 0) {
        x = positive || (rng() & 1) ? 0.0 : -0.0;
        negative += std::signbit(x);
      }
  return negative;
}

TEST(ViolationTracker, NegativeZerosAreTheSameTrianglesAndPairs) {
  std::mt19937 rng(404);
  // A flat grid at z = 0 (and x or y = 0 on its border), a terrain crossing it, small
  // triangles in z = 0 over it (coplanar overlaps) or crossing it, half of them at x = 0.
  RoundedMesh m;
  add_terrain(m, rng, 6, 0.0, 0.0);
  add_terrain(m, rng, 6, 0.0, 0.05);
  std::uniform_real_distribution<double> u(0, 1), e(-0.08, 0.08);
  for (int k = 0; k < 20; ++k) {
    const int base = static_cast<int>(m.vertices.size());
    const double x = k < 10 ? 0.0 : u(rng), y = u(rng);
    auto z = [&] { return k % 2 ? 0.0 : e(rng); };
    m.vertices.push_back({x, y, z()});
    m.vertices.push_back({x + 0.05 + std::abs(e(rng)), y + e(rng), z()});
    m.vertices.push_back({x + e(rng), y + 0.05 + std::abs(e(rng)), z()});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  finish(m);
  TrackerRun run;
  Pairs expected = run.check(m, "zeros positive");
  ASSERT_GT(expected.size(), 50u);
  for (int round = 0; round < 6; ++round) {
    const std::string name = "round " + std::to_string(round);
    RoundedMesh negative = m;
    ASSERT_GT(sign_zeros(negative, rng), 10) << name;
    ASSERT_EQ(changed_triangles(m, negative), 0u) << name;
    EXPECT_EQ(run.check(negative, name + ": some zeros negative"), expected);
    TrackerRun fresh;  // a tracker that sees the negative zeros first
    EXPECT_EQ(fresh.check(negative, name + ": negative zeros first"), expected);
    // A small step on the negative zeros, then the same mesh with every zero positive.
    move_vertices(negative, rng, 2, 0.02);
    expected = run.check(negative, name + ": moved, negative zeros");
    m = negative;
    sign_zeros(m, rng, true);
    EXPECT_EQ(run.check(m, name + ": moved, zeros positive again"), expected);
    EXPECT_EQ(fresh.check(m, name + ": fresh tracker, moved, zeros positive"), expected);
  }
  EXPECT_EQ(run.with_violations, run.calls);
  EXPECT_GE(run.set_changes, 5);
}

TEST(ViolationTracker, AVertexMovedOntoAnotherVertexMatchesTheFullCheck) {
  std::mt19937 rng(505);
  RoundedMesh m = scene(17, 2, 8, 30);
  const std::size_t nv = m.vertices.size();
  TrackerRun run;
  run.check(m, "start");
  std::uniform_int_distribution<std::size_t> pick(0, nv - 1);
  int coincident = 0, meeting_there = 0;
  for (int step = 0; step < 30; ++step) {
    const std::string name = "step " + std::to_string(step);
    if (step % 2 == 1) {
      move_vertices(m, rng, 2, 0.02);
      run.check(m, name + " (small)");
      continue;
    }
    // A vertex v onto the position of another vertex w, where no triangle degenerates.
    for (int attempt = 0; attempt < 100; ++attempt) {
      const std::size_t v = pick(rng), w = pick(rng);
      if (m.vertices[v] == m.vertices[w] || !place(m, v, m.vertices[w])) continue;
      ++coincident;
      const Pairs now = run.check(m, name + ": vertex " + std::to_string(v) + " onto " + std::to_string(w));
      // Whether some pair meets at the common position: a triangle on v and one on w.
      auto on = [&](int t, std::size_t x) {
        return std::count(m.triangles[t].begin(), m.triangles[t].end(), static_cast<int>(x)) > 0;
      };
      meeting_there += std::any_of(now.begin(), now.end(), [&](const std::pair<int, int>& p) {
        return (on(p.first, v) && on(p.second, w)) || (on(p.first, w) && on(p.second, v));
      });
      break;
    }
  }
  EXPECT_LT(std::set<Vec3>(m.vertices.begin(), m.vertices.end()).size(), nv);  // positions still shared
  EXPECT_EQ(coincident, 15);
  EXPECT_GE(meeting_there, 10);
  EXPECT_GE(run.set_changes, 15);
}

TEST(ViolationTracker, AStaleAnswerIsRejected) {
  // By hand: B crosses A, is lifted off it (a small step: 32 triangles), is put back.
  RoundedMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, -0.5}, {0.3, 0.2, 0.5}, {0.2, 0.3, 0.5}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  add_far(m, 30);
  const Pairs crossing{{0, 1}};
  ViolationTracker tracker;
  ASSERT_EQ(oracle(m), crossing);
  EXPECT_EQ(tracker.violations(m), crossing);
  RoundedMesh lifted = m;
  lifted.vertices[3][2] = 0.1;
  ASSERT_EQ(changed_triangles(m, lifted), 1u);
  ASSERT_TRUE(oracle(lifted).empty());
  EXPECT_NE(tracker.violations(lifted), crossing);  // the stale answer
  EXPECT_EQ(tracker.violations(m), crossing);
}

// Meshes whose check depends on vertex identities, not positions alone (two vertices at one
// position, a triangle twice: moved vertices can make them). Matching triangles by corner
// positions alone got every step below wrong; the tracker checks such a mesh, and the next, in full.
TEST(ViolationTracker, SameCornerPositionsOtherVertices) {
  // A quad a b c d as (a, b, c) (a, c, d), crossed by triangle 2; b moved onto d: triangle 0
  // would be taken for the previous triangle 1 (full check (0, 1) (0, 2) (1, 2), not (0, 2)).
  RoundedMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.2, 0.6, -0.5}, {0.3, 0.6, 0.5}, {0.2, 0.7, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
  add_far(m, 30);
  TrackerRun run, again, apart_first, merged_first;
  run.check(m, "the quad crossed");
  m.vertices[1] = m.vertices[3];
  run.check(m, "b onto d");
  // Triangle 1 twice, then a far one moved (full check (0, 1) (0, 2) (1, 2), not (0, 0) (0, 2)).
  m.vertices[1] = {1, 0, 0};
  m.triangles[0] = m.triangles[1];
  again.check(m, "a triangle twice");
  m.vertices.back()[2] = 0.5;
  again.check(m, "a far triangle moved");
  // Triangles touching at (1, 0, 0) through two vertices there, then through one (merged),
  // and the other way round: no corner position changes, but the answer does (merged: none;
  // split: (0, 1)).
  RoundedMesh apart;
  apart.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}};
  apart.triangles = {{0, 1, 2}, {3, 4, 5}};
  add_far(apart, 30);
  RoundedMesh merged = apart;
  merged.triangles[1][0] = 1;
  apart_first.check(apart, "two vertices at one position");
  apart_first.check(merged, "merged");
  merged_first.check(merged, "merged first");
  merged_first.check(apart, "then split");
}

}  // namespace
