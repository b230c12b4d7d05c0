// Specification of tritri::embedded_stars and share_embedded_star (tritri/embedded_stars.h). Oracle:
// tritri::classify (exact); a star is fine when every two of its triangles are proper, share at most
// two vertices, and classify reports only vertex-on-vertex points at indices both share.
//   1. Soundness: no embedded vertex has a star that is not fine, on spheres (quantized, dented),
//      grids, boxes, fans turning < 2 pi to 6 pi, double covers, folds, reversed or repeated
//      triangles, pyramids, slivers, grids perturbed in and out of plane or folded nearly flat;
//      relabeled, axes permuted and flipped, some rotated, scaled by 2^k (|k| <= 1000), translated
//      by 0, 1e12 or 2^40 + small (then rounded).
//   2. Completeness: every vertex of spheres, flat grids and boxes (sharp corners included) is
//      embedded, also after exact relabelings, symmetries, 2^k and translations.
//   3. Double covers (closed fans winding twice, open fans over 2 pi) are not embedded and the oracle
//      finds a pair meeting elsewhere; the same fans turning once are embedded.
//   4. Hand-made stars with known answers (folds, two cones at an apex, reversed or repeated
//      triangles, repeated positions, lattice pyramids 2^-60 to 2^60 high, slivers), placed as in 1.
//   5. share_embedded_star: true exactly when the two share an embedded vertex.
//   6. threads = 1, 2 and 0 give the same, predicted, answer on an 80k-triangle sphere.
#include <gtest/gtest.h>

#include <tritri/embedded_stars.h>
#include <tritri/tritri.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri_test::Rng;
using P = std::array<double, 3>;
using Ids = std::array<int, 3>;
constexpr double kPi = std::numbers::pi;
constexpr int kOctagon[8][2] = {{4, 0}, {3, 3}, {0, 4}, {-3, 3}, {-4, 0}, {-3, -3}, {0, -4}, {3, -3}};

struct Mesh {
  std::vector<P> V;
  std::vector<Ids> F;
  int vertex(const P& p) { return V.push_back(p), static_cast<int>(V.size()) - 1; }
  void tri(int a, int b, int c) { F.push_back({a, b, c}); }
};

std::vector<std::uint8_t> embedded(const Mesh& m, int threads = 1) {
  return tritri::embedded_stars(std::span<const P>(m.V), std::span<const Ids>(m.F), threads);
}
long long count(const std::vector<std::uint8_t>& e) { return std::count(e.begin(), e.end(), 1); }

std::array<P, 3> corners(const Mesh& m, int t) { return {m.V[m.F[t][0]], m.V[m.F[t][1]], m.V[m.F[t][2]]}; }
tritri::Result classify(const Mesh& m, int i, int j) {
  const auto a = corners(m, i), b = corners(m, j);
  return tritri::classify<tritri::DoubleKernel>(a[0], a[1], a[2], b[0], b[1], b[2]);
}

struct Oracle {
  const Mesh& m;
  std::vector<char> ok;                // per triangle: proper (no repeated index, not collinear)
  std::vector<std::vector<int>> star;  // per vertex: the triangles holding it
  explicit Oracle(const Mesh& mesh) : m(mesh), ok(mesh.F.size()), star(mesh.V.size()) {
    for (int t = 0; t < std::ssize(m.F); ++t) {
      const Ids& f = m.F[t];
      const auto c = corners(m, t);
      for (const auto plane : {tritri::Plane::XY, tritri::Plane::YZ, tritri::Plane::ZX})
        ok[t] |= f[0] != f[1] && f[1] != f[2] && f[0] != f[2] &&
                 tritri::orient2d(c[0], c[1], c[2], plane) != tritri::Sign::Zero;
      for (int k = 0; k < 3; ++k)
        if (std::find(f.begin(), f.begin() + k, f[k]) == f.begin() + k) star[f[k]].push_back(t);
    }
  }
  // Whether triangles i and j meet exactly in the vertices (and edge) they share by index.
  bool fine(int i, int j) const {
    const Ids &a = m.F[i], &b = m.F[j];
    int shared = 0;
    for (int u : a) shared += static_cast<int>(std::count(b.begin(), b.end(), u));
    if (!ok[i] || !ok[j] || shared == 3) return false;
    const tritri::Result r = classify(m, i, j);
    if (r.degenerate) return false;
    for (const auto& p : r.points)
      if (p.type != tritri::Type::VA_ON_VB || a[p.id0] != b[p.id1]) return false;
    return true;
  }
  // A pair of v's star that is not fine, or {-1, -1}; counts the pairs judged.
  std::pair<int, int> bad_pair(int v, long long* judged = nullptr) const {
    const auto& s = star[v];
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j)
        if (judged && ++*judged, !fine(s[i], s[j])) return {s[i], s[j]};
    return {-1, -1};
  }
  bool fine(int v) const { return bad_pair(v).first < 0; }
};

