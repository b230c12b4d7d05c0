// The `arrange` command line: exit codes, messages and the --stats JSON contract, run as a
// separate process (the path of the binary comes from CMake). Hostile option values (every
// option, table-driven) must be usage errors: exit status 2, a message, never a signal; the
// same for make_test_meshes (found beside arrange).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/arrange_stats.h"
#include "arrangements/thread_count.h"
#include "io/write_off.h"
#include "support/mesh_generators.h"
#include "support/run_program.h"
#include "support/shared_meshes.h"
#include "support/temp_dir.h"

namespace {

using tritri_test::Exit;
using tritri_test::spawn;

namespace fs = std::filesystem;

using CliRun = tritri_test::CommandRun;

CliRun run(const std::string& args) {
  return tritri_test::run_command(std::string(ARRANGE_BIN) + " " + args + " 2>&1");
}

std::string bad(const char* name) { return (tritri_test::bad_input_dir() / name).string(); }

TEST(ArrangeCli, HelpExplainsOptionsAndKeys) {
  const CliRun r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* word : {"--stats", "--classifier", "--threads", "--scale", "intersection_points", "exit status"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST(ArrangeCli, BadCommandLinesExitWithTwo) {
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("--no-such-option x.obj").status, 2);
  EXPECT_EQ(run("--threads minus x.obj").status, 2);
  EXPECT_EQ(run("--classifier magic " + bad("obj_nan_coordinate.obj")).status, 2);
}

TEST(ArrangeCli, BadInputExitsWithOneAndNamesTheProblem) {
  struct Case {
    std::string args;
    const char* expect;  // a word the message must contain
  };
  const Case cases[] = {
      {"/nonexistent/mesh.obj", "mesh.obj"},
      {bad("unknown_extension.xyz"), "unknown_extension.xyz"},
      {bad("obj_nan_coordinate.obj"), "obj_nan_coordinate.obj"},
      {bad("obj_inf_coordinate.obj"), "obj_inf_coordinate.obj"},
      {bad("obj_index_out_of_range.obj"), "range"},
      {bad("empty_file.off"), "empty_file.off"},
      {bad("off_truncated.off"), "off_truncated.off"},
      {bad("stl_truncated_binary.stl"), "stl_truncated_binary.stl"},
      {bad("ply_huge_list_length.ply"), "ply_huge_list_length.ply"},
  };
  for (const Case& c : cases) {
    const CliRun r = run(c.args + " --stats");
    EXPECT_EQ(r.status, 1) << c.args << ": " << r.out;
    EXPECT_NE(r.out.find(c.expect), std::string::npos) << c.args << ": " << r.out;
    EXPECT_EQ(r.out.find("in_vertices"), std::string::npos) << "no JSON on failure: " << r.out;
  }
}

TEST(ArrangeCli, StatsJsonHasTheContractKeys) {
  const std::filesystem::path mesh = tritri_test::shared_meshes_dir() / "cherchi_arrangements" / "two_spheres.stl";
  TRITRI_REQUIRE_DATA(mesh);
  const CliRun r = run(mesh.string() + " --stats --threads 1");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* key : {"in_vertices", "in_triangles", "merged_vertices", "removed_degenerate", "removed_duplicate",
                          "candidate_pairs", "intersecting_pairs", "intersection_points", "lpi", "segments",
                          "coplanar_pairs", "t_load_s", "t_detect_s", "t_classify_s"})
    EXPECT_NE(r.out.find(std::string("\"") + key + "\":"), std::string::npos) << key;
  // Two spheres of 800 triangles each cross along one closed curve: 132 pairs and points
  // (the same counts as the upstream 2020 pipeline reports for this file).
  EXPECT_NE(r.out.find("\"intersecting_pairs\": 132,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"intersection_points\": 132,"), std::string::npos) << r.out;
}

// ---------------------------------------------------------------------------------------
// Hostile arguments, run without a shell (tritri_test::spawn) so that empty arguments and
// spaces pass unchanged.

std::string shown(const std::vector<std::string>& args) {
  std::string s;
  for (const auto& a : args) s += (s.empty() ? "'" : " '") + a + "'";
  return s;
}

// Values no integer option takes (support/run_program.h), and an option in place of one.
const std::vector<std::string> kBadIntegers = tritri_test::bad_integer_values("--stats");

// A two-triangle model (B pierces A) in `dir`.
std::string two_triangles(const fs::path& dir) {
  const fs::path p = dir / "two_triangles.off";
  std::ofstream(p) << "OFF\n6 2 0\n0 0 0\n4 0 0\n0 4 0\n1 1 -1\n1 1 1\n2 1 1\n3 0 1 2\n3 3 4 5\n";
  return p.string();
}

// Every case must end with exit status 2, a message naming the tool, no output, no signal.
void expect_usage_errors(const std::string& program, const char* tool,
                         const std::vector<std::vector<std::string>>& cases, const fs::path& dir) {
  for (const auto& args : cases) {
    const Exit e = spawn(program, args, dir);
    EXPECT_TRUE(e.exited) << tool << " " << shown(args) << ": killed by signal " << e.signal;
    EXPECT_EQ(e.code, 2) << tool << " " << shown(args) << ": " << e.err;
    EXPECT_NE(e.err.find(std::string(tool) + ": "), std::string::npos) << shown(args) << ": " << e.err;
    EXPECT_EQ(e.out, "") << tool << " " << shown(args) << " wrote output";
  }
}

TEST(ArrangeCli, EveryHostileOptionValueIsAUsageError) {
  tritri_test::TempDir dir;
  const std::string mesh = two_triangles(dir.path());
  std::vector<std::vector<std::string>> cases;
  // --stats first: an argument wrongly accepted would print JSON.
  for (const std::string& v : kBadIntegers) cases.push_back({mesh, "--stats", "--threads", v});
  for (const char* v : {"1025", "4096", "65536", "100000"}) cases.push_back({mesh, "--stats", "--threads", v});
  for (const char* opt : {"-o", "--output"})
    for (const std::string v : {"", "x.txt", "noextension", "dir.ply/", "x.", "--stats"})
      cases.push_back({mesh, "--stats", opt, v});
  for (const std::string v : {"", "magic", "TRITRI", " tritri", "tritri ", "--stats"})
    cases.push_back({mesh, "--stats", "--classifier", v});
  for (const char* opt : {"--threads", "-o", "--output", "--classifier"}) cases.push_back({mesh, "--stats", opt});
  const std::vector<std::vector<std::string>> twice = {{"--threads", "1", "--threads", "1"},
                                                       {"--threads", "1", "--threads", "2"},
                                                       {"-o", "a.off", "-o", "a.off"},
                                                       {"-o", "a.off", "--output", "b.off"},
                                                       {"--classifier", "native", "--classifier", "tritri"}};
  for (auto args : twice) {
    for (auto& a : args)
      if (a.ends_with(".off")) a = dir.path(a);
    args.insert(args.begin(), {mesh, "--stats"});
    cases.push_back(args);
  }
  for (const char* opt : {"--bogus", "-x", "--threads=4", "--", "---", "--STATS", "-O"})
    cases.push_back({mesh, "--stats", opt});
  cases.push_back({mesh, "--stats", ""});  // an empty input file name
  cases.push_back({"", "--stats"});
  cases.push_back({});
  cases.push_back({"--stats"});
  cases.push_back({mesh, "--stats", "--exact", "-o", dir.path("x.ply")});
  // The move limit: a finite number above 0, only with --round safe, once.
  for (const std::string v : {"", "0", "-1", "0.0", "nan", "inf", "1e400", "0.5x", " 0.5", "1/64", "--stats"})
    cases.push_back({mesh, "--stats", "--round", "safe", "--round-max-move", v});
  cases.push_back({mesh, "--stats", "--round-max-move", "0.5"});
  cases.push_back({mesh, "--stats", "--round", "nearest", "--round-max-move", "0.5"});
  cases.push_back({mesh, "--stats", "--round", "safe", "--round-max-move", "0.5", "--round-max-move", "0.5"});
  // The steps left out: known names, comma-separated, only with --round safe, once.
  for (const std::string v :
       {"", "bogus", "nudging,", ",nudging", "nudging,,rerouting", "Nudging", "level_1", "nudging,rerouting,nudging"})
    cases.push_back({mesh, "--stats", "--round", "safe", "--round-without", v});
  cases.push_back({mesh, "--stats", "--round-without", "nudging"});
  cases.push_back({mesh, "--stats", "--round", "safe", "--round-without", "nudging", "--round-without", "nudging"});
  expect_usage_errors(ARRANGE_BIN, "arrange", cases, dir.path());
  EXPECT_EQ(dir.entries(), std::set<std::string>({"stdout.txt", "stderr.txt", "two_triangles.off"}))
      << "nothing was written";
}

TEST(ArrangeCli, ThreadCountsUpToTheCapRun) {
  tritri_test::TempDir dir;
  const std::string mesh = two_triangles(dir.path());
  for (const std::string& v :
       {std::string("0"), std::string("1"), std::string("0002"), std::to_string(arrangements::kMaxThreads)}) {
    const Exit e = spawn(ARRANGE_BIN, {mesh, "--stats", "--threads", v, "--check"}, dir.path());
    ASSERT_TRUE(e.exited) << v << ": signal " << e.signal;
    EXPECT_EQ(e.code, 0) << v << ": " << e.err;
    if (v != "0") {
      EXPECT_NE(e.out.find("\"threads\": " + std::to_string(std::stoi(v)) + ","), std::string::npos) << e.out;
    }
    EXPECT_NE(e.out.find("\"intersection_points\": 2,"), std::string::npos) << e.out;
  }
  const Exit help = spawn(ARRANGE_BIN, {"--help"}, dir.path());
  EXPECT_NE(help.out.find("to " + std::to_string(arrangements::kMaxThreads)), std::string::npos) << help.out;
}

// The keys listed by `arrange --help` (one per line, after "JSON keys (--stats)").
std::vector<std::string> help_keys() {
  const Exit help = spawn(ARRANGE_BIN, {"--help"}, fs::temp_directory_path().string());
  std::vector<std::string> keys;
  std::istringstream in(help.out);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("JSON keys (--stats)")) {
      inside = true;
    } else if (inside) {
      if (line.empty()) break;
      if (line.size() > 2 && line.starts_with("  ") && line[2] != ' ')
        keys.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return keys;
}

// The --stats JSON has exactly the keys of for_each_stat, in its order, and --help lists the
// same keys in the same order, each with its meaning, within 90 columns (all three come
// from kArrangeStats; tests/python/test_bindings.py compares them with the Python dict).
TEST(ArrangeCli, StatsJsonKeysAreTheSharedList) {
  tritri_test::TempDir dir;
  const Exit e = spawn(ARRANGE_BIN, {two_triangles(dir.path()), "--stats"}, dir.path());
  ASSERT_EQ(e.code, 0) << e.err;
  std::vector<std::string> printed, listed;
  const std::regex key("\"([a-z0-9_]+)\": ");
  for (auto it = std::sregex_iterator(e.out.begin(), e.out.end(), key); it != std::sregex_iterator(); ++it)
    printed.push_back((*it)[1]);
  arrangements::for_each_stat(arrangements::ArrangeStats{},
                              [&](const char* k, const auto&, int) { listed.push_back(k); });
  EXPECT_EQ(printed, listed) << e.out;
  EXPECT_EQ(listed.size(), 41u);
  EXPECT_EQ(help_keys(), listed);
  const std::string text = arrangements::stats_key_list(2, 26, 90);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 90u) << line;
  for (const arrangements::StatKey& k : arrangements::kArrangeStatKeys) {
    EXPECT_NE(std::string_view(k.meaning), "") << k.key;
    EXPECT_NE(text.find(std::string("  ") + k.key + " "), std::string::npos) << k.key;
  }
}

