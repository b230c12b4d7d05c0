// Specification of the pair keys of the candidate-pair searches, and of
// tritri::TriangleSlabsOnDemand:
//   1. embedded_corner_keys(F, embedded) (tritri/embedded_stars.h): corner k of triangle t is
//      its vertex when that is embedded, else -1 - t; for every pair i != j the keys
//      share a value (share_key, and a plain comparison here) exactly when
//      share_embedded_star(F[i], F[j], embedded), and exactly when the two triangles share a
//      vertex v with embedded[v] (the reference, by loops). Over all pairs of: closed meshes
//      (a subdivided octahedron on the sphere, a torus grid: every vertex embedded), a mesh with
//      folds, non-manifold vertices and edges, reversed and repeated triangles (some vertices
//      embedded, some not), and both with random flags.
//   2. for_each_candidate_pair (tritri/hub_pairs.h) with keys, on a fan of 72 triangles around
//      a hub, crossed by a grid and a random soup (with and without caller groups; random keys
//      and embedded corner keys), threads 1 and 2: every pair of the same call without keys
//      whose keys share no value (decided here) is visited once, with i < j, and no pair
//      outside that call's; pairs whose keys share a value may be visited, at most once (its
//      search with stars as groups takes the keys as a hint: box_pairs.h). Keys share values
//      both within the hub's star and outside it.
//   3. for_each_overlapping_pair (tritri/box_pairs.h) with groups and keys (both overloads),
//      threads 1 and 2: every brute-force box pair outside one group whose keys share no value
//      is visited once, the pairs whose keys share one at most once, no other pair.
//   4. Keys of the wrong size (one more or one fewer than the triangles) throw
//      std::invalid_argument in both functions, with or without groups, with or without hubs.
//   5. TriangleSlabsOnDemand (tritri/direction_slabs.h): get(t) called several times per
//      triangle from an arena of 2 threads, on fresh objects (first uses race), returns slabs
//      bitwise equal to direction_slabs of t's corners (points: Vlo and Vhi one span; boxes:
//      two spans), for soups at offsets up to 1e15 and scales 2^-1000 to 2^1021; afterwards the
//      stored slabs, not a copy in the caller's scratch. apart(i, j) equals
//      apart_by_slabs(F[i], F[j], direction_slabs of each) for every ordered pair of soups whose
//      triangles share corners, on first and later uses.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <tritri/box_pairs.h>
#include <tritri/direction_slabs.h>
#include <tritri/embedded_stars.h>
#include <tritri/hub_pairs.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/brute_force_box_pairs.h"
#include "support/test_scale.h"

namespace {

using tritri_test::seed_for;
using P = std::array<double, 3>;
using Ids = std::array<int, 3>;
using Pairs = std::vector<std::pair<int, int>>;
using Flags = std::vector<std::uint8_t>;
constexpr double kPi = std::numbers::pi;

struct Mesh {
  std::vector<P> V;
  std::vector<Ids> F;
  int vertex(const P& p) {
    V.push_back(p);
    return static_cast<int>(V.size()) - 1;
  }
  void tri(int a, int b, int c) { F.push_back({a, b, c}); }
};

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
int below(std::mt19937_64& rng, int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); }

// Whether a and b hold a common value (the reference for key sharing).
bool common_value(const Ids& a, const Ids& b) {
  for (int u : a)
    for (int w : b)
      if (u == w) return true;
  return false;
}

// Whether triangles a and b have a common vertex flagged embedded (the reference for
// share_embedded_star).
bool common_embedded_vertex(const Ids& a, const Ids& b, const Flags& embedded) {
  for (int u : a)
    if (embedded[u] && std::count(b.begin(), b.end(), u) > 0) return true;
  return false;
}

Flags embedded_of(const Mesh& m) {
  return tritri::embedded_stars(std::span<const P>(m.V), std::span<const Ids>(m.F), 1);
}

// ---------------------------------------------------------------------------------------
// 1. embedded_corner_keys