struct Tally {
  long long meshes = 0, vertices = 0, embedded = 0, bad = 0, pairs = 0;
};

// "" when no embedded vertex of m has a star the oracle rejects, else the first one.
std::string check(const Mesh& m, Tally& t) {
  const auto e = embedded(m, 1 + static_cast<int>(t.meshes % 2));
  if (e.size() != m.V.size()) return "one byte per vertex expected";
  const Oracle o(m);
  ++t.meshes;
  for (int v = 0; v < std::ssize(m.V); ++v) {
    if (e[v] > 1) return "a byte other than 0 or 1";
    const auto [i, j] = o.bad_pair(v, &t.pairs);
    ++t.vertices, t.embedded += e[v], t.bad += i >= 0;
    if (!e[v] || i < 0) continue;
    std::ostringstream os;
    os << "vertex " << v << " embedded, but two of its triangles meet elsewhere: " << classify(m, i, j);
    for (int u : {i, j}) os << "\n  T" << u << " " << tritri_test::to_hex(tritri_test::Triangle(corners(m, u)));
    return os.str();
  }
  return "";
}

double unit01(Rng& rng) { return 0.5 * (rng.symmetric_unit() + 1); }
template <class T>
void shuffle(std::vector<T>& x, Rng& rng) {
  for (int i = static_cast<int>(x.size()) - 1; i > 0; --i) std::swap(x[i], x[rng.uniform(0, i)]);
}

// m with its vertices renumbered (to[old] = new) and moved by an axis permutation and sign
// flips, its triangles shuffled and their corners rotated: the same stars.
Mesh relabeled(const Mesh& m, Rng& rng, std::vector<int>* to_out = nullptr) {
  std::vector<int> to(m.V.size());
  std::iota(to.begin(), to.end(), 0);
  shuffle(to, rng);
  const int perm = rng.uniform(0, 5), flips = rng.uniform(0, 7);
  Mesh r;
  r.V.resize(m.V.size());
  for (std::size_t i = 0; i < m.V.size(); ++i) r.V[to[i]] = tritri_test::permute_axes(m.V[i], perm, flips);
  for (const Ids& f : m.F) {
    const int s = rng.uniform(0, 2);
    r.tri(to[f[s]], to[f[(s + 1) % 3]], to[f[(s + 2) % 3]]);
  }
  shuffle(r.F, rng);
  if (to_out) *to_out = to;
  return r;
}

// Scales m by 2^k (unless that overflows or loses bits: then not) and adds d (rounded).
// Returns whether every coordinate is exact.
bool place(Mesh& m, int k, const P& d) {
  bool scalable = true, exact = true;
  for (const P& p : m.V)
    for (double x : p) scalable &= std::isfinite(std::ldexp(x, k)) && std::ldexp(std::ldexp(x, k), -k) == x;
  for (P& p : m.V)
    for (int c = 0; c < 3; ++c) {
      const double x = scalable ? std::ldexp(p[c], k) : p[c], s = x + d[c], dx = s - x;
      exact &= (x - (s - dx)) + (d[c] - dx) == 0;  // two-sum: the rounding error of x + d
      p[c] = s;
    }
  return exact;
}

// A random k keeping every nonzero coordinate of m times 2^k within 2^-limit..2^limit (the
// header scales its normal's products, so any finite magnitude must do).
int random_exponent(const Mesh& m, Rng& rng, int limit = 1000) {
  int lo = 0, hi = 0;
  for (const P& p : m.V)
    for (double x : p)
      if (x != 0) lo = std::min(lo, std::ilogb(x)), hi = std::max(hi, std::ilogb(x));
  return rng.uniform(-limit - lo, limit - hi);
}