// --round safe writes doubles that are an arrangement: the written file arranged again
// finds nothing, and --check (on the rounded mesh) is clean; rounding to nearest does not
// give that on this mesh (rotated copies cross at grazing angles). Bad uses are usage errors.
TEST(ArrangeCli, RoundSafeWritesAMeshThatIsAnArrangement) {
  tritri_test::TempDir dir;
  // Five copies: they settle in 2 passes (merged input at nearest), faster than three,
  // whose one pass there fails and which settle by merged input's full ladder after
  // rerouting (about 20 passes).
  const arrangements::TriangleSoup soup =
      arrangements::rotated_copies(arrangements::uv_sphere({0.1, 0.2, 0.3}, 1.0, 12, 24), 5);
  const std::string in = (dir.path() / "copies.off").string();
  arrangements::write_off(in, soup.vertices, soup.triangles);
  const std::string safe = (dir.path() / "safe.obj").string(), near = (dir.path() / "near.obj").string();

  const CliRun r = run(in + " -o " + safe + " --round safe --stats --check");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find(" 0 violations, 0 degenerate"), std::string::npos) << r.out;
  const std::smatch passes = [&] {
    std::smatch m;
    std::regex_search(r.out, m, std::regex("\"round_passes\": ([0-9]+)"));
    return m;
  }();
  ASSERT_FALSE(passes.empty()) << r.out;
  EXPECT_GT(std::stoi(passes[1]), 1) << r.out;
  // Five copies meet at nearly coincident poles: merged input at nearest settles them in
  // one pass after level 0's (before it, rerouting spent 12 passes first: 14 in all).
  EXPECT_LE(std::stoi(passes[1]), 3) << r.out;
  EXPECT_EQ(r.out.find("\"round_merged_input\": 0,"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(safe + ".provenance.csv"));
  const CliRun again = run(safe + " --stats --check");
  ASSERT_EQ(again.status, 0) << again.out;
  for (const char* zero : {"\"lpi\": 0,", "\"tpi\": 0,", "\"intersecting_pairs\": 0,", "\"merged_vertices\": 0,",
                           "\"removed_degenerate\": 0,", "\"round_passes\": 0,"})
    EXPECT_NE(again.out.find(zero), std::string::npos) << zero << ": " << again.out;
  // --stats under --round safe counts the mesh written (issue 38): what reading it finds.
  auto count = [](const std::string& json, const std::string& key) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(json, m, std::regex("\"" + key + "\": ([0-9]+)"))) << key;
    return m.empty() ? std::string() : m[1].str();
  };
  EXPECT_EQ(count(r.out, "out_triangles"), count(again.out, "in_triangles"));
  EXPECT_EQ(count(r.out, "out_vertices"), count(again.out, "out_vertices"));

  ASSERT_EQ(run(in + " -o " + near).status, 0);
  const CliRun near_again = run(near + " --stats");
  ASSERT_EQ(near_again.status, 0) << near_again.out;
  EXPECT_EQ(near_again.out.find("\"intersecting_pairs\": 0,"), std::string::npos)
      << "rounding to nearest kept this mesh an arrangement: the test tells nothing";

  EXPECT_EQ(run(in + " -o " + safe + " --round safe --exact").status, 2);
  EXPECT_EQ(run(in + " -o " + safe + " --round nearest --exact").status, 2);
  EXPECT_EQ(run(in + " -o " + safe + " --round magic").status, 2);
  EXPECT_EQ(run(in + " -o " + safe + " --round safe --round safe").status, 2);
  EXPECT_EQ(run(in + " -o " + safe + " --round").status, 2);
  // A move limit given settles a small crossing (cheap: the copies above take seconds).
  const arrangements::TriangleSoup boxes =
      arrangements::concatenate(arrangements::box({0, 0, 0}, {2, 2, 2}), arrangements::box({1, -1, 0.5}, {3, 3, 2}));
  const std::string boxes_in = (dir.path() / "boxes.off").string();
  arrangements::write_off(boxes_in, boxes.vertices, boxes.triangles);
  EXPECT_EQ(run(boxes_in + " -o " + safe + " --round safe --round-max-move 0.25").status, 0);
}

