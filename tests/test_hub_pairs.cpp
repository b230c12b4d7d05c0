// Specification of tritri::for_each_candidate_pair (tritri/hub_pairs.h) against an exhaustive
// oracle: the pairs of tritri::for_each_overlapping_pair (same groups), each judged exactly
// (meet_only_in_shared / meet_in_shared_in_projection when they answer, else classify):
//   1. every visited pair (i, j) has i < j, is visited once and is a pair of
//      for_each_overlapping_pair (so never two triangles of one caller group);
//   2. a pair of for_each_overlapping_pair that is not visited meets only in the vertices
//      the two share by index (classify: only VA_ON_VB points at shared indices);
//   3. the visited set is the same for threads 1, 2 and 0.
// Generators (800 meshes, ~28M judged pairs at TRITRI_TEST_SCALE=1): flat caps (n = 32..2000,
// radii constant or 1e-6..1e3 relative) alone or with a second cap around the same apex turned
// in its plane or in another plane, or around a nearby apex; cones, double cones, cones with
// a base cap; fans winding two or three times, flat or folded; wedges in random 3D directions
// (lengths 1e-6..1e3 relative); coplanar lattice wedges, spokes along one direction at several
// distances; wedges up to 2^-51 short of pi crossed through their middle, along or beside
// their edges; several hubs sharing triangles (different or equal degrees). Added at random:
// triangles from outside the star (crossing the fan near the hub, a vertex at the hub's
// position under another index, sharing a rim edge or a spoke) and caller groups. Placement:
// scaled by 2^k, k in {-60, -20, 0, 20, 60} (sometimes -1040 or 960), translated by 0, 1e6,
// 1e12 or 2^40 + small, before scaling (exact for lattices and integer shifts) or after (the
// oracle judges the rounded doubles); triangles that became degenerate are dropped. Also: fans
// of 20000 and 100000 wedges get at most 4 n pairs (for_each_overlapping_pair: n^2 / 2);
// degree 31 is no hub, 32 is; degenerate wedges on a hub.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <tritri/box_pairs.h>
#include <tritri/hub_pairs.h>
#include <tritri/tritri.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri_test::Rng;
using tritri_test::scaled_count;
using tritri_test::seed_for;
using P = std::array<double, 3>;
using Ids = std::array<int, 3>;
using Pairs = std::vector<std::pair<int, int>>;
constexpr double kPi = std::numbers::pi;
constexpr int kHub = tritri::detail::hub_pairs::kHubDegree;
static_assert(kHub == 32);

struct Mesh {
  std::vector<P> V;
  std::vector<Ids> F;
  std::vector<std::int64_t> group;  // empty or one per triangle
  int vertex(const P& p) { return V.push_back(p), static_cast<int>(V.size()) - 1; }
  void tri(int a, int b, int c) { F.push_back({a, b, c}); }
};

template <class Search>
Pairs collect(const Search& search) {
  tbb::enumerable_thread_specific<Pairs> found;  // visit runs on several threads
  search([&found](int i, int j) { found.local().emplace_back(i, j); });
  Pairs all;
  for (const Pairs& p : found) all.insert(all.end(), p.begin(), p.end());
  std::sort(all.begin(), all.end());  // repeats kept: they are checked
  return all;
}
Pairs pairs(const Mesh& m, int threads, bool hubs) {
  const std::span<const P> V(m.V);
  const std::span<const Ids> F(m.F);
  const std::span<const std::int64_t> group(m.group);
  return collect([&](const auto& visit) {
    hubs ? tritri::for_each_candidate_pair(V, F, threads, group, visit)
         : tritri::for_each_overlapping_pair(V, F, threads, group, visit);
  });
}
Pairs box_pairs(const Mesh& m, int threads) { return pairs(m, threads, false); }
Pairs hub_pairs(const Mesh& m, int threads) { return pairs(m, threads, true); }

std::array<P, 3> corners(const Mesh& m, int t) { return {m.V[m.F[t][0]], m.V[m.F[t][1]], m.V[m.F[t][2]]}; }
tritri::Result classify(const Mesh& m, int i, int j) {
  const auto a = corners(m, i), b = corners(m, j);
  return tritri::classify<tritri::DoubleKernel>(a[0], a[1], a[2], b[0], b[1], b[2]);
}