// A random rotation (rounded): p cos a + (u x p) sin a + u (u . p)(1 - cos a).
void rotate(Mesh& m, Rng& rng) {
  const double z = rng.symmetric_unit(), phi = kPi * rng.symmetric_unit();
  const P u{std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z};
  const double a = kPi * rng.symmetric_unit(), c = std::cos(a), s = std::sin(a);
  for (P& p : m.V) {
    const double d = (u[0] * p[0] + u[1] * p[1] + u[2] * p[2]) * (1 - c);
    p = {p[0] * c + (u[1] * p[2] - u[2] * p[1]) * s + u[0] * d, p[1] * c + (u[2] * p[0] - u[0] * p[2]) * s + u[1] * d,
         p[2] * c + (u[0] * p[1] - u[1] * p[0]) * s + u[2] * d};
  }
}

double quantized(double x, double quantum) { return quantum > 0 ? std::round(x / quantum) * quantum : x; }

Mesh uv_sphere(int rings, int segs, double R, double quantum = 0) {
  Mesh m;
  const int north = m.vertex({0, 0, R});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segs; ++j) {
      const double phi = kPi * i / rings, theta = 2 * kPi * j / segs;
      m.vertex({R * std::sin(phi) * std::cos(theta), R * std::sin(phi) * std::sin(theta), R * std::cos(phi)});
    }
  const int south = m.vertex({0, 0, -R});
  for (P& p : m.V)
    for (double& x : p) x = quantized(x, quantum);
  auto at = [&](int i, int j) { return 1 + (i - 1) * segs + j % segs; };
  for (int j = 0; j < segs; ++j) {
    m.tri(north, at(1, j), at(1, j + 1));
    m.tri(south, at(rings - 1, j + 1), at(rings - 1, j));
    for (int i = 1; i + 1 < rings; ++i) {
      m.tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return m;
}

// Cell (a, b, c, d), counterclockwise, split along one diagonal or the other.
void quad(Mesh& m, int a, int b, int c, int d, bool other) {
  other ? (m.tri(a, b, c), m.tri(a, c, d)) : (m.tri(a, b, d), m.tri(b, c, d));
}

// (nx + 1) (ny + 1) vertices at(i, j); cells split along alternating diagonals.
template <class At>
Mesh grid(int nx, int ny, At&& at) {
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vertex(at(i, j));
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2);
  return m;
}
Mesh flat_grid(int n) {
  return grid(n, n, [](int i, int j) { return P{static_cast<double>(i), static_cast<double>(j), 0}; });
}

// The surface of [0, nx] x [0, ny] x [0, nz] in unit cells.
Mesh box(int nx, int ny, int nz) {
  const int N[3] = {nx, ny, nz};
  Mesh m;
  std::map<P, int> id;
  struct Face {
    int fixed, far, u, w;  // coordinate `fixed` at 0 or N, outward normal e_u x e_w
  };
  for (const Face& f :
       {Face{2, 0, 1, 0}, Face{2, 1, 0, 1}, Face{1, 0, 0, 2}, Face{1, 1, 2, 0}, Face{0, 0, 2, 1}, Face{0, 1, 1, 2}})
    for (int j = 0; j < N[f.w]; ++j)
      for (int i = 0; i < N[f.u]; ++i) {
        auto at = [&](int di, int dj) {
          P p{0, 0, 0};
          p[f.fixed] = f.far * N[f.fixed], p[f.u] = i + di, p[f.w] = j + dj;
          const auto [it, added] = id.try_emplace(p, static_cast<int>(m.V.size()));
          if (added) m.V.push_back(p);
          return it->second;
        };
        quad(m, at(0, 0), at(1, 0), at(1, 1), at(0, 1), (i + j) % 2);
      }
  return m;
}

