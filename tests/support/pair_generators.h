// tests/support/pair_generators.h
//
// Generators of triangle pairs for the classify tests, weighted towards the degenerate
// configurations that break classifiers: small integer grids, coplanar pairs, shared
// vertices and edges, vertices exactly on edges and faces, edges through exact points,
// one-ulp perturbations of all of these, extreme exponents, and plain random pairs.
//
// Every construction is exact in double arithmetic (small dyadic numbers), so a pair that
// is built to touch really touches. All randomness comes from a seeded splitmix64, so runs
// are reproducible on every platform.
//
// Also here: the exact symmetries used by the tests (axis permutations, sign flips, vertex
// rotation and reversal, swapping A and B) and hex printing.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace tritri_test {

using Point = std::array<double, 3>;
using Triangle = std::array<Point, 3>;

struct Pair {
  Triangle a;
  Triangle b;
};

// ---------------------------------------------------------------------------------------
// Printing with hex floats, so that a failing pair can be pasted back exactly.

inline std::string to_hex(const Point& p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "{%a, %a, %a}", p[0], p[1], p[2]);
  return buf;
}

inline std::string to_hex(const Triangle& t) {
  return "{" + to_hex(t[0]) + ", " + to_hex(t[1]) + ", " + to_hex(t[2]) + "}";
}

inline std::string to_decimal(const Triangle& t) {
  std::string s = "{";
  for (int i = 0; i < 3; ++i) {
    char buf[100];
    std::snprintf(buf, sizeof buf, "%s{%.17g, %.17g, %.17g}", i ? ", " : "", t[i][0], t[i][1], t[i][2]);
    s += buf;
  }
  return s + "}";
}

inline std::string describe(const Pair& p) {
  return "A = " + to_hex(p.a) + "\nB = " + to_hex(p.b) + "\n(decimal: A = " + to_decimal(p.a) +
         ", B = " + to_decimal(p.b) + ")";
}

// ---------------------------------------------------------------------------------------
// Deterministic random numbers (splitmix64; the std distributions are not portable).

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform integer in [lo, hi] (the modulo bias is irrelevant here).
  int uniform(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
  bool percent(int p) { return uniform(0, 99) < p; }
  // Uniform double in [-1, 1) with 53 random bits.
  double symmetric_unit() { return static_cast<double>(next() >> 11) * 0x1p-52 - 1.0; }

 private:
  std::uint64_t state_;
};

// ---------------------------------------------------------------------------------------
// Exact symmetries.

inline constexpr int kAxisPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

// New coordinate k is old coordinate perm[k], negated when bit k of `flips` is set.
inline Point permute_axes(const Point& p, int perm, int flips) {
  Point q;
  for (int k = 0; k < 3; ++k) {
    const double v = p[kAxisPermutations[perm][k]];
    q[k] = (flips >> k) & 1 ? -v : v;
  }
  return q;
}

inline Pair permute_axes(const Pair& p, int perm, int flips) {
  Pair q;
  for (int i = 0; i < 3; ++i) {
    q.a[i] = permute_axes(p.a[i], perm, flips);
    q.b[i] = permute_axes(p.b[i], perm, flips);
  }
  return q;
}

// (t1, t2, t0): old vertex v becomes vertex (v + 2) % 3, old edge e becomes edge (e + 2) % 3.
inline Triangle rotated(const Triangle& t) { return {t[1], t[2], t[0]}; }

// (t0, t2, t1): vertices 0->0, 1->2, 2->1; edges 0->2, 1->1, 2->0.
inline Triangle reversed(const Triangle& t) { return {t[0], t[2], t[1]}; }

inline Pair swapped(const Pair& p) { return {p.b, p.a}; }

// Applies a random exact symmetry: axis permutation, sign flips, vertex rotations and
// reversals of each triangle, and possibly swapping A and B.
inline Pair random_symmetry(const Pair& p, Rng& rng) {
  Pair q = permute_axes(p, rng.uniform(0, 5), rng.uniform(0, 7));
  for (int r = rng.uniform(0, 2); r > 0; --r) q.a = rotated(q.a);
  for (int r = rng.uniform(0, 2); r > 0; --r) q.b = rotated(q.b);
  if (rng.percent(50)) q.a = reversed(q.a);
  if (rng.percent(50)) q.b = reversed(q.b);
  if (rng.percent(50)) q = swapped(q);
  return q;
}

