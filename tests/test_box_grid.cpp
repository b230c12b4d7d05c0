// Specification of tritri::detail::box_pairs::visit_pairs_in_grid (tritri/detail/box_grid.h),
// the uniform-grid path of tritri::overlapping_triangle_pairs (tritri/box_pairs.h):
// - when it accepts (returns true) it calls visit(i, j), i < j, exactly once for every pair
//   of triangles whose closed boxes overlap (boxes that only touch included) and for no other
//   pair: equal to a brute-force all-pairs test, in task arenas of 1 and 2 threads;
// - it accepts uniform soups: small random triangles in a cube, triangulated planes (flat
//   boxes, many touching exactly), integer lattices scaled by 2^k, soups far from the origin
//   (differences of coordinates exact or not), negative coordinates, axis-aligned flat
//   triangles, tilings of touching cubes whose faces lie on cell boundaries;
// - it accepts small triangles crossed by long or huge ones in all directions (those sit on
//   coarse levels of its hierarchy);
// - it declines (returns false, having visited nothing) when most boxes overlap most others,
//   and overlapping_triangle_pairs (then CGAL's segment tree) still equals brute force
//   there, for threads 1, 2 and 0;
// - edge cases (0, 1, 2 boxes, identical boxes, a point-like cluster plus one far triangle,
//   point triangles, lattices scaled into the subnormals, dense tilings of cubes): accepted
//   or declined, the answer is exact. overlapping_triangle_pairs equals brute force on every
//   soup of this file;
// - with keys (three ints per triangle: random values from a small range, one of them shared
//   by neighbours in x order, some negative and unique), on every soup of this file: the grid
//   (arenas of 1 and 2 threads; it accepts exactly when it does without keys) visits each
//   brute-force pair whose keys share no value once, with i < j, and no other pair (the
//   sharing decided here by std::find_first_of); so does tritri::for_each_overlapping_pair
//   (threads 1, 2 and 0) where the grid accepts, while where it declines (CGAL's segment
//   tree, keys a hint) it may also visit pairs whose keys share a value, at most once each.
#include <gtest/gtest.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include <tritri/box_pairs.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <mutex>
#include <numeric>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/brute_force_box_pairs.h"
#include "support/test_scale.h"

namespace {

using tritri::detail::box_pairs::Box;
using tritri::detail::box_pairs::triangle_boxes;
using tritri::detail::box_pairs::visit_pairs_in_grid;
using tritri_test::scaled_count;
using tritri_test::seed_for;
using Vec3 = std::array<double, 3>;
using Tri = std::array<int, 3>;
using Pairs = std::vector<std::pair<int, int>>;

struct Soup {
  std::string name;
  std::vector<Vec3> V;
  std::vector<Tri> F;
};

void add_triangle(Soup& s, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int first = static_cast<int>(s.V.size());
  s.V.insert(s.V.end(), {a, b, c});
  s.F.push_back({first, first + 1, first + 2});
}

// All pairs i < j whose closed boxes overlap, by the definition, from the corners.
Pairs brute_force_pairs(const Soup& s) { return tritri_test::brute_force_box_pairs(s.V, s.F); }

// The pairs of `a` (sorted) missing from `b` (sorted): their count and the first few.
std::string missing(const Pairs& a, const Pairs& b) {
  Pairs d;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(d));
  std::ostringstream out;
  out << d.size();
  for (std::size_t k = 0; k < std::min<std::size_t>(d.size(), 5); ++k)
    out << (k ? ", " : " e.g. ") << "(" << d[k].first << ", " << d[k].second << ")";
  return out.str();
}

struct GridRun {
  bool accepted = false;
  Pairs pairs;  // every visit, sorted, repeats kept
};

GridRun run_grid(const Soup& s, int threads) {
  const std::vector<Box> boxes = triangle_boxes(s.V, s.V, s.F);
  GridRun run;
  std::mutex mutex;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    run.accepted = visit_pairs_in_grid(boxes, [&](int i, int j) {
      const std::lock_guard<std::mutex> lock(mutex);
      run.pairs.emplace_back(i, j);
    });
  });
  std::sort(run.pairs.begin(), run.pairs.end());
  return run;
}