// Vertex 0 at c, vertex 1 + i at link[i], triangles (0, 1 + i, 2 + i), closed or open.
Mesh fan(const P& c, const std::vector<P>& link, bool closed) {
  Mesh m;
  m.vertex(c);
  for (const P& p : link) m.vertex(p);
  const int n = static_cast<int>(link.size());
  for (int i = 0; i + 1 < n + closed; ++i) m.tri(0, 1 + i, 1 + (i + 1) % n);
  return m;
}
std::vector<P> octagon(double scale, double z = 0) {
  std::vector<P> link;
  for (const auto& [x, y] : kOctagon) link.push_back({scale * x, scale * y, z});
  return link;
}
void close_base(Mesh& m, int first, int n) {  // a fan under link vertices first..first + n - 1
  const int c = m.vertex({0, 0, 0});
  for (int i = 0; i < n; ++i) m.tri(c, first + (i + 1) % n, first + i);
}

// Link points of a fan turning `turn` in `steps` random steps (each under pi when
// steps > 2 turn / pi), closed (the last step back to the first point) or open.
std::vector<P> random_link(Rng& rng, int steps, double turn, bool closed, int mode) {
  std::vector<double> w(steps);
  double sum = 0, angle = 0;
  for (double& x : w) sum += x = 0.5 + 0.5 * unit01(rng);
  const double phase = 2 * kPi * unit01(rng);
  std::vector<P> link;
  for (int i = 0; i < steps + !closed; ++i) {
    const double r = mode == 2 ? 0.2 + 0.8 * unit01(rng) : 1, noise = rng.symmetric_unit();
    const double z[] = {0, 0.3 * std::sin(3 * angle + phase), 0.1 * noise, 2 * noise,
                        0.2 * std::sin(angle / 2 + phase)};
    link.push_back({r * std::cos(angle), r * std::sin(angle), z[mode]});
    if (i < steps) angle += turn * w[i] / sum;
  }
  return link;
}

struct Generator {
  const char* name;
  bool hostile;  // must yield stars the oracle rejects
  Mesh (*make)(Rng&);
};

std::vector<Generator> generators() {
  return {
      {"uv sphere (quantized, dented)", true,
       [](Rng& rng) {
         const double quanta[] = {0, 0x1p-10, 0x1p-4};
         const int rings = rng.uniform(3, 9), segs = rng.uniform(3, 12);
         Mesh m = uv_sphere(rings, segs, 1, quanta[rng.uniform(0, 2)]);
         const bool dent = rng.percent(50);  // some vertices moved along their position vector
         for (P& p : m.V) {
           const double s = dent && rng.percent(20) ? 0.3 + 1.4 * unit01(rng) : 1;
           p = {s * p[0], s * p[1], s * p[2]};
         }
         return m;
       }},
      {"flat grid", false, [](Rng& rng) { return flat_grid(rng.uniform(1, 8)); }},
      {"box", false,
       [](Rng& rng) {
         const int n = rng.uniform(0, 26);
         return box(1 + n % 3, 1 + n / 3 % 3, 1 + n / 9);
       }},
      {"fans turning < 2pi, 2pi, > 2pi, 4pi, 6pi", true,
       [](Rng& rng) {
         const int kind = rng.uniform(0, 4);
         const double s = unit01(rng);
         const double turn = std::array{0.2 + 6 * s, 2 * kPi, 2 * kPi + 0.5 * s * s * s, 4 * kPi, 6 * kPi}[kind];
         const bool closed = kind == 1 || kind >= 3;
         const int steps = std::max(rng.uniform(2, 40), static_cast<int>(2 * turn / kPi) + 1);
         return fan({0, 0, 0}, random_link(rng, steps, turn, closed, rng.uniform(0, 4)), closed);
       }},
      {"double cover", true,
       [](Rng& rng) {
         const int n = rng.uniform(9, 200);  // steps under pi
         return fan({0, 0, 0}, random_link(rng, n, 4 * kPi, true, rng.uniform(0, 4)), true);
       }},
      {"reversed or repeated triangle", true,
       [](Rng& rng) {
         const int n = rng.uniform(2, 6);
         Mesh m = rng.percent(50) ? uv_sphere(n + 1, n + 2, 1, 0x1p-10) : flat_grid(n);
         const Ids f = m.F[rng.uniform(0, static_cast<int>(m.F.size()) - 1)];
         const int what = rng.uniform(0, 2);
         what == 0 ? void(*std::find(m.F.begin(), m.F.end(), f) = {f[0], f[2], f[1]})
                   : m.F.push_back(what == 1 ? f : Ids{f[0], f[2], f[1]});
         return m;
       }},
      {"sharp or flat pyramid", false,
       [](Rng& rng) {
         const double shifts[] = {0, 0.5, 3, 1e-9};
         const double x = shifts[rng.uniform(0, 3)], y = shifts[rng.uniform(0, 3)];
         Mesh m = fan({x, y, std::ldexp(1.0, rng.uniform(-60, 60))}, octagon(1), true);
         if (rng.percent(50)) close_base(m, 1, 8);
         return m;
       }},
      {"sliver fan", true,
       [](Rng& rng) {
         std::vector<P> link;
         const double zs[] = {0, 0, 1, -1};
         for (const auto& [x, y] : kOctagon) {
           link.push_back({x * 0x1p30, y * 0x1p30, 0});
           const int t = rng.uniform(-1, 1);  // beside the ray of the last point: ahead, on it, behind
           if (rng.percent(40)) link.push_back({x * 0x1p30 - t * y, y * 0x1p30 + t * x, zs[rng.uniform(0, 3)]});
         }
         return fan({0, 0, 0}, link, rng.percent(80));
       }},
      {"grid perturbed in and out of plane", true,
       [](Rng& rng) {
         const double zs[] = {0, 0, 1, -1, 0x1p-20, -0x1p-20, 8, -8, 64};
         return grid(6, 6, [&](int i, int j) {
           P p{16.0 * i, 16.0 * j, zs[rng.uniform(0, 8)]};
           if (rng.percent(40)) p[0] += rng.uniform(-12, 12), p[1] += rng.uniform(-12, 12);
           return p;
         });
       }},
      {"grid folded nearly flat, perturbed along normal", true,
       [](Rng& rng) {
         const double zs[] = {0, 0x1p-20, -0x1p-20, 1, -1, 4, -4};
         return grid(8, 4, [&](int i, int j) {
           return P{16.0 * std::abs(i - 4), 16.0 * j, std::max(4 - i, 0) + zs[rng.uniform(0, 6)]};
         });
       }},
  };
}