// Multiplies every coordinate by 2^k; returns false (and leaves `out` unspecified) when that
// is not exact (overflow, or bits lost to underflow).
inline bool scale_by_power_of_two(const Pair& p, int k, Pair& out) {
  out = p;
  for (Triangle* t : {&out.a, &out.b})
    for (Point& v : *t)
      for (double& x : v) {
        const double y = std::ldexp(x, k);
        if (!std::isfinite(y) || std::ldexp(y, -k) != x) return false;
        x = y;
      }
  return true;
}

// Adds d to every point; returns false when some sum is not exact.
inline bool translate_exactly(const Pair& p, const Point& d, Pair& out) {
  out = p;
  for (Triangle* t : {&out.a, &out.b})
    for (Point& v : *t)
      for (int k = 0; k < 3; ++k) {
        // Knuth's two-sum: the rounding error of v + d, computed exactly.
        const double s = v[k] + d[k];
        const double dv = s - v[k];
        const double vv = s - dv;
        if ((v[k] - vv) + (d[k] - dv) != 0) return false;
        v[k] = s;
      }
  return true;
}

// ---------------------------------------------------------------------------------------
// Building blocks. All arithmetic below is on small dyadic numbers and therefore exact.

inline Point add(const Point& p, const Point& q) { return {p[0] + q[0], p[1] + q[1], p[2] + q[2]}; }
inline Point sub(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
inline Point mul(double s, const Point& p) { return {s * p[0], s * p[1], s * p[2]}; }

inline Point grid_point(Rng& rng, int lo, int hi) {
  return {double(rng.uniform(lo, hi)), double(rng.uniform(lo, hi)), double(rng.uniform(lo, hi))};
}

inline Triangle grid_triangle(Rng& rng, int lo, int hi) {
  return {grid_point(rng, lo, hi), grid_point(rng, lo, hi), grid_point(rng, lo, hi)};
}

// A plane through integer point o spanned by integer vectors u, v (not parallel);
// at(s, t) = o + s u + t v is exact for the small dyadic s, t used here.
struct LatticePlane {
  Point o, u, v;
  Point at(double s, double t) const { return add(o, add(mul(s, u), mul(t, v))); }
  // A random point with s, t multiples of 1/2 in [-3, 3].
  Point random_point(Rng& rng) const { return at(rng.uniform(-6, 6) * 0.5, rng.uniform(-6, 6) * 0.5); }
  Triangle random_triangle(Rng& rng) const { return {random_point(rng), random_point(rng), random_point(rng)}; }
};

inline LatticePlane random_lattice_plane(Rng& rng) {
  if (rng.percent(30)) {  // an axis plane z = c (axis permutations make the others)
    return {{0, 0, double(rng.uniform(-2, 2))}, {1, 0, 0}, {0, 1, 0}};
  }
  for (;;) {
    LatticePlane pl{grid_point(rng, -2, 2), grid_point(rng, -2, 2), grid_point(rng, -2, 2)};
    const Point& u = pl.u;
    const Point& v = pl.v;
    const Point n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (n[0] != 0 || n[1] != 0 || n[2] != 0) return pl;
  }
}

// (w0 t0 + w1 t1 + w2 t2) / 8 for integer weights summing to 8 (exact for small coordinates).
// Positive weights give a point inside the open face; one zero weight, inside an open edge.
inline Point weighted(const Triangle& t, int w0, int w1, int w2) {
  Point p;
  for (int k = 0; k < 3; ++k) p[k] = (w0 * t[0][k] + w1 * t[1][k] + w2 * t[2][k]) * 0.125;
  return p;
}

// A point of triangle t chosen exactly: a vertex, a point inside an open edge, or a point
// inside the open face (for a non-degenerate t).
inline Point point_on_triangle(const Triangle& t, Rng& rng) {
  const int kind = rng.uniform(0, 2);
  const int i = rng.uniform(0, 2);
  if (kind == 0) return t[i];
  int w[3] = {0, 0, 0};
  if (kind == 1) {
    w[i] = rng.uniform(1, 7);
    w[(i + 1) % 3] = 8 - w[i];
  } else {
    w[0] = rng.uniform(1, 6);
    w[1] = rng.uniform(1, 7 - w[0]);
    w[2] = 8 - w[0] - w[1];
  }
  return weighted(t, w[0], w[1], w[2]);
}

// A point of the plane of t: an affine combination with weights in [-8, 16] / 8.
inline Point affine_point(const Triangle& t, Rng& rng) {
  const int w0 = rng.uniform(-8, 16);
  const int w1 = rng.uniform(-8, 16);
  return weighted(t, w0, w1, 8 - w0 - w1);
}

// Nudges one coordinate by `steps` ulps (towards +inf when steps > 0).
inline double nudge(double x, int steps) {
  for (; steps > 0; --steps) x = std::nextafter(x, INFINITY);
  for (; steps < 0; ++steps) x = std::nextafter(x, -INFINITY);
  return x;
}

// ---------------------------------------------------------------------------------------
// Generators. Each returns a pair before any symmetry is applied.

// Integer coordinates in [lo, hi]: many coincidences, collinear and coplanar subsets.
inline Pair gen_grid_wide(Rng& rng) { return {grid_triangle(rng, -3, 3), grid_triangle(rng, -3, 3)}; }
inline Pair gen_grid_tight(Rng& rng) { return {grid_triangle(rng, 0, 2), grid_triangle(rng, 0, 2)}; }

// Both triangles in one plane (an axis plane or a general lattice plane).
inline Pair gen_coplanar(Rng& rng) {
  const LatticePlane pl = random_lattice_plane(rng);
  return {pl.random_triangle(rng), pl.random_triangle(rng)};
}

// Coplanar, B's vertices exact affine combinations of A's: nested, overlapping, touching.
inline Pair gen_coplanar_overlap(Rng& rng) {
  const LatticePlane pl = random_lattice_plane(rng);
  Pair p;
  p.a = pl.random_triangle(rng);
  for (Point& v : p.b) v = rng.percent(50) ? point_on_triangle(p.a, rng) : affine_point(p.a, rng);
  return p;
}

// B's vertices besides the ones fixed by a generator: in A's plane or off it.
inline Point free_vertex(const Triangle& a, Rng& rng, bool in_plane) {
  return in_plane ? affine_point(a, rng) : grid_point(rng, -3, 3);
}

// A and B share one vertex.
inline Pair gen_shared_vertex(Rng& rng) {
  Pair p;
  p.a = rng.percent(50) ? grid_triangle(rng, -3, 3) : random_lattice_plane(rng).random_triangle(rng);
  const bool in_plane = rng.percent(40);
  p.b = {p.a[rng.uniform(0, 2)], free_vertex(p.a, rng, in_plane), free_vertex(p.a, rng, in_plane)};
  return p;
}

// A and B share two vertices (an edge), the third vertex of B in A's plane or off it.
inline Pair gen_shared_edge(Rng& rng) {
  Pair p;
  p.a = rng.percent(50) ? grid_triangle(rng, -3, 3) : random_lattice_plane(rng).random_triangle(rng);
  const int i = rng.uniform(0, 2);
  p.b = {p.a[i], p.a[(i + 1) % 3], free_vertex(p.a, rng, rng.percent(50))};
  return p;
}

// One or more vertices of B exactly on A (its vertices, open edges or open face), and
// sometimes a vertex of A exactly on B as well.
inline Pair gen_vertex_on_triangle(Rng& rng) {
  Pair p;
  p.a = rng.percent(50) ? grid_triangle(rng, -3, 3) : random_lattice_plane(rng).random_triangle(rng);
  const bool in_plane = rng.percent(40);
  const int on = rng.uniform(1, 3);
  for (int k = 0; k < 3; ++k) p.b[k] = k < on ? point_on_triangle(p.a, rng) : free_vertex(p.a, rng, in_plane);
  if (rng.percent(30)) p.a[rng.uniform(0, 2)] = point_on_triangle(p.b, rng);
  return p;
}

// An edge of B passes exactly through a point of A (vertex, open edge or open face): the
// point is the midpoint of the edge. The edge may lie in A's plane.
inline Pair gen_edge_through_point(Rng& rng) {
  Pair p;
  p.a = rng.percent(50) ? grid_triangle(rng, -3, 3) : random_lattice_plane(rng).random_triangle(rng);
  const Point c = point_on_triangle(p.a, rng);
  const bool in_plane = rng.percent(40);
  Point d = in_plane ? sub(affine_point(p.a, rng), c) : grid_point(rng, -3, 3);
  if (rng.percent(30)) d = mul(0.5, d);
  p.b = {add(c, d), sub(c, d), free_vertex(p.a, rng, in_plane && rng.percent(70))};
  return p;
}

// Both triangles have an edge through one common point (edges crossing exactly there).
inline Pair gen_edges_crossing_at_point(Rng& rng) {
  const Point c = mul(0.5, grid_point(rng, -4, 4));
  const LatticePlane pl = random_lattice_plane(rng);
  const bool coplanar = rng.percent(50);
  auto direction = [&] { return coplanar ? sub(pl.random_point(rng), pl.o) : grid_point(rng, -3, 3); };
  auto third = [&] { return coplanar ? add(c, sub(pl.random_point(rng), pl.o)) : add(c, grid_point(rng, -3, 3)); };
  const Point da = direction(), db = direction();
  Pair p;
  p.a = {add(c, da), sub(c, mul(rng.uniform(1, 3) * 0.5, da)), third()};
  p.b = {add(c, db), sub(c, mul(rng.uniform(1, 3) * 0.5, db)), third()};
  return p;
}

// Uniform random coordinates in [-1, 1): the generic case.
inline Pair gen_random(Rng& rng) {
  Pair p;
  for (Triangle* t : {&p.a, &p.b})
    for (Point& v : *t)
      for (double& x : v) x = rng.symmetric_unit();
  return p;
}

// Random triangle B whose vertices straddle A's plane near A (likely crossings).
inline Pair gen_random_near(Rng& rng) {
  Pair p = gen_random(rng);
  const Point c = weighted(p.a, 3, 3, 2);
  for (Point& v : p.b)
    for (int k = 0; k < 3; ++k) v[k] = c[k] + 0.5 * rng.symmetric_unit();
  return p;
}

// The structured generators, for composition by the ones below.
inline Pair gen_structured(Rng& rng) {
  switch (rng.uniform(0, 7)) {
    case 0:
      return gen_grid_wide(rng);
    case 1:
      return gen_grid_tight(rng);
    case 2:
      return gen_coplanar(rng);
    case 3:
      return gen_coplanar_overlap(rng);
    case 4:
      return gen_shared_vertex(rng);
    case 5:
      return gen_shared_edge(rng);
    case 6:
      return gen_vertex_on_triangle(rng);
    default:
      return gen_edge_through_point(rng);
  }
}

// A structured pair with one to three coordinates nudged by one or two ulps (near misses
// and near hits; zeros become subnormals).
inline Pair gen_perturbed(Rng& rng) {
  Pair p = gen_structured(rng);
  for (int n = rng.uniform(1, 3); n > 0; --n) {
    Triangle& t = rng.percent(50) ? p.a : p.b;
    double& x = t[rng.uniform(0, 2)][rng.uniform(0, 2)];
    x = nudge(x, rng.percent(50) ? rng.uniform(1, 2) : -rng.uniform(1, 2));
  }
  return p;
}

// A structured pair scaled exactly by 2^k, k up to +-1000 (exercises the exact fallbacks
// for huge and tiny magnitudes), and translated exactly by a dyadic vector.
inline Pair gen_scaled(Rng& rng) {
  const Pair p = gen_structured(rng);
  static constexpr int kExponents[] = {-1000, -600, -500, -300, -60, -30, 30, 60, 300, 500, 600, 1000};
  Pair q;
  const int k = rng.percent(50) ? kExponents[rng.uniform(0, 11)] : rng.uniform(-40, 40);
  if (!scale_by_power_of_two(p, k, q)) q = p;
  Pair t;
  const Point d = {std::ldexp(rng.uniform(-64, 64), k - 3), std::ldexp(rng.uniform(-64, 64), k - 3),
                   std::ldexp(rng.uniform(-64, 64), k - 3)};
  if (rng.percent(50) && translate_exactly(q, d, t)) q = t;
  return q;
}

struct NamedGenerator {
  const char* name;
  Pair (*make)(Rng&);
  int weight;  // relative frequency
};

// The generator mix used by the oracle and property tests.
inline const std::vector<NamedGenerator>& pair_generators() {
  static const std::vector<NamedGenerator> generators = {
      {"grid[-3,3]", gen_grid_wide, 8},
      {"grid[0,2]", gen_grid_tight, 8},
      {"coplanar", gen_coplanar, 10},
      {"coplanar_overlap", gen_coplanar_overlap, 10},
      {"shared_vertex", gen_shared_vertex, 8},
      {"shared_edge", gen_shared_edge, 8},
      {"vertex_on_triangle", gen_vertex_on_triangle, 10},
      {"edge_through_point", gen_edge_through_point, 10},
      {"edges_crossing_at_point", gen_edges_crossing_at_point, 8},
      {"perturbed", gen_perturbed, 8},
      {"scaled", gen_scaled, 6},
      {"random", gen_random, 3},
      {"random_near", gen_random_near, 3},
  };
  return generators;
}

// Picks a generator by weight; returns its index in pair_generators().
inline std::size_t pick_generator(Rng& rng) {
  const auto& gens = pair_generators();
  int total = 0;
  for (const auto& g : gens) total += g.weight;
  int r = rng.uniform(0, total - 1);
  for (std::size_t i = 0; i < gens.size(); ++i) {
    if (r < gens[i].weight) return i;
    r -= gens[i].weight;
  }
  return gens.size() - 1;
}

}  // namespace tritri_test