// Keys, three per triangle: one value shared by runs of 8 neighbours in the order of the
// boxes' minimum x (so that overlapping pairs often share it), the others random in
// 0 .. n / 3 or, one time in four, negative and held by no other key.
std::vector<Tri> random_keys(const Soup& s) {
  const int n = static_cast<int>(s.F.size());
  std::mt19937_64 rng(seed_for(707) + s.F.size());
  std::vector<double> xmin(s.F.size());
  for (int t = 0; t < n; ++t) xmin[t] = std::min({s.V[s.F[t][0]][0], s.V[s.F[t][1]][0], s.V[s.F[t][2]][0]});
  std::vector<int> order(s.F.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return xmin[a] < xmin[b]; });
  std::vector<Tri> keys(s.F.size());
  const auto range = static_cast<unsigned>(n / 3 + 1);
  for (int r = 0; r < n; ++r) {
    const int t = order[r], spatial = static_cast<int>(rng() % 3);
    for (int k = 0; k < 3; ++k)
      keys[t][k] = k == spatial ? r / 8 : (rng() % 4 == 0 ? -1 - (3 * t + k) : static_cast<int>(rng() % range));
  }
  return keys;
}

// Whether keys a and b share a value (the reference: not the header's share_key).
bool keys_meet(const Tri& a, const Tri& b) {
  return std::find_first_of(a.begin(), a.end(), b.begin(), b.end()) != a.end();
}

// The visits of one search among n triangles, each pair i < j counted: in a byte per pair
// (row by row of the upper triangle) when most pairs are expected, else in lists per thread,
// sorted at the end. Visits with i >= j or out of range are counted apart. add() is
// thread-safe.
class VisitLog {
 public:
  VisitLog(std::size_t n, bool dense) : n_(n), dense_(dense), count_(dense ? n * (n - (n > 0)) / 2 : 0, 0) {}
  void add(int i, int j) {
    if (i < 0 || i >= j || static_cast<std::size_t>(j) >= n_)
      bad_.fetch_add(1, std::memory_order_relaxed);
    else if (dense_)
      std::atomic_ref<std::uint8_t>(count_[slot(i, j)]).fetch_add(1, std::memory_order_relaxed);
    else
      lists_.local().emplace_back(i, j);
  }
  long long visits() const {
    long long v = bad_ + std::accumulate(count_.begin(), count_.end(), 0LL);
    for (const Pairs& l : lists_) v += static_cast<long long>(l.size());
    return v;
  }
  // "" when every pair of `must` was visited once, every other pair of `allowed` at most once
  // and no other pair (both sorted, `must` within `allowed`).
  std::string differences(const Pairs& must, const Pairs& allowed) const {
    long long missed = 0, extra = 0, repeated = 0;
    std::ostringstream first;
    auto note = [&](long long& what, std::size_t i, std::size_t j, int times) {
      if (missed + extra + repeated == 0) first << " e.g. (" << i << ", " << j << ") visited " << times << " times";
      ++what;
    };
    if (dense_) {
      std::vector<std::uint8_t> wanted(count_.size(), 0);  // 1: must, 2: allowed
      for (const auto& [i, j] : allowed) wanted[slot(i, j)] = 2;
      for (const auto& [i, j] : must) wanted[slot(i, j)] = 1;
      for (std::size_t i = 0, p = 0; i < n_; ++i)
        for (std::size_t j = i + 1; j < n_; ++j, ++p) {
          const int c = count_[p], w = wanted[p];
          if (c > 1 && w > 0) note(repeated, i, j, c);
          if (c == 0 && w == 1) note(missed, i, j, c);
          if (c > 0 && w == 0) note(extra, i, j, c);
        }
    } else {
      Pairs got, once;
      for (const Pairs& l : lists_) got.insert(got.end(), l.begin(), l.end());
      std::sort(got.begin(), got.end());
      for (std::size_t k = 0, e = 0; k < got.size(); k = e) {
        while (e < got.size() && got[e] == got[k]) ++e;  // got[k .. e) one pair
        const auto [i, j] = got[k];
        if (!std::binary_search(allowed.begin(), allowed.end(), got[k]))
          note(extra, i, j, static_cast<int>(e - k));
        else if (e - k > 1)
          note(repeated, i, j, static_cast<int>(e - k));
        once.push_back(got[k]);
      }
      Pairs lost;
      std::set_difference(must.begin(), must.end(), once.begin(), once.end(), std::back_inserter(lost));
      for (const auto& [i, j] : lost) note(missed, i, j, 0);
    }
    if (missed + extra + repeated + bad_ == 0) return "";
    std::ostringstream out;
    out << "missed " << missed << ", extra " << extra << ", repeated " << repeated << ", not i < j " << bad_
        << first.str();
    return out.str();
  }