// 1.
TEST(EmbeddedStars, NeverEmbeddedWhenTwoTrianglesMeetElsewhere) {
  Rng rng(tritri_test::seed_for(0xe5b5));
  const int exponents[] = {-1000, -700, -300, -60, 0, 0, 0, 20, 300, 700, 1000};
  const P offsets[] = {{0, 0, 0}, {0, 0, 0}, {1e12, -1e12, 1e12}, {0x1p40 + 3, 0x1p40 - 5, -0x1p40 + 7}};
  long long vertices = 0, embedded_vertices = 0, bad = 0;
  for (const Generator& gen : generators()) {
    Tally t;
    for (long long n = 0; n < tritri_test::scaled_count(60); ++n) {
      Mesh m = relabeled(gen.make(rng), rng);
      if (rng.percent(20)) rotate(m, rng);
      const int k = exponents[rng.uniform(0, 10)];
      place(m, k, offsets[rng.uniform(0, 3)]);
      ASSERT_EQ(check(m, t), "") << gen.name << ", case " << n;
    }
    std::printf("%-48s %3lld meshes %5lld vertices %5lld embedded %4lld bad stars %6lld pairs\n", gen.name, t.meshes,
                t.vertices, t.embedded, t.bad, t.pairs);
    EXPECT_GT(t.embedded, 0) << gen.name;
    if (gen.hostile) {
      EXPECT_GT(t.bad, 0) << gen.name << ": the generator no longer makes bad stars";
    }
    vertices += t.vertices, embedded_vertices += t.embedded, bad += t.bad;
  }
  EXPECT_GT(embedded_vertices, vertices / 3);
  EXPECT_GT(bad, vertices / 50);
}