// The oracle: true when triangles i and j meet elsewhere than in vertices shared by index.
bool meets_beyond_shared(const Mesh& m, int i, int j) {
  const Ids &ia = m.F[i], &ib = m.F[j];
  const tritri::DoubleKernel k;
  const auto a = corners(m, i), b = corners(m, j);  // proper triangles: place() dropped the others
  if (tritri::meet_only_in_shared(k, a, ia, b, ib) || tritri::meet_in_shared_in_projection(k, a, ia, b, ib))
    return false;
  const tritri::Result r = classify(m, i, j);
  if (r.degenerate) return true;
  for (const auto& p : r.points)
    if (p.type != tritri::Type::VA_ON_VB || ia[p.id0] != ib[p.id1]) return true;
  return false;
}

std::string describe(const Mesh& m, int i, int j) {
  std::ostringstream os;
  for (int t : {i, j})
    os << "\n  T" << t << " = {" << m.F[t][0] << ", " << m.F[t][1] << ", " << m.F[t][2] << "} "
       << tritri_test::to_hex(tritri_test::Triangle(corners(m, t))) << (m.group.empty() ? "" : " group ")
       << (m.group.empty() ? "" : std::to_string(m.group[t]));
  os << "\n  classify: " << classify(m, i, j);
  return os.str();
}

struct Stats {  // meshes, triangles, pairs: of the boxes, visited, skipped; visited that meet (in a star)
  long long cases = 0, triangles = 0, box = 0, hub = 0, skipped = 0, required = 0, required_in_star = 0;
};

// "" when for_each_candidate_pair keeps its promise on m, else the first violation.
std::string check(const Mesh& m, Stats& s) {
  const Pairs all = box_pairs(m, 2);
  Pairs seen;
  for (int threads : {1, 2, 0}) {
    const Pairs h = hub_pairs(m, threads);
    for (const auto& [i, j] : h)
      if (!(i < j)) return "visited (" + std::to_string(i) + ", " + std::to_string(j) + "): not i < j";
    if (auto it = std::adjacent_find(h.begin(), h.end()); it != h.end())
      return "visited twice:" + describe(m, it->first, it->second);
    Pairs extra;
    std::set_difference(h.begin(), h.end(), all.begin(), all.end(), std::back_inserter(extra));
    if (!extra.empty())
      return "visited a pair for_each_overlapping_pair does not:" + describe(m, extra[0].first, extra[0].second);
    if (threads == 1) seen = h;
    if (h != seen) return "threads = " + std::to_string(threads) + " visits another set than threads = 1";
  }
  std::vector<int> degree(m.V.size(), 0);
  for (const Ids& t : m.F)
    for (int v : t) ++degree[v];
  ++s.cases, s.triangles += std::ssize(m.F), s.box += std::ssize(all), s.hub += std::ssize(seen);
  std::vector<char> visited(all.size(), 0), meets(all.size(), 0);
  for (std::size_t p = 0, k = 0; p < all.size(); ++p)
    if (k < seen.size() && seen[k] == all[p]) visited[p] = 1, ++k;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, all.size()), [&](const auto& r) {
    for (std::size_t p = r.begin(); p != r.end(); ++p) meets[p] = meets_beyond_shared(m, all[p].first, all[p].second);
  });
  for (std::size_t p = 0; p < all.size(); ++p) {
    const auto [i, j] = all[p];
    if (!visited[p]) {
      ++s.skipped;
      if (meets[p]) return "missed a pair that meets beyond its shared vertices:" + describe(m, i, j);
    } else if (meets[p]) {
      ++s.required;
      bool star = false;
      for (int v : m.F[i]) star |= degree[v] >= kHub && std::find(m.F[j].begin(), m.F[j].end(), v) != m.F[j].end();
      s.required_in_star += star;
    }
  }
  return "";
}

// ---------------------------------------------------------------------------------------
// Generators. Local coordinates: lattice meshes are integers (R = 2^20 the fan radius),
// the others doubles about 1 (R = 1). Random arguments are drawn into named variables (an
// argument list has no evaluation order).