// The helpers through which the tool adds its own load and write times keep t_total_s the
// sum of its parts.
TEST(ArrangeStats, LoadAndWriteTimesAddToTheTotal) {
  arrangements::ArrangeStats s;
  s.t_output_s = 0.25;
  s.t_total_s = 1;
  arrangements::add_load_time(s, 0.5);
  EXPECT_EQ(s.t_load_s, 0.5);
  EXPECT_EQ(s.t_total_s, 1.5);
  arrangements::add_write_time(s, 0.25);
  EXPECT_EQ(s.t_output_s, 0.5);
  EXPECT_EQ(s.t_total_s, 1.75);
  EXPECT_GT(s.peak_rss_mb, 0);
}

// Long meanings wrap at the width and continue at the meaning's column; a key that reaches
// the column puts its meaning on the next line.
TEST(ArrangeStats, KeyListWrapsAtTheWidth) {
  const std::string text = arrangements::stats_key_list(1, 8, 30);
  std::istringstream lines(text);
  std::size_t n = 0, keys = 0;
  for (std::string line; std::getline(lines, line); ++n) {
    EXPECT_TRUE(line.size() <= 30 || line.find(' ', 8) == std::string::npos) << line;
    if (line[1] != ' ') {
      ++keys;
      EXPECT_EQ(line[0], ' ') << line;
    } else {
      EXPECT_EQ(line.find_first_not_of(' '), 8u) << line;
    }
  }
  EXPECT_EQ(keys, arrangements::kArrangeStatKeys.size());
  EXPECT_GT(n, keys);
  EXPECT_NE(text.find(" intersection_points\n        distinct new"), std::string::npos) << text;
}

