// arrange --max-memory MB (issue 36): a run whose heap would pass the budget ends with exit
// status 1 and "needs more than MB MB of memory", never a signal or std::bad_alloc, in
// every stage it can stop in; a budget the run fits in changes nothing (byte-identical
// output); bad values are usage errors (exit 2).
//
// The budgets sweep from 1 MB to above what the run needs, so the stop lands in loading,
// detection, classification, triangulation, the Boolean stage, the check and rounding
// (each mode is swept). The counting itself (operator new replaced in arrange,
// arrangements/tools/memory_budget.cpp) is what the process reports as exhausted; the
// test checks only outcomes, no times.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/write_off.h"
#include "support/mesh_generators.h"
#include "support/run_program.h"
#include "support/temp_dir.h"
#include "support/test_scale.h"

namespace {

using tritri_test::Exit;
using tritri_test::spawn;
using tritri_test::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Two crossing spheres of about 90,000 and 78,000 triangles: classification,
// triangulation and the Boolean stage all have work (about 70 MB for the arrangement,
// 160 MB for --round safe).
struct Inputs {
  std::string a, b;
};
Inputs write_inputs(const TempDir& dir) {
  const auto first = arrangements::uv_sphere({0.1, 0.2, 0.3}, 1.0, 150, 300);
  const auto second = arrangements::uv_sphere({0.6, 0.1, 0.2}, 0.9, 140, 280);
  Inputs in{dir.path("a.off"), dir.path("b.off")};
  arrangements::write_off(in.a, first.vertices, first.triangles);
  arrangements::write_off(in.b, second.vertices, second.triangles);
  return in;
}

// One mode swept over budgets: each run either succeeds with the unbudgeted output or
// stops with the message; small budgets stop, the largest fits.
void sweep(const std::vector<std::string>& mode, const TempDir& dir) {
  const std::string free_out = dir.path("free.off"), budget_out = dir.path("budget.off");
  std::vector<std::string> args = mode;
  args.insert(args.end(), {"-o", free_out, "--threads", "2"});
  const Exit free = spawn(ARRANGE_BIN, args, dir.path());
  ASSERT_TRUE(free.exited && free.code == 0) << free.err;
  const std::string expected = slurp(free_out);
  int stopped = 0, fitted = 0;
  // Scaled-down runs (the sanitizer build, where every run takes seconds) sweep every
  // third budget: still stops in the early stages and one fit.
  const std::vector<int> all = {1, 2, 4, 8, 16, 24, 32, 48, 64, 96, 128, 192, 256, 2000};
  const std::vector<int> few = {1, 8, 32, 96, 2000};
  for (const int mb : tritri_test::scaled_down() ? few : all) {
    std::filesystem::remove(budget_out);
    std::vector<std::string> budget_args = mode;
    budget_args.insert(budget_args.end(),
                       {"-o", budget_out, "--threads", "2", "--max-memory", std::to_string(mb)});
    const Exit r = spawn(ARRANGE_BIN, budget_args, dir.path());
    const std::string what = "budget " + std::to_string(mb) + " MB";
    ASSERT_TRUE(r.exited) << what << ": ended by signal " << r.signal << "\n" << r.err;
    if (r.code == 0) {
      ++fitted;
      EXPECT_EQ(slurp(budget_out), expected) << what << ": the output differs from the unbudgeted run";
    } else {
      ++stopped;
      EXPECT_EQ(r.code, 1) << what << "\n" << r.err;
      const std::string message =
          "arrange: needs more than " + std::to_string(mb) + " MB of memory (--max-memory " + std::to_string(mb) + ")\n";
      EXPECT_EQ(r.err, message) << what;
      EXPECT_EQ(fitted, 0) << what << ": stopped although a smaller budget sufficed";
    }
  }
  EXPECT_GT(stopped, 2) << "the budgets never stopped the run: the sweep tests nothing";
  EXPECT_GT(fitted, 0) << "even 2000 MB did not suffice";
}

TEST(MemoryBudget, ArrangementStopsCleanlyAtEveryBudget) {
  TempDir dir;
  const Inputs in = write_inputs(dir);
  sweep({in.a, in.b}, dir);
}

TEST(MemoryBudget, BooleanStopsCleanlyAtEveryBudget) {
  TempDir dir;
  const Inputs in = write_inputs(dir);
  sweep({in.a, in.b, "--boolean", "difference"}, dir);
}

TEST(MemoryBudget, CheckAndSafeRoundingStopCleanlyAtEveryBudget) {
  TempDir dir;
  const Inputs in = write_inputs(dir);
  sweep({in.a, in.b, "--check"}, dir);
  sweep({in.a, in.b, "--round", "safe"}, dir);
  sweep({in.a, in.b, "--exact"}, dir);
}

TEST(MemoryBudget, BadValuesAreUsageErrors) {
  TempDir dir;
  const Inputs in = write_inputs(dir);
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{in.a, "--max-memory", "0"}, {in.a, "--max-memory", "-5"},
        {in.a, "--max-memory", "12MB"}, {in.a, "--max-memory", ""}, {in.a, "--max-memory"},
        {in.a, "--max-memory", "10", "--max-memory", "20"}, {in.a, "--max-memory", "99999999999999999999"}}) {
    const Exit r = spawn(ARRANGE_BIN, bad, dir.path());
    EXPECT_TRUE(r.exited && r.code == 2) << bad.back() << ": exit " << r.code << "\n" << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  }
}

}  // namespace