double uniform01(Rng& rng) { return 0.5 * (rng.symmetric_unit() + 1); }
double log_uniform(Rng& rng, double lo, double hi) { return lo * std::pow(hi / lo, uniform01(rng)); }
P cross(const P& u, const P& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const P& u, const P& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
P scaled(double s, const P& u) { return {s * u[0], s * u[1], s * u[2]}; }
P unit(const P& u) { return scaled(1 / std::sqrt(dot(u, u)), u); }
P random_unit(Rng& rng) {
  P p;
  do p = {rng.symmetric_unit(), rng.symmetric_unit(), rng.symmetric_unit()};
  while (dot(p, p) < 0.01 || dot(p, p) > 1);
  return unit(p);
}

// A plane through c: integer u, w, n = u x w (lattice: at() rounds to integers, exact), or
// orthonormal u, w, n (rounded doubles).
struct Frame {
  P c, u, w, n;
  bool lattice = false;
  double R = 1;  // the fan radius in these coordinates
  P at(double x, double y, double z = 0) const {
    if (lattice) x = std::round(x), y = std::round(y), z = std::round(z);
    P p;
    for (int k = 0; k < 3; ++k) p[k] = c[k] + x * u[k] + y * w[k] + z * n[k];
    return p;
  }
  P polar(double r, double theta, double z = 0) const { return at(r * std::cos(theta), r * std::sin(theta), z); }
};

Frame random_frame(Rng& rng, bool lattice, const P& c) {
  Frame f{c, {}, {}, {}, lattice, lattice ? 0x1p20 : 1.0};
  if (lattice) {
    do f.u = tritri_test::grid_point(rng, -2, 2), f.w = tritri_test::grid_point(rng, -2, 2), f.n = cross(f.u, f.w);
    while (dot(f.n, f.n) == 0);
    return f;
  }
  f.u = random_unit(rng);
  f.w = unit(cross(f.u, random_unit(rng)));
  f.n = cross(f.u, f.w);
  return f;
}
Frame with_center(Frame f, const P& c) { return f.c = c, f; }

// n wedges (hub, r_k, r_k+1) around f.c, whose ring winds `turns` times from theta0; radii
// 0 constant, 1 in [0.5, 1], 2 in 1e-6..1e3 (times R); heights z in +-fold R (0: flat).
std::vector<int> fan(Rng& rng, Mesh& m, int hub, const Frame& f, int n, double theta0, int turns, int radii,
                     double fold, bool closed = true) {
  std::vector<int> ring;
  const bool jitter = rng.percent(40);
  for (int k = 0; k < n; ++k) {
    const double theta = theta0 + turns * 2 * kPi * (k + (jitter ? 0.45 * rng.symmetric_unit() : 0)) / n;
    const double r = f.R * (radii == 0 ? 1 : radii == 1 ? 0.5 + 0.5 * uniform01(rng) : log_uniform(rng, 1e-6, 1e3));
    ring.push_back(m.vertex(f.polar(r, theta, fold * f.R * rng.symmetric_unit())));
  }
  for (int k = 0; k + (closed ? 0 : 1) < n; ++k) m.tri(hub, ring[k], ring[(k + 1) % n]);
  return ring;
}

int fan_size(Rng& rng, int n) { return rng.percent(20) ? rng.uniform(kHub - 4, kHub + 2) : rng.uniform(kHub, n); }

// Caps: one; two around one apex, the second turned in the plane or in another plane; two
// around nearby apexes (in the plane or off it).
Mesh gen_caps(Rng& rng, int n, bool lattice, const Frame& f) {
  Mesh m;
  const int hub = m.vertex(f.c), radii = rng.uniform(0, 2);
  fan(rng, m, hub, f, n, 0, 1, radii, 0, rng.percent(80));
  const int variant = rng.uniform(0, 3), size = fan_size(rng, n), radii2 = rng.uniform(0, 2);
  const double turn = variant == 2 ? 0 : rng.symmetric_unit() * kPi, d = f.R * log_uniform(rng, 1e-6, 1);
  const double x = d * rng.symmetric_unit(), y = d * rng.symmetric_unit();
  const P c2 = variant == 3 ? f.at(x, y, rng.percent(50) ? 0 : d) : f.c;
  const bool same_plane = variant == 1 || (variant == 3 && rng.percent(50));
  const Frame g = same_plane ? with_center(f, c2) : random_frame(rng, lattice, c2);
  if (variant > 0) fan(rng, m, variant == 3 ? m.vertex(c2) : hub, g, size, turn, 1, radii2, 0);
  return m;
}

// Cones (apex at height h over a ring), double cones, cones with a base cap.
Mesh gen_cones(Rng& rng, int n, const Frame& f) {
  Mesh m;
  double h = f.R * log_uniform(rng, 1e-6, 1e3);
  if (f.lattice) h = std::max(1.0, std::round(h / std::sqrt(dot(f.n, f.n))));
  const int apex = m.vertex(f.at(0, 0, h));
  const std::vector<int> ring = fan(rng, m, apex, f, n, 0, 1, rng.uniform(0, 1), 0);
  const int variant = rng.uniform(0, 2);  // 1: a second apex below, 2: a base cap
  if (variant > 0) {
    const int below = m.vertex(f.at(0, 0, variant == 1 ? -h * log_uniform(rng, 1e-3, 1e3) : 0));
    for (int k = 0; k < n; ++k) m.tri(below, ring[(k + 1) % n], ring[k]);
  }
  return m;
}

// Fans whose ring winds two or three times (wedges overlap), flat or folded out of plane.
Mesh gen_winding(Rng& rng, int n, const Frame& f) {
  Mesh m;
  const double fold = rng.percent(50) ? 0 : log_uniform(rng, 1e-9, 1);
  const int turns = rng.uniform(2, 3), radii = rng.uniform(0, 2);
  fan(rng, m, m.vertex(f.c), f, n, 0, turns, radii, fold, rng.percent(80));
  return m;
}

// Wedges in random 3D directions around the hub, lengths 1e-6..1e3; some share a spoke
// with the previous wedge; sometimes all close to one plane.
Mesh gen_random_wedges(Rng& rng, int n) {
  Mesh m;
  const int hub = m.vertex({0, 0, 0});
  const double flat = rng.percent(30) ? log_uniform(rng, 1e-9, 1e-2) : 1;
  auto spoke = [&] {
    P d = random_unit(rng);
    d[2] *= flat;
    return m.vertex(scaled(log_uniform(rng, 1e-6, 1e3), d));
  };
  int last = spoke();
  for (int k = 0; k < n; ++k) {
    const int a = rng.percent(30) ? last : spoke();
    last = spoke();
    m.tri(hub, a, last);
  }
  return m;
}

// Exactly coplanar wedges on a lattice plane: spokes along a few integer directions at
// several distances (collinear spokes), wedges between random spokes; some wedges leave
// the plane.
Mesh gen_coplanar(Rng& rng, int n, const Frame& f) {
  Mesh m;
  const int hub = m.vertex(f.c);
  std::vector<std::array<int, 2>> dirs;
  for (int k = rng.uniform(3, 12); k > 0; --k) {
    const int x = rng.uniform(-8, 8), y = rng.uniform(-8, 8);
    if (x != 0 || y != 0) dirs.push_back({x, y});
  }
  std::vector<int> spokes;
  for (int k = 0; k < n / 2 + 2; ++k) {
    const auto d = dirs[rng.uniform(0, static_cast<int>(dirs.size()) - 1)];
    const double s = std::round(log_uniform(rng, 1, 1 << 20));
    spokes.push_back(m.vertex(f.at(s * d[0], s * d[1], rng.percent(15) ? rng.uniform(-3, 3) : 0)));
  }
  for (int k = 0; k < n; ++k) {
    const int a = spokes[rng.uniform(0, static_cast<int>(spokes.size()) - 1)];
    m.tri(hub, a, spokes[rng.uniform(0, static_cast<int>(spokes.size()) - 1)]);
  }
  return m;
}

// Wedges of nearly pi, (X s, s, 0) to (-X' s', s', 0) with X = 2^1..2^52 (arcs up to 2^-51
// short of pi: the tangent box, and the whole sphere below 1 + cos = 2^-20), crossed by
// vertical wedges (tx, ty, +-z) through the middle (0, 1), along an edge (X, 1) or one
// lattice step beside it, or elsewhere; several lattice frames around one hub.
Mesh gen_antipodal(Rng& rng, int n, int exponent = 0) {  // exponent: X = 2^exponent + {-1, 0, 1} only
  Mesh m;
  const int hub = m.vertex({0, 0, 0});
  Frame f = random_frame(rng, true, {0, 0, 0});
  double X = 2;
  for (int k = 0; k < n; ++k) {
    if (rng.percent(10)) f = random_frame(rng, true, {0, 0, 0});
    if (rng.percent(3)) f.u = {1, 0, 0}, f.w = {0, 1, 0}, f.n = {0, 0, 1};  // an axis plane
    if (k % 2 == 0) {
      const int e = exponent ? exponent : rng.uniform(1, rng.percent(50) ? 24 : 52);
      X = std::ldexp(1.0, e) + rng.uniform(-1, 1);
      const double s = rng.uniform(1, 4), s2 = rng.uniform(1, 4), X2 = X + (rng.percent(50) ? 0 : rng.uniform(-1, 1));
      m.tri(hub, m.vertex(f.at(X * s, s)), m.vertex(f.at(-X2 * s2, s2)));
      continue;
    }
    const double q = std::ldexp(1.0, rng.uniform(0, std::max(0, 52 - std::ilogb(X)) / 4));
    const int kind = rng.uniform(0, 3);  // the middle; along or beside one edge, the other; elsewhere
    const double tx = kind == 0 ? 0 : kind == 3 ? rng.uniform(-9, 9) : (kind == 1 ? X : -X) * q;
    const double ty = kind == 0 ? q : kind == 3 ? rng.uniform(-9, 9) : q + rng.uniform(-1, 1);
    const double z = rng.uniform(1, 1 << 12), e = rng.percent(50) ? 0 : rng.uniform(-2, 2);
    m.tri(hub, m.vertex(f.at(tx + e, ty, z)), m.vertex(f.at(tx - e, ty, -z)));
  }
  return m;
}

// Several hubs sharing triangles: hub j is a rim vertex of hub i's fan, so the wedges
// (hub i, hub j, r) are incident to both; degrees differ or tie.
Mesh gen_multi_hub(Rng& rng, int n, bool lattice) {
  Mesh m;
  Frame f = random_frame(rng, lattice, {0, 0, 0});
  std::vector<int> hubs{m.vertex(f.c)};
  const int count = rng.uniform(2, 4), tie = rng.percent(30) ? rng.uniform(kHub, n) : 0;
  for (int h = 0; h < count; ++h) {
    const int size = tie ? tie : rng.uniform(kHub, n);
    f = random_frame(rng, lattice, m.V[hubs[h]]);
    const int radii = rng.uniform(0, 2);
    const std::vector<int> ring = fan(rng, m, hubs[h], f, size, 0, 1, radii, rng.percent(50) ? 0 : 0.1);
    if (h + 1 < count) hubs.push_back(ring[rng.uniform(0, size - 1)]);
    for (int k = rng.uniform(0, 4); k > 0 && h > 0; --k) {  // more triangles on hub h-1 and hub h
      const double r = f.R * uniform01(rng);
      m.tri(hubs[h - 1], hubs[h], m.vertex(f.polar(r, 2 * kPi * uniform01(rng), f.R / 2)));
    }
  }
  return m;
}

// Triangles from outside the star of the hub (vertex 0): crossing the fan near the hub, a
// vertex at the hub's position under another index (crossing or in the plane), sharing a
// rim edge or a spoke (folded back into the plane or out of it).
void add_outside(Rng& rng, Mesh& m, const Frame& f, int count) {
  const int wedges = static_cast<int>(m.F.size());
  for (int k = 0; k < count; ++k) {
    const double eps = f.R * log_uniform(rng, 1e-9, 1e-1), th = 2 * kPi * uniform01(rng), r = f.R * uniform01(rng);
    const double z = rng.percent(30) ? 0 : f.R * log_uniform(rng, 1e-6, 1) / (f.lattice ? 8 : 1);
    const Ids w = m.F[rng.uniform(0, wedges - 1)];
    switch (rng.uniform(0, 3)) {
      case 0: {  // crossing near the hub
        const P c = f.polar(eps, th);
        const Frame g = with_center(f, c);
        m.tri(m.vertex(g.at(r, 0, z + 1)), m.vertex(g.at(-r, eps, -z - 1)), m.vertex(g.at(eps, r, -z - 1)));
        break;
      }
      case 1:  // a vertex at the hub's position, another index
        m.tri(m.vertex(m.V[0]), m.vertex(f.polar(r, th, z)), m.vertex(f.polar(r, th + uniform01(rng), -z)));
        break;
      case 2:  // sharing a rim edge
        m.tri(w[2], w[1], m.vertex(f.polar(r * uniform01(rng), th, z)));
        break;
      default:  // sharing a spoke: joins the star
        m.tri(w[0], w[rng.uniform(1, 2)], m.vertex(f.polar(r, th, z)));
    }
  }
}

// Caller groups: none, all -1, runs of consecutive triangles with their own ids, scattered
// small ids, long runs (a whole fan), huge ids.
void add_groups(Rng& rng, Mesh& m) {
  const int mode = rng.uniform(0, 4);
  if (mode == 0) return;
  m.group.assign(m.F.size(), -1);
  const std::int64_t base = mode == 4 ? (std::int64_t(1) << 50) : 0;
  for (std::size_t t = 0; t < m.F.size();) {
    const std::size_t end = std::min(m.F.size(), t + rng.uniform(1, mode == 3 ? 200 : 12));
    const std::int64_t id = mode == 2 ? rng.uniform(0, 3) : static_cast<std::int64_t>(t);
    if (rng.percent(mode == 1 ? 0 : 50))
      for (std::size_t i = t; i < end; ++i) m.group[i] = base + id;
    t = end;
  }
}

// Scales by 2^k and translates by T (before scaling: exact for lattices; or after: rounded);
// drops the triangles that became degenerate. Returns a label.
std::string place(Rng& rng, Mesh& m, bool lattice) {
  static constexpr int kScales[] = {-60, -20, 0, 20, 60, -1040, 960};
  static constexpr double kShifts[] = {0, 1e6, 1e12, 0x1p40 + 3, 0x1p40 + 0.5, 0x1p40 + 0x1p-12};
  const int k = kScales[rng.percent(5) ? rng.uniform(5, 6) : rng.uniform(0, 4)];
  const double shift = kShifts[rng.percent(40) ? 0 : rng.uniform(1, 5)];
  const bool before = lattice ? rng.percent(70) : rng.percent(30);
  P T;
  for (double& x : T) {
    const double sign = rng.percent(50) ? 1 : -1;
    x = sign * shift * (1 + rng.uniform(0, 7) * 0.125);
  }
  for (P& p : m.V)
    for (int a = 0; a < 3; ++a) p[a] = before ? std::ldexp(p[a] + T[a], k) : std::ldexp(p[a], k) + T[a];
  std::vector<Ids> F;
  std::vector<std::int64_t> group;
  for (std::size_t t = 0; t < m.F.size(); ++t) {
    const auto c = corners(m, static_cast<int>(t));
    if (tritri::projection(tritri::DoubleKernel{}, c[0], c[1], c[2]).second == 0) continue;
    F.push_back(m.F[t]);
    if (!m.group.empty()) group.push_back(m.group[t]);
  }
  m.F = std::move(F);
  m.group = std::move(group);
  std::ostringstream os;
  os << "2^" << k << (before ? " * (p + " : " * p + ") << shift << (before ? ")" : "");
  return os.str();
}

constexpr const char* kFamilies[] = {"caps", "cones", "winding", "random 3D", "coplanar", "near pi", "multi-hub"};
constexpr int kFamilyCount = std::ssize(kFamilies);

TEST(HubPairs, VisitsEveryPairThatMeetsBeyondItsSharedVerticesOnGeneratedStars) {
  Rng rng(seed_for(0x4b0b));
  const long long cases = scaled_count(800);
  Stats stats[kFamilyCount];
  int failures = 0;
  for (long long c = 0; c < cases && failures < 5; ++c) {
    const int family = static_cast<int>(c % kFamilyCount);
    const int n = c % 400 == 0 || c % 400 == 9 ? 2000  // caps, winding
                  : c % 41 == 3                   ? rng.uniform(500, 1000)
                                                  : static_cast<int>(log_uniform(rng, 32, 300));
    const bool lattice = family == 4 || family == 5 || (family != 3 && rng.percent(50));
    const Frame f = random_frame(rng, lattice, lattice ? tritri_test::grid_point(rng, -5, 5) : P{0, 0, 0});
    Mesh m = family == 0   ? gen_caps(rng, n, lattice, f)
             : family == 1 ? gen_cones(rng, n, f)
             : family == 2 ? gen_winding(rng, n, f)
             : family == 3 ? gen_random_wedges(rng, n)
             : family == 4 ? gen_coplanar(rng, n, f)
             : family == 5 ? gen_antipodal(rng, n)
                           : gen_multi_hub(rng, n, lattice);
    if (rng.percent(40)) add_outside(rng, m, with_center(f, m.V[0]), rng.uniform(1, n / 4 + 1));
    if (rng.percent(40)) add_groups(rng, m);
    const std::string where = place(rng, m, lattice);
    if (m.F.size() < 2) continue;
    const std::string error = check(m, stats[family]);
    if (!error.empty() && ++failures)
      ADD_FAILURE() << "case " << c << " (" << kFamilies[family] << ", n = " << n << ", "
                    << (lattice ? "lattice" : "doubles") << ", " << where << ", " << m.F.size()
                    << " triangles): " << error;
  }
  // The oracle is not vacuous: in each family pairs were skipped (checked to meet only in
  // shared vertices) and pairs of one star that really meet were visited.
  Stats total;
  for (int fam = 0; fam < kFamilyCount; ++fam) {
    const Stats& s = stats[fam];
    std::printf(
        "%-9s %4lld meshes %7lld triangles %9lld box pairs %8lld visited %9lld skipped %8lld meet, %lld in a star\n",
        kFamilies[fam], s.cases, s.triangles, s.box, s.hub, s.skipped, s.required, s.required_in_star);
    EXPECT_GT(s.skipped, 0) << kFamilies[fam];
    EXPECT_GT(s.required_in_star, 0) << kFamilies[fam];
    total.cases += s.cases, total.box += s.box, total.skipped += s.skipped;
  }
  EXPECT_GT(total.cases, cases * 8 / 10);
  EXPECT_GT(total.skipped, total.box / 3);
}

// Wedges nearly pi wide for every X = 2^1..2^52 (1 + cos from 1/2 down to 2^-103, either
// side of the whole-sphere threshold 2^-20), each mesh placed as above.
TEST(HubPairs, WedgesNearlyPiWideAtEveryExponent) {
  Rng rng(seed_for(0x91));
  Stats s;
  for (int e = 1; e <= 52; ++e)
    for (long long trial = 0; trial < scaled_count(6); ++trial) {
      Mesh m = gen_antipodal(rng, 96, e);
      const std::string where = place(rng, m, true);
      ASSERT_EQ(check(m, s), "") << "X = 2^" << e << ", " << where;
    }
  EXPECT_GT(s.required_in_star, 0);
}

// A flat fan of n wedges around the origin in the plane z = 0, rim radius 1.
Mesh flat_fan(int n) {
  Mesh m;
  m.vertex({0, 0, 0});
  for (int k = 0; k < n; ++k) m.vertex({std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n), 0});
  for (int k = 0; k < n; ++k) m.tri(0, 1 + k, 1 + (k + 1) % n);
  return m;
}