// ---------------------------------------------------------------------------------------
// Hostile input, round two: output that must not be lost, JSON that must stay JSON, files
// that arrange writes and must read.

// The flat JSON object --stats prints: key -> raw value; false unless every value is a
// JSON number, string or null (no inf, nan, or anything else).
bool flat_json(const std::string& text, std::map<std::string, std::string>& values) {
  static const std::regex member(
      R"re(\s*"([a-z0-9_]+)": (-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?|"[^"\\]*"|null)\s*(,|\})\s*)re");
  if (text.empty() || text.front() != '{') return false;
  std::size_t at = 1;
  std::smatch m;
  while (at < text.size()) {
    const std::string rest = text.substr(at);
    if (!std::regex_search(rest, m, member, std::regex_constants::match_continuous)) return false;
    values[m[1]] = m[2];
    at += m.length(0);
    if (m[6] == "}") return at == text.size();
  }
  return false;
}

TEST(ArrangeStats, JsonNeverHoldsNonFiniteNumbers) {
  arrangements::ArrangeStats s;
  s.round_max_move = std::numeric_limits<double>::infinity();
  s.round_max_move_rel = std::numeric_limits<double>::quiet_NaN();
  s.t_total_s = -std::numeric_limits<double>::infinity();
  s.peak_rss_mb = std::numeric_limits<double>::max();
  std::map<std::string, std::string> v;
  const std::string json = arrangements::stats_json(s);
  ASSERT_TRUE(flat_json(json, v)) << json;
  EXPECT_EQ(v["round_max_move"], "null");
  EXPECT_EQ(v["round_max_move_rel"], "null");
  EXPECT_EQ(v["t_total_s"], "null");
  EXPECT_EQ(v["peak_rss_mb"].size(), 311u) << "DBL_MAX with one decimal";
}