// 2.
TEST(EmbeddedStars, EveryVertexOfCleanMeshes) {
  Rng rng(tritri_test::seed_for(0xc0e5));
  const P offsets[] = {{0x1p40 + 3, 0x1p40 - 5, -0x1p40 + 7}, {1e12, -1e12, 1e12}};
  const Mesh meshes[] = {uv_sphere(12, 16, 4, 0x1p-10),
                         uv_sphere(3, 4, 4, 0x1p-10),
                         flat_grid(12),
                         box(3, 4, 5),
                         box(1, 1, 1),
                         box(1, 9, 2)};
  long long vertices = 0, exact_translations = 0, sharp = 0;
  for (int name = 0; name < 6; ++name) {  // spheres, grid, boxes
    const Mesh& m = meshes[name];
    Tally t;
    ASSERT_EQ(check(m, t), "") << "mesh " << name;
    ASSERT_EQ(t.bad, 0) << "mesh " << name << ": the oracle rejects a star of a clean mesh";
    const auto e = embedded(m);
    EXPECT_EQ(count(e), std::ssize(m.V)) << "mesh " << name;
    for (int v = 0; v < std::ssize(m.V) && name >= 3; ++v) {
      int extremes = 0;  // 3: a corner, 2: on an edge of the box
      for (int c = 0; c < 3; ++c)
        extremes +=
            m.V[v][c] == 0 || std::none_of(m.V.begin(), m.V.end(), [&](const P& p) { return p[c] > m.V[v][c]; });
      sharp += extremes >= 2;
      EXPECT_TRUE(extremes < 2 || e[v] == 1) << "box " << name << ": corner or edge vertex " << v;
    }
    for (long long trial = 0; trial < tritri_test::scaled_count(40); ++trial) {
      const Mesh r = relabeled(m, rng);
      Mesh c = r;
      // Translated with cells of 2^k, down to 1 or 2 ulps of the offset (the fallback direction
      // q - p is scaled to |p|, so it does not round to an axis at box corners), else scaled.
      const bool translate = rng.percent(50);
      const int k = translate ? rng.uniform(-13, 40) : random_exponent(m, rng);
      const bool exact = translate && place(c, k, offsets[rng.uniform(0, 1)]);
      exact_translations += exact;
      if (!exact) c = r, place(c, k, {0, 0, 0});  // exact: scaled only when that is exact
      vertices += std::ssize(c.V);
      ASSERT_EQ(count(embedded(c, 1 + static_cast<int>(trial % 2))), std::ssize(c.V)) << "mesh " << name << ", 2^" << k;
    }
  }
  EXPECT_GT(exact_translations, tritri_test::scaled_count(40));
  EXPECT_EQ(sharp, (8 + 4 * (2 + 3 + 4)) + 8 + (8 + 4 * (0 + 8 + 1)));  // corners, inner edge vertices
  std::printf("%lld vertices of placed clean meshes, all embedded\n", vertices);
}

// 3.
TEST(EmbeddedStars, DoubleCoversAreNot) {
  for (int n : {5, 6, 7, 8, 9, 12, 16, 17, 33, 64, 101, 200})
    for (int variant = 0; variant < 3; ++variant)
      for (int winding : {2, 1}) {
        std::vector<P> link;
        for (int i = 0; i < n; ++i) {
          const double theta = 2 * kPi * winding * i / n;
          const double r = variant == 2 && i % 2 ? 0.5 : 1, z = variant == 1 ? 0.1 * std::sin(theta / 2 + 0.3) : 0;
          link.push_back({r * std::cos(theta), r * std::sin(theta), z});
        }
        const Mesh m = fan({0, 0, 0}, link, true);
        const std::string what = "n = " + std::to_string(n) + ", variant " + std::to_string(variant);
        EXPECT_EQ(Oracle(m).fine(0), winding == 1) << "oracle, " << what << ", winding " << winding;
        EXPECT_EQ(int(embedded(m)[0]), int(winding == 1)) << what << ", winding " << winding;
      }
  for (int n : {3, 4, 7, 16, 50, 200})  // open fans turning 2 pi +- delta, in a plane
    for (double delta : {0.5, 1e-3})
      for (int sign : {1, -1}) {
        std::vector<P> link;
        for (int i = 0; i <= n; ++i)
          link.push_back({std::cos((2 * kPi + sign * delta) * i / n), std::sin((2 * kPi + sign * delta) * i / n), 0});
        const Mesh m = fan({0, 0, 0}, link, false);
        EXPECT_EQ(Oracle(m).fine(0), sign < 0) << "oracle, open, n = " << n << ", turn 2 pi + " << sign * delta;
        EXPECT_EQ(int(embedded(m)[0]), int(sign < 0)) << "open, n = " << n << ", turn 2 pi + " << sign * delta;
      }
}