// Visited pairs of a big fan: near-linear, valid, and the oracle on a sample of the
// n^2 / 2 pairs of for_each_overlapping_pair (all of which overlap: the boxes hold the hub).
void check_big_fan(int n, bool count_box_pairs) {
  const Mesh m = flat_fan(n);
  const Pairs h = hub_pairs(m, 2);
  EXPECT_LE(h.size(), 4u * n) << n;
  EXPECT_EQ(hub_pairs(m, 0), h) << n;
  EXPECT_EQ(std::adjacent_find(h.begin(), h.end()), h.end()) << n;
  for (const auto& [i, j] : h) ASSERT_LT(i, j);
  if (count_box_pairs) {
    EXPECT_EQ(hub_pairs(m, 1), h) << n;
    tbb::enumerable_thread_specific<long long> count(0);
    tritri::for_each_overlapping_pair(std::span<const P>(m.V), std::span<const Ids>(m.F), 0, {},
                                      [&count](int, int) { ++count.local(); });
    EXPECT_EQ(count.combine(std::plus<>()), static_cast<long long>(n) * (n - 1) / 2);
  }
  Rng rng(seed_for(n));
  for (int s = 0; s < scaled_count(20000); ++s) {
    int i = rng.uniform(0, n - 1), j = rng.uniform(0, n - 1);
    if (i == j) continue;
    if (i > j) std::swap(i, j);
    if (!std::binary_search(h.begin(), h.end(), std::pair{i, j})) {
      ASSERT_FALSE(meets_beyond_shared(m, i, j)) << describe(m, i, j);
    }
  }
  for (int k = 0; k < n; ++k)  // neighbours share a spoke: their arcs touch
    ASSERT_TRUE(std::binary_search(h.begin(), h.end(), std::pair{std::min(k, (k + 1) % n), std::max(k, (k + 1) % n)}))
        << k;
}