// Two triangles (B pierces A) scaled by 2^e: the crossing points are not doubles, so safe
// rounding moves them; the figures scale with the model (2^600: squared moves overflow a
// double; 2^-600: they underflow to 0).
std::map<std::string, std::string> scaled_round_safe_stats(const fs::path& dir, int e) {
  std::vector<arrangements::Vec3> V = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -1}, {1.3, 1.7, 1}, {2.1, 0.9, 1.1}};
  for (auto& p : V)
    for (double& c : p) c = std::ldexp(c, e);
  const std::string in = (dir / ("scaled" + std::to_string(e) + ".off")).string();
  arrangements::write_off(in, V, {{0, 1, 2}, {3, 4, 5}});
  const Exit r = spawn(ARRANGE_BIN, {in, "--round", "safe", "--stats", "--threads", "1"}, dir);
  EXPECT_EQ(r.code, 0) << e << ": " << r.err;
  std::map<std::string, std::string> v;
  EXPECT_TRUE(flat_json(r.out.substr(0, r.out.find_last_not_of('\n') + 1), v)) << e << ": " << r.out;
  return v;
}

TEST(ArrangeCli, RoundSafeStatsAreJsonAndScaleWithTheModel) {
  tritri_test::TempDir dir;
  const auto unit = scaled_round_safe_stats(dir.path(), 0);
  const double move = std::stod(unit.at("round_max_move")), rel = std::stod(unit.at("round_max_move_rel"));
  ASSERT_GT(move, 0);
  ASSERT_GT(rel, 0);
  for (int e : {600, -600, 560, -560}) {
    const auto v = scaled_round_safe_stats(dir.path(), e);
    if (!v.count("round_max_move_rel")) continue;  // refused or not JSON: failed above
    EXPECT_EQ(v.at("round_max_move_rel"), unit.at("round_max_move_rel")) << e;
    EXPECT_NEAR(std::stod(v.at("round_max_move")) / std::ldexp(move, e), 1, 1e-3) << e;
  }
}