// 4.
// Vertex v of m: the oracle must find it `fine` or not as built, and the certificate must
// answer `expected`, also on relabeled, scaled and translated copies (each checked as in 1).
void expect_star(const Mesh& m, int v, bool fine, bool expected, const std::string& what, Rng& rng) {
  ASSERT_EQ(Oracle(m).fine(v), fine) << what << ": the oracle disagrees with the construction";
  EXPECT_EQ(int(embedded(m)[v]), int(expected)) << what;
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<int> to;
    const Mesh r = relabeled(m, rng, &to);
    Mesh c = r;
    const int k = random_exponent(m, rng);
    if (!place(c, k, {0x1p40 + 3, -1e12, 0x1p40 - 5})) c = r, place(c, k, {0, 0, 0});
    EXPECT_EQ(int(embedded(c, 2)[to[v]]), int(expected)) << what << ", placed with 2^" << k;
    Tally t;
    EXPECT_EQ(check(c, t), "") << what << ", placed with 2^" << k;
  }
}

TEST(EmbeddedStars, HandMadeStars) {
  Rng rng(tritri_test::seed_for(0x4a2d));
  const P o{0, 0, 0};
  expect_star(fan(o, octagon(4), true), 0, true, true, "flat octagon", rng);
  for (int k = 0; k < 8; ++k)  // link vertex k moved back between k - 2 and k - 1: coplanar, or lifted
    for (double lift : {0.0, 0x1p-10, -0x1p-10, 1.0, -1.0, 8.0}) {
      std::vector<P> link = octagon(4);
      link[k] = {link[(k + 6) % 8][0] + link[(k + 7) % 8][0], link[(k + 6) % 8][1] + link[(k + 7) % 8][1], lift};
      Tally t;
      if (lift == 0) expect_star(fan(o, link, true), 0, false, false, "coplanar fold at " + std::to_string(k), rng);
      EXPECT_EQ(check(fan(o, link, k % 2), t), "") << "fold at " << k << " lifted by " << lift;
    }
  expect_star(fan(o, {{4, 0, 0}, {0, 4, 0}, {3, 1, 0}}, false), 0, false, false, "open coplanar fold", rng);
  expect_star(fan(o, {{4, 0, 0}, {0, 4, 0}, {-3, 1, 0}}, false), 0, true, true, "open, unfolded", rng);
  for (int kind = 0; kind < 3; ++kind) {  // two cones at one apex: opposite, one inside the other, coincident
    Mesh m = fan(o, octagon(1, 1), true);
    expect_star(m, 0, true, true, "one cone", rng);
    const int first = static_cast<int>(m.V.size());
    for (const P& p : octagon(kind == 1 ? 0.5 : 1, kind == 0 ? -1 : 1)) m.vertex(p);
    for (int i = 0; i < 8; ++i) m.tri(0, first + (i + 1) % 8, first + i);
    expect_star(m, 0, kind != 2, false, "two cones, kind " + std::to_string(kind), rng);
  }
  for (int k = 0; k < 3; ++k) {  // a second index at a link vertex's position, at the centre's (2 fans)
    Mesh m = fan(o, octagon(4), true);
    const int dup = m.vertex(P(m.V[k == 0 ? 3 : 0])), first = k == 1 ? static_cast<int>(m.V.size()) : 1;
    if (k == 0) m.F[2][1] = dup;  // the triangle starting at link vertex 3
    for (int i = 0; i < 8 && k > 0; ++i) m.tri(dup, first + i, first + (i + 1) % 8);
    for (int i = 1; i <= 8 && k == 1; ++i) m.vertex(P(m.V[i]));
    expect_star(m, k == 2, k == 1, k == 1, "repeated position " + std::to_string(k), rng);
    if (k > 0) expect_star(m, k == 1 ? dup : 0, true, true, "one of two coincident fans", rng);
  }
  for (int k = 0; k < 3; ++k) {  // the octagon with a triangle reversed, repeated, repeated reversed
    Mesh m = fan(o, octagon(4), true);
    k == 0 ? std::swap(m.F[3][1], m.F[3][2]) : m.F.push_back(k == 1 ? m.F[3] : Ids{m.F[3][0], m.F[3][2], m.F[3][1]});
    expect_star(m, 0, k == 0, false, "reversed or repeated triangle, " + std::to_string(k), rng);
  }
  for (int k = -60; k <= 60; k += 10) {  // lattice pyramids, flat to sharp, closed by a base
    Mesh m = fan({0, 0, std::ldexp(1.0, k)}, octagon(1), true);
    close_base(m, 1, 8);
    expect_star(m, 0, true, true, "pyramid apex at 2^" + std::to_string(k), rng);
    expect_star(m, 9, true, true, "pyramid base centre, apex at 2^" + std::to_string(k), rng);
  }
  for (int t = -1; t <= 1; ++t) {  // a sliver beside the ray of link point 2: ahead, on it, behind
    std::vector<P> link = octagon(0x1p30);
    link.insert(link.begin() + 3, {link[2][0] - t * kOctagon[2][1], link[2][1] + t * kOctagon[2][0], 0});
    expect_star(fan(o, link, true), 0, t > 0, t > 0, "sliver " + std::to_string(t), rng);
  }
}

