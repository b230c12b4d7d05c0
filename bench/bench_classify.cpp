// bench/bench_classify.cpp
//
// Time per triangle pair of tritri::classify on each backend (DoubleKernel and
// CgalKernel over Epick, Epeck and Simple_cartesian<Gmpq>), with CGAL::do_intersect on
// Epick (yes/no only) as the baseline, on four pair sets built before timing from a
// fixed seed:
//   random       vertices uniform in the unit cube
//   box_overlap  small random triangles whose axis-aligned boxes overlap (what a
//                broad phase hands to the classifier)
//   shared_vertex  B's vertex 0 is A's vertex 0, the other vertices random nearby
//   coplanar     both triangles exactly in one random plane, overlapping
// One benchmark iteration classifies one pair (cycling through the set), so the Time
// column and the "ns/pair" counter are nanoseconds per pair. See bench/README.md.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "tritri/tritri.h"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using GmpqKernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

using P = std::array<double, 3>;
using Pair = std::array<P, 6>;  // a0 a1 a2 b0 b1 b2

constexpr std::size_t kPairsPerSet = 4096;  // a power of two: the loop index wraps with a mask
constexpr std::uint64_t kSeed = 20240611;

// ---------------------------------------------------------------------------------------
// Pair sets (double coordinates; every backend converts them exactly).

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g_); }
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(g_);
  }
  P in_cube(double lo, double hi) { return {real(lo, hi), real(lo, hi), real(lo, hi)}; }

 private:
  std::mt19937_64 g_;
};