 private:
  std::size_t slot(std::size_t i, std::size_t j) const { return i * (2 * n_ - i - 1) / 2 + (j - i - 1); }
  std::size_t n_;
  bool dense_;
  std::vector<std::uint8_t> count_;
  tbb::enumerable_thread_specific<Pairs> lists_;
  std::atomic<long long> bad_{0};
};

enum class Expect { kAccept, kDecline, kEither };

// The grid in arenas of 1 and 2 threads, then the public function with 1, 2 and all threads,
// against brute force (a visit(i, j) with i >= j shows as an extra pair).
void check(const Soup& s, Expect expect) {
  SCOPED_TRACE(s.name + ", " + std::to_string(s.F.size()) + " triangles");
  const Pairs expected = brute_force_pairs(s);
  bool accepted = false;
  for (int threads : {1, 2}) {
    SCOPED_TRACE("arena of " + std::to_string(threads) + " thread(s)");
    const GridRun run = run_grid(s, threads);
    if (threads == 1) accepted = run.accepted;
    EXPECT_TRUE(expect != Expect::kAccept || run.accepted) << "the grid declined a uniform soup";
    EXPECT_TRUE(expect != Expect::kDecline || !run.accepted) << "the grid accepted a soup of long triangles";
    EXPECT_EQ(run.accepted, accepted) << "the decision depends on the thread count";
    if (!run.accepted) {
      EXPECT_TRUE(run.pairs.empty()) << "declined after visiting " << run.pairs.size() << " pairs";
      continue;
    }
    const auto repeat = std::adjacent_find(run.pairs.begin(), run.pairs.end());
    if (repeat != run.pairs.end())
      ADD_FAILURE() << "pair (" << repeat->first << ", " << repeat->second << ") visited more than once";
    Pairs unique = run.pairs;
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    EXPECT_TRUE(unique == expected) << "missed " << missing(expected, unique) << "; extra "
                                    << missing(unique, expected);
  }
  for (int threads : {1, 2, 0}) {
    const Pairs got = tritri::overlapping_triangle_pairs(s.V, s.F, threads);
    EXPECT_TRUE(got == expected) << "overlapping_triangle_pairs, threads " << threads << ": missed "
                                 << missing(expected, got) << "; extra " << missing(got, expected);
  }
  // With keys: the same pairs less those whose keys share a value.
  const std::vector<Tri> keys = random_keys(s);
  Pairs want;
  for (const auto& [i, j] : expected)
    if (!keys_meet(keys[i], keys[j])) want.emplace_back(i, j);
  if (expected.size() >= 100) {  // the keys filter some pairs, not all
    EXPECT_GT(want.size(), 0u) << "every pair shares a key";
    EXPECT_LT(want.size(), expected.size()) << "no pair shares a key";
  }
  const std::size_t n = s.F.size();
  const bool dense = want.size() > n * n / 32;  // then a byte per pair costs less than sorting
  const std::vector<Box> boxes = triangle_boxes(s.V, s.V, s.F);
  for (int threads : {1, 2}) {
    VisitLog log(n, dense);
    bool keyed_accepted = false;
    tbb::task_arena arena(threads);
    arena.execute([&] {
      keyed_accepted = visit_pairs_in_grid(boxes, [&log](int i, int j) { log.add(i, j); }, std::span<const Tri>(keys));
    });
    EXPECT_EQ(keyed_accepted, accepted) << "keys changed the grid's decision, arena of " << threads;
    if (keyed_accepted)
      EXPECT_EQ(log.differences(want, want), "") << "the grid with keys, arena of " << threads;
    else
      EXPECT_EQ(log.visits(), 0) << "the grid with keys declined after visiting pairs, arena of " << threads;
  }
  // for_each_overlapping_pair: the same where the grid accepts; where it declines, CGAL's
  // segment tree may also visit pairs whose keys share a value (box_pairs.h: there the keys
  // are a hint), each at most once.
  const Pairs& allowed = accepted ? want : expected;
  for (int threads : {1, 2, 0}) {
    VisitLog log(n, dense);
    tritri::for_each_overlapping_pair(
        std::span<const Vec3>(s.V), std::span<const Tri>(s.F), threads, {}, [&log](int i, int j) { log.add(i, j); },
        std::span<const Tri>(keys));
    EXPECT_EQ(log.differences(want, allowed), "") << "for_each_overlapping_pair with keys, threads " << threads;
  }
}