// The octahedron |x| + |y| + |z| = k on the integer lattice, k^2 triangles per face,
// outward, its vertices then pushed onto the unit sphere.
Mesh octahedron_sphere(int k) {
  Mesh m;
  std::map<std::array<int, 3>, int> id;
  auto at = [&](int sx, int sy, int sz, int i, int j) {
    const std::array<int, 3> p{sx * i, sy * j, sz * (k - i - j)};
    const auto [it, added] = id.try_emplace(p, static_cast<int>(m.V.size()));
    if (added) {
      const double r = std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]);
      m.vertex({p[0] / r, p[1] / r, p[2] / r});
    }
    return it->second;
  };
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        const bool flip = sx * sy * sz < 0;  // a reflection of the positive face
        auto face = [&](int a, int b, int c) { flip ? m.tri(a, c, b) : m.tri(a, b, c); };
        for (int i = 0; i < k; ++i)
          for (int j = 0; i + j < k; ++j) {
            face(at(sx, sy, sz, i, j), at(sx, sy, sz, i + 1, j), at(sx, sy, sz, i, j + 1));
            if (i + j + 2 <= k) face(at(sx, sy, sz, i + 1, j), at(sx, sy, sz, i + 1, j + 1), at(sx, sy, sz, i, j + 1));
          }
      }
  return m;
}

