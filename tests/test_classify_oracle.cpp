// Agreement of tritri::classify with an independent exact oracle, and across backends.
//
// The oracle (support/classify_oracle.h) rebuilds every reported point exactly from its
// type, checks that it lies in the claimed open simplices of both triangles, and compares
// the point set with the corners of CGAL's exact Triangle_3 / Triangle_3 intersection. The
// pairs come mostly from the degenerate generators of support/pair_generators.h, each
// under a random exact symmetry. Counts scale with TRITRI_TEST_SCALE (1,000,000 oracle
// pairs at 1.0). The work runs on two threads (TRITRI_TEST_THREADS overrides); results do
// not depend on it.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <tritri/tritri.h>

#include "support/classify_oracle.h"
#include "support/pair_generators.h"
#include "support/test_scale.h"

namespace {

using tritri_test::Pair;
using tritri_test::Rng;

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using GmpqKernel = CGAL::Simple_cartesian<CGAL::Gmpq>;

constexpr std::uint64_t kOracleSeed = 0x7a11'0c1a'551f'1e5dull;

tritri::Result classify_double(const Pair& p) {
  return tritri::classify<tritri::DoubleKernel>(p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]);
}

template <class CK>
tritri::Result classify_cgal(const Pair& p) {
  auto pt = [](const tritri_test::Point& v) { return typename CK::Point_3(v[0], v[1], v[2]); };
  return tritri::classify<tritri::CgalKernel<CK>>(pt(p.a[0]), pt(p.a[1]), pt(p.a[2]), pt(p.b[0]), pt(p.b[1]),
                                                  pt(p.b[2]));
}

std::string result_string(const tritri::Result& r) { return tritri_test::result_string(r); }

// Counts failures per source and keeps the first few in full. Filled by one worker
// thread per chunk, merged and reported on the main thread.
class FailureLog {
 public:
  void add(const std::string& source, const Pair& p, const std::string& what) {
    ++per_source_[source];
    if (++count_ <= kKeptFailures) messages_.push_back("[" + source + "] " + what + "\n" + tritri_test::describe(p));
  }
  void merge(const FailureLog& other) {
    for (const auto& [source, n] : other.per_source_) per_source_[source] += n;
    for (const auto& m : other.messages_)
      if (static_cast<int>(messages_.size()) < kKeptFailures) messages_.push_back(m);
    count_ += other.count_;
  }
  void report() const {
    for (const auto& m : messages_) ADD_FAILURE() << m;
  }
  int count() const { return count_; }
  std::string summary() const {
    std::string s;
    for (const auto& [source, n] : per_source_) s += "  " + source + ": " + std::to_string(n) + "\n";
    return s;
  }

 private:
  static constexpr int kKeptFailures = 8;
  int count_ = 0;
  std::map<std::string, int> per_source_;
  std::vector<std::string> messages_;
};

// What the oracle run exercised (so that a broken generator cannot pass silently).
struct Coverage {
  long long pairs = 0, intersecting = 0, coplanar = 0, degenerate = 0;
  long long by_type[8] = {};
  long long by_size[7] = {};

  void merge(const Coverage& o) {
    pairs += o.pairs;
    intersecting += o.intersecting;
    coplanar += o.coplanar;
    degenerate += o.degenerate;
    for (int t = 0; t < 8; ++t) by_type[t] += o.by_type[t];
    for (int k = 0; k <= 6; ++k) by_size[k] += o.by_size[k];
  }
  void add(const tritri::Result& r) {
    ++pairs;
    intersecting += r.intersects();
    coplanar += r.coplanar;
    degenerate += r.degenerate;
    for (const auto& p : r.points) ++by_type[static_cast<int>(p.type)];
    ++by_size[r.points.size()];
  }
  void print() const {
    std::printf("pairs %lld, intersecting %lld, coplanar %lld, degenerate %lld\n", pairs, intersecting, coplanar,
                degenerate);
    for (int t = 0; t < 8; ++t)
      std::printf("  %-12s %lld\n", tritri::to_string(static_cast<tritri::Type>(t)), by_type[t]);
    for (int k = 0; k <= 6; ++k) std::printf("  %d points: %lld\n", k, by_size[k]);
  }
};

void check_one(const std::string& source, const Pair& p, FailureLog& log, Coverage& coverage) {
  const tritri::Result r = classify_double(p);
  coverage.add(r);
  const std::string what = tritri_test::check_classification(p, r);
  if (!what.empty()) log.add(source, p, what + "\n  got " + result_string(r));
}

// The oracle's pair stream is cut into chunks of kChunk pairs, each with its own seed, so
// that the chunks can run on two threads and still give the same pairs on every run.
constexpr long long kChunk = 10'000;

struct Chunk {
  long long first, count;
  Rng rng;
};