// A failed write to standard output is an error (exit status 1, a message), never lost
// output with status 0: a full device, a closed stdout.
TEST(ArrangeCli, AFailedWriteToStandardOutputExitsWithOne) {
  tritri_test::TempDir dir;
  const std::string mesh = two_triangles(dir.path());
  const bool full = fs::exists("/dev/full");
  for (const std::string& args : {mesh + " --stats", std::string("--help"), mesh + " --stats -o " + dir.path("o.off")})
    for (const std::string& redirect : {std::string(" >/dev/full"), std::string(" >&-")}) {
      if (redirect == " >/dev/full" && !full) continue;
      // stderr into the pipe, stdout to the failing place.
      const auto r = tritri_test::run_command(std::string(ARRANGE_BIN) + " " + args + " 2>&1" + redirect);
      EXPECT_EQ(r.status, 1) << args << redirect << ": " << r.out;
      EXPECT_NE(r.out.find("arrange: "), std::string::npos) << args << redirect << ": " << r.out;
      EXPECT_NE(r.out.find("standard output"), std::string::npos) << args << redirect << ": " << r.out;
    }
  // Nothing written to stdout: a closed stdout does not matter.
  EXPECT_EQ(tritri_test::run_command(std::string(ARRANGE_BIN) + " " + mesh + " 2>&1 >&-").status, 0);
}

// -o takes any file name the system takes (up to NAME_MAX bytes; OBJ and OFF also need
// room for ".provenance.csv"): the temporary file beside it has a short name of its own.
TEST(ArrangeCli, OutputNamesUpToTheSystemLimitAreWritten) {
  tritri_test::TempDir dir;
  const std::string mesh = two_triangles(dir.path());
  for (const auto& [length, ext] : std::vector<std::pair<std::size_t, std::string>>{
           {236, ".ply"}, {251, ".ply"}, {255, ".ply"}, {236, ".off"}, {240, ".obj"}}) {
    const std::string name = std::string(length - ext.size(), 'n') + ext;
    const Exit e = spawn(ARRANGE_BIN, {mesh, "-o", dir.path(name)}, dir.path());
    EXPECT_EQ(e.code, 0) << length << ext << ": " << e.err;
    EXPECT_EQ(spawn(ARRANGE_BIN, {dir.path(name)}, dir.path()).code, 0) << length << ext;
    std::error_code ec;  // a side file's name may be too long for the system (.ply has none)
    fs::remove(dir.path(name), ec);
    fs::remove(dir.path(name + ".provenance.csv"), ec);
  }
  EXPECT_EQ(dir.entries(), std::set<std::string>({"stdout.txt", "stderr.txt", "two_triangles.off"}))
      << "no temporary file stays";
}