int scaled(long long n) { return static_cast<int>(scaled_count(n)); }

// n triangles with corners within `size` of random centres in [lo, lo + side]^3.
Soup random_cube(std::mt19937_64& rng, int n, double lo, double side, double size, std::string name) {
  std::uniform_real_distribution<double> unit(0, 1);
  Soup s{std::move(name), {}, {}};
  for (int t = 0; t < n; ++t) {
    const Vec3 c = {lo + side * unit(rng), lo + side * unit(rng), lo + side * unit(rng)};
    Vec3 p[3];
    for (Vec3& q : p)
      for (int a = 0; a < 3; ++a) q[a] = c[a] + size * unit(rng);
    add_triangle(s, p[0], p[1], p[2]);
  }
  return s;
}

// n triangles with integer corners base + [0, spread), base in [first, first + range)^3,
// all times 2^k (exact while the integers times 2^k are representable). flat: one axis,
// chosen per triangle, has the same coordinate at the three corners.
Soup lattice(std::mt19937_64& rng, int n, int first, int range, int spread, int k, bool flat, std::string name) {
  Soup s{std::move(name), {}, {}};
  for (int t = 0; t < n; ++t) {
    int base[3], p[3][3];
    for (int& b : base) b = first + static_cast<int>(rng() % static_cast<unsigned>(range));
    const int flat_axis = flat ? static_cast<int>(rng() % 3) : -1;
    for (auto& q : p)
      for (int a = 0; a < 3; ++a) q[a] = base[a] + (a == flat_axis ? 0 : static_cast<int>(rng() % spread));
    Vec3 v[3];
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a) v[c][a] = std::ldexp(static_cast<double>(p[c][a]), k);
    add_triangle(s, v[0], v[1], v[2]);
  }
  return s;
}