// Runs body(chunk) for the chunks covering n pairs on up to two threads (the machines this
// runs on have two cores shared with other jobs; TRITRI_TEST_THREADS overrides).
template <class Body>
void for_chunks(long long n, std::uint64_t seed, Body body) {
  const long long chunks = (n + kChunk - 1) / kChunk;
  int threads = 2;
  if (const char* t = std::getenv("TRITRI_TEST_THREADS")) threads = std::max(1, std::atoi(t));
  threads = static_cast<int>(std::min<long long>(threads, chunks));
  std::atomic<long long> next{0};
  auto work = [&] {
    for (long long c; (c = next.fetch_add(1)) < chunks;) {
      // Hashing the chunk index keeps the chunks' splitmix streams apart.
      Rng chunk_seed(seed ^ (static_cast<std::uint64_t>(c) * 0xD1B54A32D192ED03ull));
      Chunk chunk{c * kChunk, std::min(kChunk, n - c * kChunk), Rng(chunk_seed.next())};
      body(c, chunk);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// The i-th pair of a chunk's stream: a weighted random generator, then a random symmetry.
Pair next_pair(Rng& rng, std::size_t& generator) {
  generator = tritri_test::pick_generator(rng);
  return tritri_test::random_symmetry(tritri_test::pair_generators()[generator].make(rng), rng);
}

TEST(ClassifyOracle, GeneratedPairsMatchExactCgalIntersection) {
  const long long n = tritri_test::scaled_count(1'000'000);
  const long long chunks = (n + kChunk - 1) / kChunk;
  std::vector<FailureLog> logs(chunks);
  std::vector<Coverage> coverages(chunks);
  for_chunks(n, kOracleSeed, [&](long long c, Chunk& chunk) {
    for (long long i = 0; i < chunk.count; ++i) {
      std::size_t g;
      const Pair p = next_pair(chunk.rng, g);
      check_one(tritri_test::pair_generators()[g].name, p, logs[c], coverages[c]);
    }
  });
  FailureLog log;
  Coverage coverage;
  for (long long c = 0; c < chunks; ++c) {
    log.merge(logs[c]);
    coverage.merge(coverages[c]);
  }
  coverage.print();
  log.report();
  EXPECT_EQ(log.count(), 0) << "failures per generator:\n" << log.summary();
  EXPECT_EQ(coverage.pairs, n);
  // The generators must reach every type and every shape of the intersection (checked from
  // 20,000 pairs on: hexagons are about 0.3% of the pairs).
  if (n >= 20'000) {
    for (int t = 0; t < 8; ++t) EXPECT_GT(coverage.by_type[t], 0) << tritri::to_string(static_cast<tritri::Type>(t));
    for (int k = 0; k <= 6; ++k) EXPECT_GT(coverage.by_size[k], 0) << k << " points";
    EXPECT_GT(coverage.coplanar, n / 10);
    EXPECT_GT(coverage.degenerate, 0);
  }
}

// The oracle itself must be able to fail: every corruption of a correct Result (a point
// dropped, one id or type changed, a flag flipped, a segment dropped or added) is rejected.
TEST(ClassifyOracle, OracleRejectsCorruptedResults) {
  Rng rng(77);
  const long long n = tritri_test::scaled_count(2'000);
  long long corruptions = 0;
  auto expect_rejected = [&](const Pair& p, const tritri::Result& bad, const char* how) {
    ++corruptions;
    EXPECT_NE(tritri_test::check_classification(p, bad), "")
        << how << ": oracle accepted " << result_string(bad) << "\n"
        << tritri_test::describe(p);
  };
  for (long long i = 0; i < n; ++i) {
    std::size_t g;
    const Pair p = next_pair(rng, g);
    const tritri::Result r = classify_double(p);
    if (!tritri_test::check_classification(p, r).empty()) continue;  // reported by the tests above
    tritri::Result flipped = r;
    flipped.coplanar = !flipped.coplanar;
    if (!r.degenerate) expect_rejected(p, flipped, "coplanar flipped");
    if (r.points.empty()) continue;
    tritri::Result flagged = r;
    flagged.degenerate = true;
    expect_rejected(p, flagged, "degenerate set");
    // Drop the last point and the segments that use it.
    tritri::Result dropped = r;
    dropped.points.clear();
    for (std::size_t k = 0; k + 1 < r.points.size(); ++k) dropped.points.push_back(r.points[k]);
    dropped.segments.clear();
    for (const auto& sg : r.segments)
      if (static_cast<std::size_t>(sg.p1) + 1 < r.points.size()) dropped.segments.push_back(sg);
    expect_rejected(p, dropped, "last point dropped");
    // Change one id or the type of one point (other values of the same kind of simplex).
    const std::size_t k = static_cast<std::size_t>(rng.uniform(0, static_cast<int>(r.points.size()) - 1));
    tritri::Result renamed = r;
    renamed.points[k].id0 = static_cast<std::int8_t>((r.points[k].id0 + 1) % 3);
    expect_rejected(p, renamed, "id0 changed");
    if (r.points[k].id1 >= 0) {
      renamed = r;
      renamed.points[k].id1 = static_cast<std::int8_t>((r.points[k].id1 + 2) % 3);
      expect_rejected(p, renamed, "id1 changed");
    }
    renamed = r;
    const auto t = r.points[k].type;
    using tritri::Type;
    if (t == Type::VA_ON_EB || t == Type::VB_ON_EA) {
      renamed.points[k].type = t == Type::VA_ON_EB ? Type::VB_ON_EA : Type::VA_ON_EB;
      expect_rejected(p, renamed, "VA_ON_EB and VB_ON_EA exchanged");
    }
    if (!r.segments.empty()) {
      tritri::Result fewer = r;
      fewer.segments.clear();
      for (std::size_t j = 1; j < r.segments.size(); ++j) fewer.segments.push_back(r.segments[j]);
      expect_rejected(p, fewer, "first segment dropped");
    }
    // Add a missing pair of points as a segment (a polygon diagonal, or a segment for one point).
    const bool room = r.segments.size() < r.segments.capacity();
    if (room && (r.points.size() >= 4 || (r.points.size() == 2 && r.segments.empty()))) {
      tritri::Result more = r;
      more.segments.clear();
      bool added = false;
      for (std::int8_t a = 0; a < static_cast<std::int8_t>(r.points.size()); ++a)
        for (std::int8_t b = a + 1; b < static_cast<std::int8_t>(r.points.size()); ++b) {
          const bool present =
              std::find(r.segments.begin(), r.segments.end(), tritri::Segment{a, b}) != r.segments.end();
          if (present || !added) {
            if (!present) added = true;
            more.segments.push_back({a, b});
          }
        }
      if (added) expect_rejected(p, more, "diagonal added");
    }
  }
  EXPECT_GT(corruptions, n);
}

// Every pair of triangles with vertices at distinct corners of the unit cube, in both
// vertex orientations: small, exhaustive, full of shared vertices, edges and coplanar faces.
TEST(ClassifyOracle, AllUnitCubeTrianglePairsMatchExactCgalIntersection) {
  std::vector<tritri_test::Triangle> tris;
  auto corner = [](int c) { return tritri_test::Point{double(c & 1), double((c >> 1) & 1), double(c >> 2)}; };
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      for (int k = j + 1; k < 8; ++k) {
        tris.push_back({corner(i), corner(j), corner(k)});
        tris.push_back({corner(i), corner(k), corner(j)});
      }
  FailureLog log;
  Coverage coverage;
  for (const auto& a : tris)
    for (const auto& b : tris) check_one("unit_cube", {a, b}, log, coverage);
  coverage.print();
  log.report();
  EXPECT_EQ(log.count(), 0);
  EXPECT_EQ(coverage.pairs, 112LL * 112LL);
}

// CgalKernel over Epick, Epeck and Simple_cartesian<Gmpq> gives exactly DoubleKernel's
// Result on every pair of the oracle's pair stream.
TEST(ClassifyOracle, CgalBackendsGiveTheDoubleKernelResult) {
  const long long n = tritri_test::scaled_count(1'000'000);
  const long long chunks = (n + kChunk - 1) / kChunk;
  std::vector<FailureLog> logs(chunks);
  std::vector<std::array<long long, 3>> compared(chunks, {0, 0, 0});
  for_chunks(n, kOracleSeed, [&](long long c, Chunk& chunk) {
    auto compare = [&](const char* backend, const Pair& p, const tritri::Result& want, const tritri::Result& got) {
      if (!(got == want))
        logs[c].add(
            backend, p,
            std::string(backend) + " gives " + result_string(got) + "\n  DoubleKernel gives " + result_string(want));
    };
    for (long long i = 0; i < chunk.count; ++i) {
      std::size_t g;
      const Pair p = next_pair(chunk.rng, g);
      const tritri::Result want = classify_double(p);
      compare("Epick", p, want, classify_cgal<Epick>(p));
      ++compared[c][0];
      compare("Simple_cartesian<Gmpq>", p, want, classify_cgal<GmpqKernel>(p));
      ++compared[c][1];
      compare("Epeck", p, want, classify_cgal<Epeck>(p));
      ++compared[c][2];
    }
  });
  FailureLog log;
  long long total[3] = {0, 0, 0};
  for (long long c = 0; c < chunks; ++c) {
    log.merge(logs[c]);
    for (int k = 0; k < 3; ++k) total[k] += compared[c][k];
  }
  std::printf("compared: Epick %lld, Simple_cartesian<Gmpq> %lld, Epeck %lld\n", total[0], total[1], total[2]);
  log.report();
  EXPECT_EQ(log.count(), 0) << "failures per backend:\n" << log.summary();
}

}  // namespace