// A torus (radii 3 and 1) of nu x nv quads, two triangles each, consistently oriented.
Mesh torus(int nu, int nv) {
  Mesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv, r = 3 + std::cos(v);
      m.vertex({r * std::cos(u), r * std::sin(u), std::sin(v)});
    }
  auto id = [&](int i, int j) { return (i % nu) * nv + j % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.tri(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.tri(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return m;
}

// An open or closed fan around a new apex c: wedges (apex, ring k, ring k + 1), ring k at
// c + cos(a) u + sin(a) w, a from 0 turning `turn` radians in `wedges` steps.
int fan(Mesh& m, const P& c, const P& u, const P& w, int wedges, double turn, bool closed) {
  const int apex = m.vertex(c), first = static_cast<int>(m.V.size());
  const int points = closed ? wedges : wedges + 1;
  for (int k = 0; k < points; ++k) {
    const double a = turn * k / wedges;
    m.vertex({c[0] + std::cos(a) * u[0] + std::sin(a) * w[0], c[1] + std::cos(a) * u[1] + std::sin(a) * w[1],
              c[2] + std::cos(a) * u[2] + std::sin(a) * w[2]});
  }
  for (int k = 0; k < wedges; ++k) m.tri(apex, first + k, first + (k + 1) % points);
  return apex;
}

// Stars that are not embedded beside ones that are. Returns the bowtie's apex.
int hostile_mesh(Mesh& m) {
  // A flat 7 x 7 grid with three triangles reversed.
  auto id = [](int i, int j) { return j * 8 + i; };
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) m.vertex({double(i), double(j), 0});
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 7; ++i) {
      m.tri(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.tri(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  for (int t : {10, 53, 71}) std::swap(m.F[t][1], m.F[t][2]);
  // A bowtie: two closed fans in different planes around one apex (two fans at a vertex).
  const int apex = fan(m, {20, 0, 0}, {1, 0, 0}, {0, 1, 0}, 8, 2 * kPi, true);
  const int second = fan(m, {20, 0, 0}, {0, 0, 1}, {0.6, 0.8, 0}, 7, 2 * kPi, true);
  for (Ids& f : m.F)
    for (int& v : f)
      if (v == second) v = apex;
  // A book: three triangles on one edge (a non-manifold edge).
  const int a = m.vertex({30, 0, 0}), b = m.vertex({31, 0, 0});
  for (const P& p : {P{30.5, 1, 0}, P{30.5, -1, 0}, P{30.5, 0, 1}}) m.tri(a, b, m.vertex(p));
  // Folds: an open fan turning 3 pi, a closed fan winding twice.
  fan(m, {40, 0, 0}, {1, 0, 0}, {0, 1, 0}, 9, 3 * kPi, false);
  fan(m, {50, 0, 0}, {1, 0, 0}, {0, 1, 0}, 10, 4 * kPi, true);
  // A repeated triangle, a triangle with a repeated index, one sharing nothing.
  m.F.push_back(m.F[20]);
  m.tri(id(3, 3), id(3, 3), id(4, 5));
  m.tri(m.vertex({60, 0, 0}), m.vertex({61, 0, 0}), m.vertex({60, 1, 0}));
  return apex;
}

// Every pair of m against the references, for the flags `embedded`. Returns the pairs that
// share only vertices not flagged.
long long check_corner_keys(const Mesh& m, const Flags& embedded, const std::string& name) {
  SCOPED_TRACE(name);
  const std::vector<Ids> keys = tritri::embedded_corner_keys(std::span<const Ids>(m.F), std::span(embedded));
  EXPECT_EQ(keys.size(), m.F.size());
  if (keys.size() != m.F.size()) return 0;
  for (std::size_t t = 0, wrong = 0; t < m.F.size() && wrong == 0; ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = m.F[t][k], expected = embedded[v] ? v : -1 - static_cast<int>(t);
      wrong += keys[t][k] != expected;
      EXPECT_EQ(keys[t][k], expected) << "triangle " << t << " corner " << k;
    }
  long long shared_embedded = 0, shared_other = 0, mismatches = 0;
  std::string first;
  for (std::size_t i = 0; i < m.F.size(); ++i)
    for (std::size_t j = i + 1; j < m.F.size(); ++j) {
      const bool expected = common_embedded_vertex(m.F[i], m.F[j], embedded);
      shared_embedded += expected;
      shared_other += !expected && common_value(m.F[i], m.F[j]);
      const bool got[] = {tritri::detail::box_pairs::share_key(keys[i], keys[j]),
                          tritri::detail::box_pairs::share_key(keys[j], keys[i]), common_value(keys[i], keys[j]),
                          tritri::share_embedded_star(m.F[i], m.F[j], embedded),
                          tritri::share_embedded_star(m.F[j], m.F[i], embedded)};
      for (int g = 0; g < 5; ++g)
        if (got[g] != expected && mismatches++ == 0)
          first = "pair (" + std::to_string(i) + ", " + std::to_string(j) + "), answer " + std::to_string(g) +
                  (expected ? ": they share an embedded vertex" : ": they share no embedded vertex");
    }
  EXPECT_EQ(mismatches, 0) << first;
  EXPECT_GT(shared_embedded, 0) << "no pair shares an embedded vertex";
  std::printf("%-34s %5zu triangles: %6lld pairs share an embedded vertex, %5lld share only others\n", name.c_str(),
              m.F.size(), shared_embedded, shared_other);
  return shared_other;
}

Flags random_flags(std::size_t n, std::mt19937_64& rng) {
  Flags f(n);
  for (auto& x : f) x = rng() % 2;
  return f;
}

TEST(PairKeys, EmbeddedCornerKeysShareAValueExactlyWhenTrianglesShareAnEmbeddedStarOnClosedMeshes) {
  std::mt19937_64 rng(seed_for(0x6b31));
  for (const auto& [mesh, name] : {std::pair{octahedron_sphere(9), "octahedral sphere"}, {torus(24, 12), "torus"}}) {
    const Flags e = embedded_of(mesh);
    ASSERT_EQ(std::count(e.begin(), e.end(), 1), std::ssize(mesh.V)) << name << ": a closed mesh, every star embedded";
    check_corner_keys(mesh, e, name);
    EXPECT_GT(check_corner_keys(mesh, random_flags(mesh.V.size(), rng), std::string(name) + ", random flags"), 0);
  }
}

TEST(PairKeys, EmbeddedCornerKeysShareAValueExactlyWhenTrianglesShareAnEmbeddedStarOnHostileMeshes) {
  std::mt19937_64 rng(seed_for(0x6b32));
  Mesh m;
  const int apex = hostile_mesh(m);
  const Flags e = embedded_of(m);
  EXPECT_FALSE(e[apex]) << "the bowtie's apex (two fans)";
  long long used = 0, embedded = 0;  // among vertices of some triangle
  std::vector<char> in_triangle(m.V.size(), 0);
  for (const Ids& f : m.F)
    for (int v : f) in_triangle[v] = 1;
  for (std::size_t v = 0; v < m.V.size(); ++v) used += in_triangle[v], embedded += in_triangle[v] && e[v];
  ASSERT_GT(embedded, 0) << "no embedded vertex: the test could not fail";
  ASSERT_LT(embedded, used) << "every vertex embedded: the test could not fail";
  EXPECT_GT(check_corner_keys(m, e, "hostile mesh"), 0) << "no pair shares only vertices that are not embedded";
  EXPECT_GT(check_corner_keys(m, random_flags(m.V.size(), rng), "hostile mesh, random flags"), 0);
}

// ---------------------------------------------------------------------------------------
// 2-4. Keys in the searches

// A closed fan of 72 wedges around the hub (vertex 0) in z = 0, a vertical grid through it,
// and small random triangles, some with a corner on the fan's rim.
Mesh hub_scene(std::mt19937_64& rng) {
  Mesh m;
  const int hub = fan(m, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 72, 2 * kPi, true);
  EXPECT_EQ(hub, 0);
  const int first = static_cast<int>(m.V.size());
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 6; ++i) m.vertex({0.3, -0.6 + 0.2 * i, -0.3 + 0.15 * j});
  auto id = [&](int i, int j) { return first + j * 7 + i; };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 6; ++i) {
      m.tri(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.tri(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  for (int t = 0; t < 60; ++t) {
    const P c{uniform(rng, -1.2, 1.2), uniform(rng, -1.2, 1.2), uniform(rng, -0.3, 0.3)};
    Ids f;
    for (int& v : f) {
      const P p{c[0] + uniform(rng, 0, 0.3), c[1] + uniform(rng, 0, 0.3), c[2] + uniform(rng, 0, 0.3)};
      v = rng() % 4 == 0 ? 1 + below(rng, 72) : m.vertex(p);  // a rim vertex, or a new one
    }
    if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) m.F.push_back(f);
  }
  return m;
}

// Caller groups: four wedges and the grid in one, pairs of random triangles in others.
std::vector<std::int64_t> scene_groups(const Mesh& m) {
  std::vector<std::int64_t> group(m.F.size(), -1);
  for (std::size_t t = 0; t < m.F.size(); ++t)
    if (t < 4 || (t >= 72 && t < 120))
      group[t] = 7;
    else if (t >= 120 && t % 4 < 2)
      group[t] = 100 + static_cast<std::int64_t>(t / 4);
  return group;
}

// Three values per triangle in 0 .. 23, each one time in four negative and unique instead.
std::vector<Ids> random_keys(std::size_t n, std::mt19937_64& rng) {
  std::vector<Ids> keys(n);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) keys[t][k] = rng() % 4 == 0 ? -1 - static_cast<int>(3 * t + k) : below(rng, 24);
  return keys;
}

// Every visit of search(visit), sorted, repeats kept.
template <class Search>
Pairs visits(const Search& search) {
  tbb::enumerable_thread_specific<Pairs> found;
  search([&found](int i, int j) { found.local().emplace_back(i, j); });
  Pairs all;
  for (const Pairs& p : found) all.insert(all.end(), p.begin(), p.end());
  std::sort(all.begin(), all.end());
  return all;
}

// "" when `got` (sorted) has every pair i < j at most once, every pair of `must` and no pair
// outside `allowed` (both sorted; `must` within `allowed`).
std::string differences(const Pairs& got, const Pairs& must, const Pairs& allowed) {
  for (const auto& [i, j] : got)
    if (!(i < j)) return "visited (" + std::to_string(i) + ", " + std::to_string(j) + "): not i < j";
  if (auto it = std::adjacent_find(got.begin(), got.end()); it != got.end())
    return "visited (" + std::to_string(it->first) + ", " + std::to_string(it->second) + ") twice";
  Pairs missed, extra;
  std::set_difference(must.begin(), must.end(), got.begin(), got.end(), std::back_inserter(missed));
  std::set_difference(got.begin(), got.end(), allowed.begin(), allowed.end(), std::back_inserter(extra));
  if (missed.empty() && extra.empty()) return "";
  std::ostringstream os;
  os << "missed " << missed.size() << ", extra " << extra.size();
  for (const Pairs* d : {&missed, &extra})
    if (!d->empty()) os << (d == &missed ? "; missed " : "; extra ") << d->front().first << ", " << d->front().second;
  return os.str();
}

// Pairs of `got` (sorted) in `shared` (sorted).
long long common_pairs(const Pairs& got, const Pairs& shared) {
  Pairs both;
  std::set_intersection(got.begin(), got.end(), shared.begin(), shared.end(), std::back_inserter(both));
  return std::ssize(both);
}

TEST(PairKeys, CandidatePairsWithKeysAreThoseWithoutLessThePairsWhoseKeysShareAValue) {
  std::mt19937_64 rng(seed_for(0x6b33));
  const Mesh m = hub_scene(rng);
  const std::span<const P> V(m.V);
  const std::span<const Ids> F(m.F);
  const std::vector<std::vector<Ids>> key_sets = {
      random_keys(m.F.size(), rng), tritri::embedded_corner_keys(F, std::span<const std::uint8_t>(embedded_of(m)))};
  const std::size_t box_pairs = tritri_test::brute_force_box_pairs(m.V, m.F).size();
  for (bool grouped : {false, true}) {
    const std::vector<std::int64_t> group = grouped ? scene_groups(m) : std::vector<std::int64_t>{};
    const Pairs all = visits([&](const auto& visit) { tritri::for_each_candidate_pair(V, F, 1, group, visit); });
    ASSERT_EQ(std::adjacent_find(all.begin(), all.end()), all.end());
    const auto in_star = std::count_if(all.begin(), all.end(), [&](const auto& p) {
      return m.F[p.first][0] == 0 && m.F[p.second][0] == 0;  // the wedges hold the hub first
    });
    EXPECT_LT(in_star, 72 * 71 / 8) << "the hub's star was searched by boxes";
    EXPECT_LT(all.size(), box_pairs);
    for (std::size_t s = 0; s < key_sets.size(); ++s) {
      SCOPED_TRACE(std::string(s == 0 ? "random keys" : "embedded corner keys") + (grouped ? ", groups" : ""));
      const std::vector<Ids>& keys = key_sets[s];
      Pairs want, shared;
      long long filtered[2] = {0, 0}, kept[2] = {0, 0};  // [in the hub's star]
      for (const auto& [i, j] : all) {
        const bool star = m.F[i][0] == 0 && m.F[j][0] == 0;
        if (common_value(keys[i], keys[j]))
          ++filtered[star], shared.emplace_back(i, j);
        else
          ++kept[star], want.emplace_back(i, j);
      }
      EXPECT_GT(filtered[1], 0) << "in the star";
      EXPECT_GT(kept[0], 0) << "outside the star";
      if (s == 0) {  // (corner keys: the rim's stars are not embedded, the hub's is)
        EXPECT_GT(filtered[0], 0) << "outside the star";
        EXPECT_GT(kept[1], 0) << "in the star";
      }
      for (int threads : {1, 2}) {
        const Pairs got =
            visits([&](const auto& visit) { tritri::for_each_candidate_pair(V, F, threads, group, visit, keys); });
        EXPECT_EQ(differences(got, want, all), "") << "threads " << threads;
        // The hub's own pairs go through the arc search's grid, which skips by the keys: none
        // of them whose keys share a value may be visited (without caller groups, which take
        // triangles out of the star).
        if (!grouped) {
          long long visited_sharing = 0;
          for (const auto& [i, j] : got)
            visited_sharing += m.F[i][0] == 0 && m.F[j][0] == 0 && common_value(keys[i], keys[j]);
          EXPECT_EQ(visited_sharing, 0) << "the hub's arc search visited pairs whose keys share a value";
        }
        std::printf("%s%s, threads %d: %zu pairs without keys, %zu with: %lld of the %zu whose keys share a value\n",
                    s == 0 ? "random keys" : "corner keys", grouped ? ", groups" : "", threads, all.size(), got.size(),
                    common_pairs(got, shared), shared.size());
      }
    }
  }
}

TEST(PairKeys, OverlappingPairsWithGroupsAndKeysAreTheBoxPairsLessGroupsAndSharedKeys) {
  std::mt19937_64 rng(seed_for(0x6b34));
  const Mesh m = hub_scene(rng);
  const std::span<const P> V(m.V);
  const std::span<const Ids> F(m.F);
  const std::vector<std::int64_t> group = scene_groups(m);
  const std::vector<Ids> keys = random_keys(m.F.size(), rng);
  Pairs want, allowed;
  long long same_group = 0, shared = 0;
  for (const auto& [i, j] : tritri_test::brute_force_box_pairs(m.V, m.F)) {
    if (group[i] >= 0 && group[i] == group[j]) {
      ++same_group;
      continue;
    }
    allowed.emplace_back(i, j);
    if (common_value(keys[i], keys[j]))
      ++shared;
    else
      want.emplace_back(i, j);
  }
  EXPECT_GT(same_group, 0);
  EXPECT_GT(shared, 0);
  EXPECT_GT(want.size(), 0u);
  for (int threads : {1, 2}) {
    const Pairs got =
        visits([&](const auto& visit) { tritri::for_each_overlapping_pair(V, F, threads, group, visit, keys); });
    EXPECT_EQ(differences(got, want, allowed), "") << "threads " << threads;
    const Pairs boxes =
        visits([&](const auto& visit) { tritri::for_each_overlapping_pair(V, V, F, threads, group, visit, keys); });
    EXPECT_EQ(differences(boxes, want, allowed), "") << "Vlo, Vhi; threads " << threads;
  }
}

TEST(PairKeys, KeysOfTheWrongSizeThrow) {
  std::mt19937_64 rng(seed_for(0x6b35));
  std::vector<Mesh> meshes(3);  // one triangle; a small fan (no hub); the hub scene
  meshes[0].tri(meshes[0].vertex({0, 0, 0}), meshes[0].vertex({1, 0, 0}), meshes[0].vertex({0, 1, 0}));
  fan(meshes[1], {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 5, 2 * kPi, true);
  meshes[2] = hub_scene(rng);
  for (const Mesh* m = meshes.data(); m != meshes.data() + meshes.size(); ++m) {
    const std::span<const P> V(m->V);
    const std::span<const Ids> F(m->F);
    const std::vector<std::int64_t> group(m->F.size(), 3);
    const auto visit = [](int, int) {};
    for (const std::size_t size : {m->F.size() - 1, m->F.size() + 1}) {
      if (size == 0) continue;  // no keys
      SCOPED_TRACE(std::to_string(m->F.size()) + " triangles, " + std::to_string(size) + " keys");
      const std::vector<Ids> keys(size, Ids{1, 2, 3});
      for (const std::span<const std::int64_t> g : {std::span<const std::int64_t>(), std::span(group)}) {
        EXPECT_THROW(tritri::for_each_overlapping_pair(V, F, 1, g, visit, keys), std::invalid_argument);
        EXPECT_THROW(tritri::for_each_overlapping_pair(V, V, F, 2, g, visit, keys), std::invalid_argument);
        EXPECT_THROW(tritri::for_each_candidate_pair(V, F, 1, g, visit, keys), std::invalid_argument);
      }
    }
    const std::vector<Ids> keys(m->F.size(), Ids{1, 2, 3});  // the right size
    EXPECT_NO_THROW(tritri::for_each_overlapping_pair(V, F, 1, group, visit, keys));
    EXPECT_NO_THROW(tritri::for_each_candidate_pair(V, F, 1, {}, visit, keys));
  }
}

// ---------------------------------------------------------------------------------------
// 5. TriangleSlabsOnDemand

// Triangles over clusters of vertices at offset o and scale s (corners o + s u, u in
// [-1, 1]^3), 1 in 10 with corners from two clusters; vertex indices shared, some positions
// repeated under another index. The last cluster's coordinates reach 2^1021 (whole-line slabs).
Mesh slab_soup(std::mt19937_64& rng, int triangles, int per_cluster) {
  constexpr std::pair<double, double> kClusters[] = {{0, 1},         {1e15, 1},          {-1e15, 1e3},  {1e15, 4},
                                                     {0, 0x1p-1000}, {0x1p-990, 0x1p-1000}, {0, 1e-300}, {0, 0x1p1021}};
  constexpr int kCount = std::ssize(kClusters);
  Mesh m;
  for (const auto& [o, s] : kClusters)
    for (int k = 0; k < per_cluster; ++k) {
      if (k > 0 && rng() % 8 == 0) {
        m.vertex(m.V.back());  // the same position, another index
        continue;
      }
      m.vertex({o + s * uniform(rng, -1, 1), o - s * uniform(rng, -1, 1), -o + s * uniform(rng, -1, 1)});
    }
  for (int t = 0; t < triangles; ++t) {
    const int c = below(rng, kCount), d = rng() % 10 == 0 ? below(rng, kCount) : c;
    m.tri(c * per_cluster + below(rng, per_cluster), c * per_cluster + below(rng, per_cluster),
          d * per_cluster + below(rng, per_cluster));
  }
  return m;
}

// Vertex boxes around V: each coordinate, or it and the next double above it.
std::vector<P> upper_bounds(const std::vector<P>& V, std::mt19937_64& rng) {
  std::vector<P> hi = V;
  for (P& p : hi)
    for (double& x : p)
      if (rng() % 2) x = std::nextafter(x, std::numeric_limits<double>::infinity());
  return hi;
}

bool bitwise_equal(const tritri::DirectionSlabs& a, const tritri::DirectionSlabs& b) {
  return std::memcmp(a.lo.data(), b.lo.data(), sizeof(float) * a.lo.size()) == 0 &&
         std::memcmp(a.hi.data(), b.hi.data(), sizeof(float) * a.hi.size()) == 0;
}

// The reference: direction_slabs of triangle t's corners (points, or boxes lo .. hi).
tritri::DirectionSlabs reference_slabs(std::span<const P> lo, std::span<const P> hi, const Ids& f, bool boxes) {
  if (!boxes) return tritri::direction_slabs(lo[f[0]], lo[f[1]], lo[f[2]]);
  return tritri::direction_slabs({lo[f[0]], lo[f[1]], lo[f[2]]}, {hi[f[0]], hi[f[1]], hi[f[2]]});
}

TEST(TriangleSlabsOnDemand, GetReturnsEachTrianglesSlabsBitwiseFromConcurrentCalls) {
  std::mt19937_64 rng(seed_for(0x6b36));
  const Mesh m = slab_soup(rng, static_cast<int>(tritri_test::scaled_count(4000)), 60);
  const std::vector<P> Vhi = upper_bounds(m.V, rng);
  const std::size_t n = m.F.size();
  constexpr std::size_t kCalls = 4;  // per triangle and round
  tbb::task_arena arena(2);
  for (bool boxes : {false, true}) {
    SCOPED_TRACE(boxes ? "vertex boxes" : "points");
    const std::span<const P> lo(m.V), hi = boxes ? std::span<const P>(Vhi) : lo;
    std::vector<tritri::DirectionSlabs> expected(n);
    for (std::size_t t = 0; t < n; ++t) expected[t] = reference_slabs(lo, hi, m.F[t], boxes);
    long long infinite = 0;  // slabs of the whole line (the 2^1021 cluster)
    for (const auto& s : expected) infinite += std::isinf(s.lo[0]);
    EXPECT_GT(infinite, 0);
    EXPECT_LT(infinite, static_cast<long long>(n));
    for (int round = 0; round < 40; ++round) {
      const tritri::TriangleSlabsOnDemand slabs(lo, hi, std::span<const Ids>(m.F));
      std::atomic<long long> wrong{0};
      arena.execute([&] {
        // Calls c and c + n ask for one triangle: the two halves of the range, on two threads,
        // meet each triangle at about the same time.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kCalls * n, 32), [&](const auto& r) {
          for (std::size_t c = r.begin(); c < r.end(); ++c) {
            tritri::DirectionSlabs scratch;
            if (!bitwise_equal(slabs.get(c % n, scratch), expected[c % n])) wrong.fetch_add(1);
          }
        });
      });
      ASSERT_EQ(wrong.load(), 0) << "round " << round;
      for (std::size_t t = 0; t < n; ++t) {  // every triangle now stored
        tritri::DirectionSlabs scratch;
        const tritri::DirectionSlabs& s = slabs.get(t, scratch);
        ASSERT_TRUE(bitwise_equal(s, expected[t])) << "triangle " << t << " once stored";
        ASSERT_NE(&s, &scratch) << "triangle " << t << " computed again after its first use";
      }
    }
  }
}

TEST(TriangleSlabsOnDemand, ApartIsApartBySlabsOfTheDirectionSlabsOnEveryPair) {
  std::mt19937_64 rng(seed_for(0x6b37));
  for (int trial = 0; trial < 3; ++trial) {
    const Mesh m = slab_soup(rng, 240, 12 + 8 * trial);  // few vertices: many shared corners
    const std::vector<P> Vhi = upper_bounds(m.V, rng);
    const std::size_t n = m.F.size();
    for (bool boxes : {false, true}) {
      SCOPED_TRACE(std::string(boxes ? "vertex boxes" : "points") + ", trial " + std::to_string(trial));
      const std::span<const P> lo(m.V), hi = boxes ? std::span<const P>(Vhi) : lo;
      std::vector<tritri::DirectionSlabs> s(n);
      for (std::size_t t = 0; t < n; ++t) s[t] = reference_slabs(lo, hi, m.F[t], boxes);
      std::vector<char> expected(n * n);
      long long apart = 0, sharing = 0, overlapping = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
          if (i == j) continue;
          expected[i * n + j] = tritri::apart_by_slabs(m.F[i], m.F[j], s[i], s[j]);
          apart += expected[i * n + j];
          sharing += common_value(m.F[i], m.F[j]);
          overlapping += !expected[i * n + j] && !common_value(m.F[i], m.F[j]);
        }
      EXPECT_GT(apart, 0);
      EXPECT_GT(sharing, 0);
      EXPECT_GT(overlapping, 0);
      const tritri::TriangleSlabsOnDemand slabs(lo, hi, std::span<const Ids>(m.F));
      std::atomic<long long> wrong{0};
      tbb::task_arena arena(2);
      arena.execute([&] {  // first uses, concurrently
        tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
          for (std::size_t j = 0; j < n; ++j)
            if (i != j && slabs.apart(i, j) != static_cast<bool>(expected[i * n + j])) wrong.fetch_add(1);
        });
      });
      EXPECT_EQ(wrong.load(), 0) << "first uses";
      for (std::size_t i = 0; i < n; ++i)  // stored slabs
        for (std::size_t j = 0; j < n; ++j)
          if (i != j) {
            ASSERT_EQ(slabs.apart(i, j), static_cast<bool>(expected[i * n + j])) << i << ", " << j;
          }
    }
  }
}

}  // namespace