TEST(HubPairs, PairCountsAreNearLinearOnBigFlatFans) {
  check_big_fan(20000, true);
  check_big_fan(100000, false);
}

// The hub threshold: 31 wedges are no hub (all box pairs), 32 are.
TEST(HubPairs, DegreeThirtyOneIsNoHubThirtyTwoIs) {
  for (int n : {kHub - 1, kHub}) {
    const Mesh m = flat_fan(n);
    const Pairs h = hub_pairs(m, 1), all = box_pairs(m, 1);
    ASSERT_EQ(all.size(), std::size_t(n) * (n - 1) / 2);
    EXPECT_TRUE(n < kHub ? h == all : h.size() < all.size() / 4) << n << ": " << h.size() << " pairs";
    Stats s;
    EXPECT_EQ(check(m, s), "");
  }
}

// Degenerate wedges on the hub (the oracle above never sees them: classify does not judge
// them): a spoke (hub, a, b) with a, b on one ray, or on opposite rays, or with a at the
// hub's position under another index, inside a flat fan; the segment meets the wedges
// around its direction beyond the hub, so those pairs must be visited (the arc box is a
// point, or the whole sphere).
TEST(HubPairs, DegenerateWedgesOnTheHubMeetTheWedgesAroundTheirDirection) {
  for (int variant = 0; variant < 3; ++variant)
    for (int k = 0; k < 64; k += 7) {
      Mesh m = flat_fan(64);
      const double th = 2 * kPi * (k + 0.5) / 64;  // the middle of wedge k
      const P d{std::cos(th) / 8, std::sin(th) / 8, 0};
      const int a = variant == 2 ? m.vertex({0, 0, 0}) : m.vertex(scaled(variant == 0 ? 1 : -1, d));
      m.tri(0, a, m.vertex(scaled(2, d)));  // triangle 64
      const Pairs h = hub_pairs(m, 1), all = box_pairs(m, 1);
      EXPECT_TRUE(std::binary_search(h.begin(), h.end(), std::pair{k, 64})) << variant << " " << k;
      const bool opposite = std::binary_search(h.begin(), h.end(), std::pair{(k + 32) % 64, 64});
      EXPECT_TRUE(variant != 1 || opposite) << k;  // the opposite ray meets wedge k + 32
      EXPECT_TRUE(std::includes(all.begin(), all.end(), h.begin(), h.end()));
    }
}