// Replacing an output file keeps its permission bits (and those of its side file); a new
// file gets the usual 0666 minus the umask.
TEST(ArrangeCli, ReplacingAnOutputFileKeepsItsMode) {
  tritri_test::TempDir dir;
  const std::string mesh = two_triangles(dir.path());
  auto mode = [](const std::string& p) {
    struct stat st {};
    EXPECT_EQ(::stat(p.c_str(), &st), 0) << p;
    return st.st_mode & 07777;
  };
  const std::string fresh = dir.path("fresh.off"), reference = dir.write("reference.txt", "");
  ASSERT_EQ(spawn(ARRANGE_BIN, {mesh, "-o", fresh}, dir.path()).code, 0);
  EXPECT_EQ(mode(fresh), mode(reference));
  EXPECT_EQ(mode(fresh + ".provenance.csv"), mode(reference));
  for (const ::mode_t m : {0600, 0640, 0604, 0755}) {
    for (const std::string& p : {fresh, fresh + ".provenance.csv"}) ASSERT_EQ(::chmod(p.c_str(), m), 0);
    ASSERT_EQ(spawn(ARRANGE_BIN, {mesh, "-o", fresh}, dir.path()).code, 0);
    EXPECT_EQ(mode(fresh), m);
    EXPECT_EQ(mode(fresh + ".provenance.csv"), m);
  }
}

// An arrangement with no triangles (degenerate input only) is written as an empty mesh,
// which arrange reads again, in every format, and with every option.
TEST(ArrangeCli, AnEmptyArrangementIsWrittenAndReadAgain) {
  tritri_test::TempDir dir;
  const std::string degenerate =
      dir.write("degenerate.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n3 0 1 2\n3 0 0 3\n");
  for (const char* ext : {".off", ".obj", ".ply"}) {
    const std::string out = dir.path(std::string("empty") + ext), again = dir.path(std::string("again") + ext);
    const Exit w = spawn(ARRANGE_BIN, {degenerate, "-o", out, "--stats"}, dir.path());
    ASSERT_EQ(w.code, 0) << w.err;
    EXPECT_NE(w.out.find("\"out_triangles\": 0,"), std::string::npos) << w.out;
    std::vector<std::vector<std::string>> reruns = {
        {out, "--stats", "-o", again}, {out, "--round", "safe", "--check", "-o", again}, {out, "--scale", "--check"},
        {out, two_triangles(dir.path()), out, "--stats"}};
    if (std::string(ext) != ".ply") reruns.push_back({out, "--exact", "-o", again});
    for (const auto& args : reruns) {
      const Exit r = spawn(ARRANGE_BIN, args, dir.path());
      EXPECT_EQ(r.code, 0) << ext << " " << shown(args) << ": " << r.err;
    }
  }
}

TEST(MakeTestMeshesCli, EveryHostileOptionValueIsAUsageError) {
  const fs::path program = fs::path(ARRANGE_BIN).parent_path() / "make_test_meshes";
  if (!fs::exists(program)) GTEST_SKIP() << "make_test_meshes is not built beside arrange";
  tritri_test::TempDir dir;
  const std::string out = dir.path("meshes");
  std::vector<std::vector<std::string>> cases;
  for (const std::string& v : kBadIntegers) cases.push_back({out, "--rotated-copies", v});
  for (const char* v : {"0", "129", "100000"}) cases.push_back({out, "--rotated-copies", v});
  cases.push_back({out, "--rotated-copies"});
  cases.push_back({out, "--rotated-copies", "1", "--rotated-copies", "1"});
  for (const char* opt : {"--bogus", "-x", "--rotated-copies=2", "--"}) cases.push_back({out, opt});
  cases.push_back({out, dir.path("other")});  // two OUTDIRs
  cases.push_back({""});
  cases.push_back({});
  cases.push_back({"--rotated-copies", "2"});
  expect_usage_errors(program.string(), "make_test_meshes", cases, dir.path());
  EXPECT_FALSE(fs::exists(out)) << "nothing was written";

  const Exit ok = spawn(program.string(), {out, "--rotated-copies", "1"}, dir.path());
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(fs::path(out) / "sphere_copies_1.off"));
}

}  // namespace