// 5.
TEST(EmbeddedStars, ShareEmbeddedStar) {
  Mesh m = flat_grid(6);
  const int t0 = 2 * (3 * 6 + 3);  // an interior triangle, reversed: its corners are not embedded
  std::swap(m.F[t0][1], m.F[t0][2]);
  const Ids bad = m.F[t0];
  auto e = embedded(m);  // not const: e and random (below) are looped over together
  for (int v = 0; v < std::ssize(m.V); ++v)
    ASSERT_EQ(int(e[v]), int(std::find(bad.begin(), bad.end(), v) == bad.end())) << "vertex " << v;
  const Oracle o(m);
  Rng rng(tritri_test::seed_for(0x5a4e));
  std::vector<std::uint8_t> random(m.V.size());  // any bytes: "some shared vertex has a nonzero byte"
  for (auto& b : random) b = rng.percent(50);
  long long yes = 0, only_bad = 0, disjoint = 0;
  for (const auto* bytes : {&e, &random})
    for (int i = 0; i < std::ssize(m.F); ++i)
      for (int j = 0; j < std::ssize(m.F); ++j) {
        bool any = false, good = false;
        for (int u : m.F[i])
          if (std::find(m.F[j].begin(), m.F[j].end(), u) != m.F[j].end()) any = true, good |= (*bytes)[u] != 0;
        const bool got = tritri::share_embedded_star(m.F[i], m.F[j], *bytes);
        EXPECT_EQ(got, good) << "triangles " << i << ", " << j << (bytes == &e ? "" : ", random bytes");
        if (bytes != &e || i == j) continue;
        EXPECT_TRUE(!got || o.fine(i, j)) << "triangles " << i << ", " << j;
        yes += got, only_bad += any && !good, disjoint += !any;
      }
  EXPECT_GT(yes, 500);
  EXPECT_GE(only_bad, 10);
  EXPECT_GT(disjoint, 4000);
}

// 6.
TEST(EmbeddedStars, SameAnswerForAnyThreadCount) {
  Mesh m = uv_sphere(200, 200, 1);  // 39802 vertices, 79600 triangles; poles of degree 200
  ASSERT_EQ(count(embedded(m, 2)), std::ssize(m.V));
  // Reverse 3% of the triangles and every triangle at the north pole: a vertex stays embedded
  // exactly when all or none of its triangles are reversed.
  Rng rng(tritri_test::seed_for(0x7e4d));
  std::vector<int> reversed(m.V.size(), 0), degree(m.V.size(), 0);
  for (Ids& f : m.F) {
    const bool flip = f[0] == 0 || rng.percent(3);
    if (flip) std::swap(f[1], f[2]);
    for (int v : f) ++degree[v], reversed[v] += flip;
  }
  std::vector<std::uint8_t> expected(m.V.size());
  for (std::size_t v = 0; v < m.V.size(); ++v) expected[v] = reversed[v] == 0 || reversed[v] == degree[v];
  ASSERT_EQ(expected[0], 1);
  EXPECT_GT(std::ssize(m.V) - count(expected), 5000);
  for (int threads : {1, 2, 0}) EXPECT_EQ(embedded(m, threads), expected) << "threads = " << threads;
}

}  // namespace