// Caller groups at their edges (both failed before the caller's ids were renumbered):
// (a) ids near INT64_MAX: a star's id computed above the caller's largest id overflowed and
//     could equal a caller's id, so the star's pairs with the crossing triangle were lost;
// (b) a group vector of the wrong size must throw, as for_each_overlapping_pair does, before
//     any entry is read.
TEST(HubPairs, CallerGroupIdsNearInt64MaxAndGroupVectorsOfTheWrongSize) {
  Mesh m = flat_fan(40);
  m.tri(m.vertex({0.3, 0.2, -1}), m.vertex({0.4, 0.2, 1}), m.vertex({0.3, 0.4, 1}));  // crosses the fan
  m.tri(m.vertex({5, 5, 5}), m.vertex({6, 5, 5}), m.vertex({5, 6, 5}));             // far away
  m.group.assign(m.F.size(), -1);
  m.group[40] = std::numeric_limits<std::int64_t>::max(), m.group[41] = m.group[40] - 1;
  Stats s;
  EXPECT_EQ(check(m, s), "");
  m.group.push_back(-1);  // one entry too many (no read out of bounds)
  EXPECT_THROW(box_pairs(m, 1), std::invalid_argument);
  EXPECT_THROW(hub_pairs(m, 1), std::invalid_argument);
}

}  // namespace
