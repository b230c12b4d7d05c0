// bench/bench_implicit_predicates.cpp
//
// Nanoseconds per predicate of the implicit-point backend, each on a filter-hit set (general
// position) and an exact-path set (degenerate by construction, exact zeros the filter cannot
// certify):
//
//   orient3d  4 explicit (and the double backend on std::array, same points), 1 LPI, 1 TPI,
//             4 LPI;  orient2d (XY) 1 LPI;  equal / less between an LPI and a TPI.
//
// Points are built before timing; each benchmark cycles through 4096 cases. The counter
// filter_rate is the share of staged evaluations decided by the floating-point filter
// (tritri::implicit_predicate_stats(); predicates on explicit points only go to the double
// backend and do not count).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <tritri/tritri.h>

#include "../tests/support/implicit_recipes.h"
#include "../tests/support/test_scale.h"

namespace {

using tritri::ImplicitPoint;
using tritri::Plane;
using tritri_test::Point;
using tritri_test::Rng;
using tritri_test::Triple;

constexpr int kCases = 4096;

ImplicitPoint E(const Point& p) { return ImplicitPoint::explicit_point(p); }
// The constructions below are defined by construction (or with probability one for random
// doubles); lpi / tpi throw otherwise.
ImplicitPoint lpi(const Point& p, const Point& q, const Triple& t) {
  return ImplicitPoint::lpi(p, q, t[0], t[1], t[2]);
}
ImplicitPoint tpi(const Triple& a, const Triple& b, const Triple& c) {
  return ImplicitPoint::tpi(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
}

Point random_point(Rng& rng) { return {rng.symmetric_unit(), rng.symmetric_unit(), rng.symmetric_unit()}; }
Triple random_triple(Rng& rng) { return {random_point(rng), random_point(rng), random_point(rng)}; }
Point grid_point(Rng& rng) {
  return {double(rng.uniform(-8, 8)), double(rng.uniform(-8, 8)), double(rng.uniform(-8, 8))};
}

ImplicitPoint random_lpi(Rng& rng) { return lpi(random_point(rng), random_point(rng), random_triple(rng)); }
ImplicitPoint random_tpi(Rng& rng) { return tpi(random_triple(rng), random_triple(rng), random_triple(rng)); }

using Case = std::array<ImplicitPoint, 4>;
using DoubleCase = std::array<Point, 4>;

struct Sets {
  std::vector<DoubleCase> explicit_general, explicit_degenerate;
  std::vector<Case> explicit4[2], one_lpi[2], one_tpi[2], four_lpi[2], orient2d_lpi[2], lpi_tpi[2];
};

// [0]: general position (filter hits), [1]: degenerate by construction (exact path).
Sets make_sets() {
  Sets s;
  Rng rng(tritri_test::seed_for(7));
  for (int i = 0; i < kCases; ++i) {
    // 4 explicit: random doubles / four points of a lattice plane.
    const DoubleCase g = {random_point(rng), random_point(rng), random_point(rng), random_point(rng)};
    const Point o = grid_point(rng), u = grid_point(rng), v = grid_point(rng);
    auto on = [&](int a, int b) { return tritri_test::moved(tritri_test::moved(o, u, a), v, b); };
    const DoubleCase d = {on(0, 0), on(rng.uniform(-3, 3), rng.uniform(-3, 3)), on(rng.uniform(-3, 3), 1),
                          on(1, rng.uniform(-3, 3))};
    s.explicit_general.push_back(g);
    s.explicit_degenerate.push_back(d);
    s.explicit4[0].push_back({E(g[0]), E(g[1]), E(g[2]), E(g[3])});
    s.explicit4[1].push_back({E(d[0]), E(d[1]), E(d[2]), E(d[3])});

    // 1 LPI: three random explicit points / the LPI's own plane triple.
    const Triple t = random_triple(rng);
    s.one_lpi[0].push_back({E(random_point(rng)), E(random_point(rng)), E(random_point(rng)), random_lpi(rng)});
    s.one_lpi[1].push_back({E(t[0]), E(t[1]), E(t[2]), lpi(random_point(rng), random_point(rng), t)});

    // 1 TPI: likewise, the plane being one of the three.
    s.one_tpi[0].push_back({E(random_point(rng)), E(random_point(rng)), E(random_point(rng)), random_tpi(rng)});
    s.one_tpi[1].push_back({E(t[0]), E(t[1]), E(t[2]), tpi(random_triple(rng), t, random_triple(rng))});

    // 4 LPI: random / four lines meeting one plane (given by rotations of one triple).
    s.four_lpi[0].push_back({random_lpi(rng), random_lpi(rng), random_lpi(rng), random_lpi(rng)});
    Case c;
    for (int k = 0; k < 4; ++k) c[k] = lpi(random_point(rng), random_point(rng), tritri_test::reordered(t, rng));
    s.four_lpi[1].push_back(c);

    // orient2d(XY) with 1 LPI: random / the LPI on the line through the two others.
    const Point p = random_point(rng), q = random_point(rng);
    s.orient2d_lpi[0].push_back({E(random_point(rng)), E(random_point(rng)), random_lpi(rng), E(p)});
    s.orient2d_lpi[1].push_back({E(p), E(q), lpi(p, q, random_triple(rng)), E(p)});

    // equal / less, LPI vs TPI: unrelated / one point (line pq meets plane t) built twice.
    s.lpi_tpi[0].push_back({random_lpi(rng), random_tpi(rng), E(p), E(p)});
    const Triple m1 = {p, q, random_point(rng)}, m2 = {q, p, random_point(rng)};
    s.lpi_tpi[1].push_back({lpi(p, q, t), tpi(m1, t, m2), E(p), E(p)});
  }
  return s;
}

const Sets& sets() {
  static const Sets s = make_sets();
  return s;
}

// One predicate per iteration, cycling through the cases.
template <class C, class F>
void run(benchmark::State& state, const std::vector<C>& cases, F eval) {
  auto& stats = tritri::implicit_predicate_stats();
  const auto before = stats;
  std::size_t i = 0;
  int acc = 0;
  for (auto _ : state) {
    acc += eval(cases[i]);
    if (++i == cases.size()) i = 0;
  }
  benchmark::DoNotOptimize(acc);
  const double f = static_cast<double>(stats.filtered - before.filtered);
  const double e = static_cast<double>(stats.exact - before.exact);
  if (f + e > 0) state.counters["filter_rate"] = f / (f + e);
  state.SetItemsProcessed(state.iterations());
}

int o3(const Case& c) { return tritri::to_int(tritri::orient3d(c[0], c[1], c[2], c[3])); }

void register_all() {
  const char* set_name[2] = {"general", "degenerate"};
  for (int k = 0; k < 2; ++k) {
    const std::string suffix = std::string("/") + set_name[k];
    benchmark::RegisterBenchmark(("orient3d_double_backend" + suffix).c_str(), [k](benchmark::State& st) {
      run(st, k == 0 ? sets().explicit_general : sets().explicit_degenerate,
          [](const DoubleCase& c) { return tritri::to_int(tritri::orient3d(c[0], c[1], c[2], c[3])); });
    });
    benchmark::RegisterBenchmark(("orient3d_4explicit" + suffix).c_str(),
                                 [k](benchmark::State& st) { run(st, sets().explicit4[k], o3); });
    benchmark::RegisterBenchmark(("orient3d_1lpi" + suffix).c_str(),
                                 [k](benchmark::State& st) { run(st, sets().one_lpi[k], o3); });
    benchmark::RegisterBenchmark(("orient3d_1tpi" + suffix).c_str(),
                                 [k](benchmark::State& st) { run(st, sets().one_tpi[k], o3); });
    benchmark::RegisterBenchmark(("orient3d_4lpi" + suffix).c_str(),
                                 [k](benchmark::State& st) { run(st, sets().four_lpi[k], o3); });
    benchmark::RegisterBenchmark(("orient2d_xy_1lpi" + suffix).c_str(), [k](benchmark::State& st) {
      run(st, sets().orient2d_lpi[k],
          [](const Case& c) { return tritri::to_int(tritri::orient2d(c[0], c[1], c[2], Plane::XY)); });
    });
    benchmark::RegisterBenchmark(("equal_lpi_tpi" + suffix).c_str(), [k](benchmark::State& st) {
      run(st, sets().lpi_tpi[k], [](const Case& c) { return int(tritri::equal(c[0], c[1])); });
    });
    benchmark::RegisterBenchmark(("less_lpi_tpi" + suffix).c_str(), [k](benchmark::State& st) {
      run(st, sets().lpi_tpi[k], [](const Case& c) { return int(tritri::less(c[0], c[1])); });
    });
  }
}

}  // namespace

int main(int argc, char** argv) {
  (void)sets();  // build every point before any timing
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