P add(const P& a, const P& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

std::vector<Pair> random_pairs(Rng& r) {
  std::vector<Pair> v(kPairsPerSet);
  for (auto& p : v)
    for (auto& q : p) q = r.in_cube(0, 1);
  return v;
}

bool boxes_overlap(const Pair& p) {
  for (int k = 0; k < 3; ++k) {
    const double alo = std::min({p[0][k], p[1][k], p[2][k]}), ahi = std::max({p[0][k], p[1][k], p[2][k]});
    const double blo = std::min({p[3][k], p[4][k], p[5][k]}), bhi = std::max({p[3][k], p[4][k], p[5][k]});
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
}

// Triangles of size ~0.3 around random centers; only pairs with overlapping boxes kept.
std::vector<Pair> box_overlapping_pairs(Rng& r) {
  std::vector<Pair> v;
  while (v.size() < kPairsPerSet) {
    Pair p;
    for (int t = 0; t < 2; ++t) {
      const P c = r.in_cube(0, 1);
      for (int i = 0; i < 3; ++i) p[3 * t + i] = add(c, r.in_cube(-0.15, 0.15));
    }
    if (boxes_overlap(p)) v.push_back(p);
  }
  return v;
}

std::vector<Pair> shared_vertex_pairs(Rng& r) {
  std::vector<Pair> v(kPairsPerSet);
  for (auto& p : v) {
    for (int i = 0; i < 3; ++i) p[i] = r.in_cube(0, 1);
    p[3] = p[0];
    p[4] = add(p[0], r.in_cube(-0.5, 0.5));
    p[5] = add(p[0], r.in_cube(-0.5, 0.5));
  }
  return v;
}

// Both triangles in the plane o + s*u + t*w with o on a 2^-10 grid, u and w on a 2^-6 grid
// and (s, t) on a 2^-8 grid, so every coordinate is exact (a multiple of 2^-14 below 4)
// and all six points are exactly coplanar. B's vertex 0 is a strictly positive dyadic
// combination of A's vertices, so B meets A's interior.
std::vector<Pair> coplanar_overlapping_pairs(Rng& r) {
  using Param = std::array<std::int64_t, 2>;  // (s, t) in units of 2^-8
  auto cross2 = [](const Param& a, const Param& b, const Param& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  };
  std::vector<Pair> v;
  while (v.size() < kPairsPerSet) {
    P o, u, w;
    for (int k = 0; k < 3; ++k) {
      o[k] = std::ldexp(static_cast<double>(r.integer(0, 1024)), -10);
      u[k] = std::ldexp(static_cast<double>(r.integer(-64, 64)), -6);
      w[k] = std::ldexp(static_cast<double>(r.integer(-64, 64)), -6);
    }
    const P normal = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    if (normal[0] == 0 && normal[1] == 0 && normal[2] == 0) continue;  // exact: small integers / 2^12

    Param pa[3], pb[3];
    for (auto& q : pa) q = {16 * r.integer(0, 16), 16 * r.integer(0, 16)};
    const std::int64_t k0 = r.integer(1, 14), k1 = r.integer(1, 15 - k0), k2 = 16 - k0 - k1;
    pb[0] = {(k0 * pa[0][0] + k1 * pa[1][0] + k2 * pa[2][0]) / 16,
             (k0 * pa[0][1] + k1 * pa[1][1] + k2 * pa[2][1]) / 16};
    for (int i = 1; i < 3; ++i) pb[i] = {16 * r.integer(-8, 24), 16 * r.integer(-8, 24)};
    if (cross2(pa[0], pa[1], pa[2]) == 0 || cross2(pb[0], pb[1], pb[2]) == 0) continue;

    Pair p;
    for (int i = 0; i < 6; ++i) {
      const Param& q = i < 3 ? pa[i] : pb[i - 3];
      const double s = std::ldexp(static_cast<double>(q[0]), -8), t = std::ldexp(static_cast<double>(q[1]), -8);
      for (int k = 0; k < 3; ++k) p[i][k] = o[k] + s * u[k] + t * w[k];
    }
    v.push_back(p);
  }
  return v;
}

struct PairSet {
  std::string name;
  std::vector<Pair> pairs;
};

std::vector<PairSet> make_sets() {
  Rng r(kSeed);
  std::vector<PairSet> sets;
  sets.push_back({"random", random_pairs(r)});
  sets.push_back({"box_overlap", box_overlapping_pairs(r)});
  sets.push_back({"shared_vertex", shared_vertex_pairs(r)});
  sets.push_back({"coplanar", coplanar_overlapping_pairs(r)});
  return sets;
}

// ---------------------------------------------------------------------------------------
// Timing helpers.

// Per-pair CPU time of the last do_intersect run on each set, for the "x_do_intersect"
// ratio counter of the classify benchmarks (registered to run after the baseline).
std::map<std::string, double> g_baseline_ns;

// CPU time of this thread (what the CPU column and the rate counters use), in ns.
double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

void report_time(benchmark::State& state, double loop_cpu_ns) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  // The same number as the CPU column (one iteration is one pair), kept as a plain value
  // so that JSON output and the ratio counter can use it.
  state.counters["ns/pair"] = state.iterations() ? loop_cpu_ns / static_cast<double>(state.iterations()) : 0.0;
}

template <class K>
typename K::Point to_point(const P& p) {
  if constexpr (std::is_same_v<typename K::Point, P>) {
    return p;
  } else {
    return typename K::Point(p[0], p[1], p[2]);
  }
}

Epick::Point_3 epick_point(const P& p) { return {p[0], p[1], p[2]}; }

// ---------------------------------------------------------------------------------------
// Benchmarks.

template <class K>
void BM_classify(benchmark::State& state, const PairSet* set) {
  using Q = typename K::Point;
  std::vector<std::array<Q, 6>> pairs;
  pairs.reserve(set->pairs.size());
  for (const Pair& p : set->pairs)
    pairs.push_back({to_point<K>(p[0]), to_point<K>(p[1]), to_point<K>(p[2]), to_point<K>(p[3]), to_point<K>(p[4]),
                     to_point<K>(p[5])});
  const std::size_t mask = pairs.size() - 1;
  const K k{};

  std::size_t i = 0;
  const double start = thread_cpu_ns();
  for (auto _ : state) {
    const auto& q = pairs[i];
    tritri::Result r = tritri::classify(k, q[0], q[1], q[2], q[3], q[4], q[5]);
    benchmark::DoNotOptimize(r);
    i = (i + 1) & mask;
  }
  const double loop_ns = thread_cpu_ns() - start;
  report_time(state, loop_ns);
  if (auto it = g_baseline_ns.find(set->name); it != g_baseline_ns.end() && it->second > 0)
    state.counters["x_do_intersect"] = state.counters["ns/pair"].value / it->second;

  // Untimed: predicate calls per pair (the algorithm makes the same calls on every
  // exact backend) and the fraction of intersecting pairs.
  tritri::PredicateCounts counts;
  const tritri::CountingKernel<K> counting(counts);
  std::size_t hits = 0;
  for (const auto& q : pairs) hits += tritri::classify(counting, q[0], q[1], q[2], q[3], q[4], q[5]).intersects();
  const double n = static_cast<double>(pairs.size());
  state.counters["orient3d/pair"] = static_cast<double>(counts.orient3d) / n;
  state.counters["orient2d/pair"] = static_cast<double>(counts.orient2d) / n;
  state.counters["intersecting"] = static_cast<double>(hits) / n;
}

void BM_do_intersect_epick(benchmark::State& state, const PairSet* set) {
  using T = Epick::Triangle_3;
  std::vector<std::array<T, 2>> pairs;
  pairs.reserve(set->pairs.size());
  for (const Pair& p : set->pairs)
    pairs.push_back({T(epick_point(p[0]), epick_point(p[1]), epick_point(p[2])),
                     T(epick_point(p[3]), epick_point(p[4]), epick_point(p[5]))});
  const std::size_t mask = pairs.size() - 1;

  std::size_t i = 0;
  const double start = thread_cpu_ns();
  for (auto _ : state) {
    bool hit = CGAL::do_intersect(pairs[i][0], pairs[i][1]);
    benchmark::DoNotOptimize(hit);
    i = (i + 1) & mask;
  }
  const double loop_ns = thread_cpu_ns() - start;
  report_time(state, loop_ns);
  g_baseline_ns[set->name] = state.counters["ns/pair"].value;

  std::size_t hits = 0;
  for (const auto& t : pairs) hits += CGAL::do_intersect(t[0], t[1]);
  state.counters["intersecting"] = static_cast<double>(hits) / static_cast<double>(pairs.size());
}

// Setup check, printed not fatal: tritri and do_intersect must agree on yes/no, and the
// coplanar set must really be coplanar.
void check_sets(const std::vector<PairSet>& sets) {
  for (const PairSet& s : sets) {
    std::size_t disagree = 0, not_coplanar = 0;
    for (const Pair& p : s.pairs) {
      const auto r = tritri::classify<tritri::DoubleKernel>(p[0], p[1], p[2], p[3], p[4], p[5]);
      const Epick::Triangle_3 a(epick_point(p[0]), epick_point(p[1]), epick_point(p[2]));
      const Epick::Triangle_3 b(epick_point(p[3]), epick_point(p[4]), epick_point(p[5]));
      disagree += r.intersects() != CGAL::do_intersect(a, b);
      if (s.name == "coplanar") {
        for (int i = 3; i < 6; ++i)
          not_coplanar += CGAL::orientation(a[0], a[1], a[2], epick_point(p[i])) != CGAL::COPLANAR;
        not_coplanar += !r.coplanar;
      }
    }
    if (disagree || not_coplanar)
      std::fprintf(stderr, "WARNING: set %s: %zu pairs where tritri and do_intersect disagree, %zu not coplanar\n",
                   s.name.c_str(), disagree, not_coplanar);
  }
}

template <class K>
void register_classify(const char* backend, const std::vector<PairSet>& sets) {
  for (const PairSet& s : sets)
    benchmark::RegisterBenchmark(("classify/" + std::string(backend) + "/" + s.name).c_str(), BM_classify<K>, &s);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  static const std::vector<PairSet> sets = make_sets();
  check_sets(sets);

  // The baseline first, so the classify benchmarks can report their ratio to it.
  for (const PairSet& s : sets)
    benchmark::RegisterBenchmark(("do_intersect/Epick/" + s.name).c_str(), BM_do_intersect_epick, &s);
  register_classify<tritri::DoubleKernel>("double", sets);
  register_classify<tritri::CgalKernel<Epick>>("Epick", sets);
  register_classify<tritri::CgalKernel<Epeck>>("Epeck", sets);
  register_classify<tritri::CgalKernel<GmpqKernel>>("Gmpq", sets);

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