// An m x m grid of squares of side `step`, two triangles each, from `origin`: in the plane
// normal to `axis` (flat boxes), or for axis 3 on the slanted plane z = u + 2 v.
Soup plane_grid(int m, int axis, double step, const Vec3& origin, std::string name) {
  Soup s{std::move(name), {}, {}};
  auto at = [&](int i, int j) {
    Vec3 p = origin;
    if (axis < 3) {
      p[(axis + 1) % 3] += i * step;
      p[(axis + 2) % 3] += j * step;
    } else {
      p[0] += i * step;
      p[1] += j * step;
      p[2] += (i + 2 * j) * step;
    }
    return p;
  };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      add_triangle(s, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      add_triangle(s, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return s;
}

// The 12 triangles of the surface of the box [lo, hi].
void add_cube(Soup& s, const Vec3& lo, const Vec3& hi) {
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {lo[axis], hi[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 p[4];
      for (int c = 0; c < 4; ++c) {
        p[c][axis] = side;
        p[c][u] = (c == 1 || c == 2) ? hi[u] : lo[u];
        p[c][v] = (c >= 2) ? hi[v] : lo[v];
      }
      add_triangle(s, p[0], p[1], p[2]);
      add_triangle(s, p[0], p[2], p[3]);
    }
}

// Small triangles in the unit cube crossed by `rounds` x 8 long or huge ones: along each
// axis, along the four diagonals, and one big slanted face.
Soup crossed(std::mt19937_64& rng, int n, int rounds, std::string name) {
  Soup s = random_cube(rng, n, 0, 1, 0.3 / std::cbrt(n), std::move(name));
  std::uniform_real_distribution<double> unit(0, 1);
  for (int r = 0; r < rounds; ++r) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 a = {unit(rng), unit(rng), unit(rng)}, b = a, c = a;
      a[axis] = -0.1;
      b[axis] = 1.1;
      c[(axis + 1) % 3] += 0.01;
      add_triangle(s, a, b, c);
    }
    for (int d = 0; d < 4; ++d) {
      const Vec3 a = {d & 1 ? 1.1 : -0.1, d & 2 ? 1.1 : -0.1, -0.1};
      const Vec3 b = {1 - a[0], 1 - a[1], 1.1};
      add_triangle(s, a, b, {a[0] + 0.02 * unit(rng), a[1], a[2] + 0.02});
    }
    add_triangle(s, {-0.2, unit(rng), -0.1}, {1.2, -0.1, unit(rng)}, {unit(rng), 1.1, 1.2});
  }
  return s;
}

TEST(BoxGrid, AcceptsSmallRandomTrianglesInACubeAndIsExact) {
  std::mt19937_64 rng(seed_for(701));
  for (int n : {scaled(300), scaled(1500), scaled(4000)}) {
    // Sizes about the mean spacing: each box meets a few others.
    check(random_cube(rng, n, 0, 1, 1.5 / std::cbrt(n), "unit cube"), Expect::kAccept);
    check(random_cube(rng, n, -3, 2, 4 / std::cbrt(n), "negative cube"), Expect::kAccept);
  }
}

TEST(BoxGrid, AcceptsTriangulatedPlanesWhoseBoxesTouch) {
  const int m = std::max(3, static_cast<int>(std::sqrt(scaled(3000) / 2.0)));
  for (int axis = 0; axis < 4; ++axis) {
    check(plane_grid(m, axis, 1, {0, 0, 0}, "plane " + std::to_string(axis)), Expect::kAccept);
    check(plane_grid(m, axis, 0.25, {-3, -5, -7}, "negative plane " + std::to_string(axis)), Expect::kAccept);
    check(plane_grid(m, axis, 0.1, {0.3, -0.7, 1.9}, "inexact plane " + std::to_string(axis)), Expect::kAccept);
  }
}

// Integer lattices times 2^k: every coordinate and difference exact, boxes that touch and
// coincide everywhere. Accepted while 1 / h is a finite double (h, the cell size, is about
// 2^(k + 2)); deeper in the subnormals 1 / h overflows, every box falls in the last cell and
// the grid declines (seen for k <= -1028): exact either way.
TEST(BoxGrid, AcceptsLatticesScaledByPowersOfTwo) {
  std::mt19937_64 rng(seed_for(702));
  const int n = scaled(2000);
  const int range = std::max(4, static_cast<int>(2 * std::cbrt(n)));  // a box meets ~10 others
  for (int k : {-1074, -1070, -1060, -1040, -1028, -1021, -1000, -500, -30, 0, 30, 500, 900, 960}) {
    const Expect expect = k >= -1021 ? Expect::kAccept : Expect::kEither;
    for (bool flat : {false, true})
      for (int first : {0, -range / 2, -3 * range}) {
        const std::string name =
            "lattice 2^" + std::to_string(k) + (flat ? " flat" : "") + " from " + std::to_string(first);
        check(lattice(rng, n, first, range, 3, k, flat, name), expect);
      }
  }
}

// Far from the origin: a narrow soup at O (differences of coordinates exact), a soup of
// triangles barely above the ulp at O (boxes coincide and touch), and soups across the
// origin at the scale of O (differences inexact); all also negated.
TEST(BoxGrid, AcceptsSoupsFarFromTheOrigin) {
  std::mt19937_64 rng(seed_for(703));
  const int n = scaled(2000);
  const double size = 1.5 / std::cbrt(n);
  for (double offset : {1e6, 1e15, 1e300}) {
    for (double sign : {1.0, -1.0}) {
      std::ostringstream at;
      at << " at " << sign * offset;
      const double o = sign * offset, ulp = std::nextafter(offset, 2 * offset) - offset;
      check(random_cube(rng, n, o, offset * 1e-6, offset * 1e-6 * size, "narrow" + at.str()), Expect::kAccept);
      check(random_cube(rng, n, o, 16 * ulp * std::cbrt(n), 8 * ulp, "ulp-sized" + at.str()), Expect::kAccept);
      const double lo = sign > 0 ? -offset / 2 : -offset;
      check(random_cube(rng, n, lo, offset, offset * size, "across the origin" + at.str()), Expect::kAccept);
    }
  }
}

// Cubes [i, i + 1]^3 times 2^k, all of them (a tiling) or a checkerboard (touching along
// edges): their faces' flat boxes touch exactly on planes that are multiples of the cell
// size (2^(k + 1)). Dense (each box meets dozens): the grid may decline, exact either way.
TEST(BoxGrid, TouchingCubesOnCellBoundaries) {
  const int c = std::max(2, static_cast<int>(std::cbrt(scaled(1000))));
  for (int k : {-20, 0, 3, 40})
    for (int keep : {1, 2}) {
      Soup s{"cubes 2^" + std::to_string(k) + (keep == 2 ? " checkerboard" : " tiling"), {}, {}};
      const double h = std::ldexp(1.0, k);
      for (int i = 0; i < c; ++i)
        for (int j = 0; j < c; ++j)
          for (int l = -c / 2; l < c - c / 2; ++l)
            if ((i + j + l + c) % keep == 0)
              add_cube(s, {i * h, j * h, l * h}, {(i + 1) * h, (j + 1) * h, (l + 1) * h});
      check(s, Expect::kEither);
    }
}

// Long triangles sit on coarse levels of the hierarchy: accepted, and exact.
TEST(BoxGrid, AcceptsLongTrianglesCrossingManySmallOnes) {
  std::mt19937_64 rng(seed_for(704));
  for (int n : {std::max(200, scaled(300)), scaled(2000), scaled(4000)})  // small ones the majority
    for (int rounds : {1, 2, 4}) check(crossed(rng, n, rounds, "crossed x" + std::to_string(rounds)), Expect::kAccept);
}

// Most boxes overlapping most others (big triangles jittered over one region): the pairwise
// tests would be quadratic, the grid declines, and the segment tree is exact.
TEST(BoxGrid, DeclinesWhenMostBoxesOverlapEachOther) {
  std::mt19937_64 rng(seed_for(706));
  std::uniform_real_distribution<double> unit(0, 1);
  for (int n : {2000, std::max(2000, scaled(5000))}) {  // n^2 / 2 tests > 40 n log2 n
    Soup s{"overlapping", {}, {}};
    for (int t = 0; t < n; ++t)
      add_triangle(s, {unit(rng), unit(rng), unit(rng)}, {10 + unit(rng), unit(rng), 10 * unit(rng)},
                   {unit(rng), 10 + unit(rng), 10 * unit(rng)});
    check(s, Expect::kDecline);
  }
}

// Soups between uniform and crossed: accepted or not, exact.
TEST(BoxGrid, IsExactOnUnevenSoupsWhetherItAcceptsOrNot) {
  std::mt19937_64 rng(seed_for(705));
  std::uniform_real_distribution<double> unit(0, 1);
  const int n = scaled(2000);
  for (int needles : {1, 3, 10, n / 50, n / 10}) {
    Soup s = random_cube(rng, n, 0, 1, 1.5 / std::cbrt(n), "needles " + std::to_string(needles));
    for (int t = 0; t < needles; ++t) {
      const double y = unit(rng), z = unit(rng);
      add_triangle(s, {-0.1, y, z}, {1.2, y + 0.01, z}, {unit(rng), y, z + 0.01});
    }
    check(s, Expect::kEither);
  }
  // Sizes spread over six orders of magnitude.
  Soup s{"log-uniform sizes", {}, {}};
  for (int t = 0; t < n; ++t) {
    const double size = std::pow(10.0, -6 * unit(rng)), x = unit(rng), y = unit(rng), z = unit(rng);
    add_triangle(s, {x, y, z}, {x + size * unit(rng), y + size, z}, {x, y + size * unit(rng), z + size});
  }
  check(s, Expect::kEither);
}

TEST(BoxGrid, ZeroOneAndTwoBoxes) {
  const Soup empty{"empty", {}, {}};
  check(empty, Expect::kAccept);
  Soup one{"one", {}, {}};
  add_triangle(one, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  check(one, Expect::kAccept);
  const double ulp = std::nextafter(1.0, 2.0);
  // Overlapping, touching in a plane, an edge, a corner, one ulp apart, far apart, identical.
  const Vec3 shifts[] = {{0.5, 0.25, 0}, {1, 0.5, 0.5}, {1, 1, 0.5}, {1, 1, 1}, {ulp, 0, 0}, {7, -9, 3}, {0, 0, 0}};
  for (const Vec3& d : shifts) {
    Soup two{"two, shift " + std::to_string(&d - shifts), {}, {}};
    add_triangle(two, {0, 0, 0}, {1, 0, 0.5}, {0, 1, 1});
    add_triangle(two, {d[0], d[1], d[2]}, {d[0] + 1, d[1], d[2] + 0.5}, {d[0], d[1] + 1, d[2] + 1});
    check(two, Expect::kAccept);
  }
  // Two point triangles: the span is zero, the grid declines; the pair is still found.
  Soup points{"two equal points", {}, {}};
  add_triangle(points, {2, 3, 4}, {2, 3, 4}, {2, 3, 4});
  add_triangle(points, {2, 3, 4}, {2, 3, 4}, {2, 3, 4});
  check(points, Expect::kDecline);
}

TEST(BoxGrid, AllBoxesIdentical) {
  for (int n : {3, 10, 40, scaled(400)}) {
    Soup s{"identical x" + std::to_string(n), {}, {}};
    for (int t = 0; t < n; ++t) add_triangle(s, {0, 0, 0}, {1, 2, 0}, {0, 1, 3});
    check(s, Expect::kEither);
    Soup p{"identical points x" + std::to_string(n), {}, {}};
    for (int t = 0; t < n; ++t) add_triangle(p, {1, 1, 1}, {1, 1, 1}, {1, 1, 1});
    check(p, Expect::kDecline);  // span zero
  }
}

// A cluster of tiny triangles near one point plus one triangle far away: the span is large,
// the median extent tiny; and the same with most triangles degenerate to points (median
// extent zero).
TEST(BoxGrid, PointLikeClusterPlusOneFarTriangle) {
  std::mt19937_64 rng(seed_for(706));
  for (int n : {2, 5, 20, 100, scaled(1000)})
    for (double far : {1.0, 1e9, 1e300}) {
      Soup s = random_cube(rng, n, 0.5, 1e-12, 1e-13, "cluster of " + std::to_string(n) + " + far");
      add_triangle(s, {far, far, far}, {far, 2 * far, far}, {far, far, -far});
      check(s, Expect::kEither);
      Soup p{"points + far", {}, {}};
      for (int t = 0; t < n; ++t) {
        const Vec3 q = {static_cast<double>(rng() % 3), static_cast<double>(rng() % 3), 0};
        add_triangle(p, q, q, t % 3 ? q : Vec3{q[0] + 1, q[1], 1});
      }
      add_triangle(p, {far, 0, 0}, {far, 1, 0}, {far, 0, 1});
      check(p, Expect::kEither);
    }
}

}  // namespace
