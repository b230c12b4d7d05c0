// The `tritri-compare` command line, run as a separate process (COMPARE_BIN comes from
// CMake) on generated meshes written to a temporary folder: exit codes, the JSON contract,
// the injected disagreement, several files as one model, and refused input. The reported
// number of intersection points is checked against the pipeline run in this process
// (arrangements::run_pipeline keeping the graph, both classifiers) and, for a two-triangle model,
// against a count derived by hand. Hostile option values (every option, table-driven) are
// usage errors: exit status 2 and a message, never a signal.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>

#include <unistd.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pipeline.h"
#include "arrangements/load_triangle_soup.h"
#include "support/mesh_generators.h"
#include "arrangements/thread_count.h"
#include "io/write_off.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using namespace arrangements;

struct CliRun {
  int status = -1;
  std::string out, err;
};

// Runs the tool with `args`; stdout through the pipe, stderr through a file.
CliRun run(const std::string& args, const fs::path& dir) {
  const fs::path err_file = dir / "stderr.txt";
  const auto r = tritri_test::run_command(std::string(COMPARE_BIN) + " " + args + " 2>" + err_file.string());
  std::ifstream in(err_file);
  return {r.status, r.out, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
}

// Minimal JSON reading: the raw value of `key` at any depth (first occurrence): a string
// (with quotes), a balanced object or list, or a scalar token. "" when the key is absent.
std::string raw_value(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\": ";
  const std::size_t at = json.find(pattern);
  if (at == std::string::npos) return "";
  std::size_t i = at + pattern.size(), j = i;
  if (i >= json.size()) return "";
  if (json[i] == '"') {
    for (j = i + 1; j < json.size() && json[j] != '"'; ++j)
      if (json[j] == '\\') ++j;
    return json.substr(i, j + 1 - i);
  }
  if (json[i] == '{' || json[i] == '[') {
    int depth = 0;
    bool in_string = false;
    for (j = i; j < json.size(); ++j) {
      const char c = json[j];
      if (in_string) {
        if (c == '\\')
          ++j;
        else if (c == '"')
          in_string = false;
      } else if (c == '"') {
        in_string = true;
      } else if (c == '{' || c == '[') {
        ++depth;
      } else if ((c == '}' || c == ']') && --depth == 0) {
        return json.substr(i, j + 1 - i);
      }
    }
    return "";
  }
  while (j < json.size() && json[j] != ',' && json[j] != '}' && json[j] != ']' && json[j] != '\n') ++j;
  return json.substr(i, j - i);
}

long long integer(const std::string& json, const std::string& key) {
  const std::string v = raw_value(json, key);
  if (v.empty()) {
    ADD_FAILURE() << "no key " << key;
    return -1;
  }
  std::size_t used = 0;
  const long long x = std::stoll(v, &used);
  EXPECT_EQ(used, v.size()) << key << " is not an integer: " << v;
  return x;
}

// The top-level keys of the contract, and the keys of each classifier's object.
const char* kTopKeys[] = {"file",         "in_vertices",    "in_triangles", "intersection_points",
                          "points_equal", "segments_equal", "counts_equal", "euler_equal",
                          "agree",        "differences",    "native",       "tritri"};
const char* kRunKeys[] = {"t_classify_s", "t_total_s", "out_vertices",   "out_triangles",
                          "euler",        "out_edges", "orient3d_calls", "orient2d_calls"};

// Each test writes its files in a fresh folder (dir_), removed afterwards.
class TritriCompare : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const TriangleSoup& s) {
    const fs::path p = dir_ / name;
    write_off(p.string(), s.vertices, s.triangles);
    return p.string();
  }
  std::string write_text(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  CliRun compare(const std::string& args) { return run(args, dir_); }

  // The tool's JSON for `files` must state agreement, carry every contract key, and report
  // the counts this process finds with the pipeline itself.
  void expect_agreement(const std::vector<std::string>& files) {
    std::string args, file_list;
    for (const auto& f : files) {
      args += f + " ";
      file_list += (file_list.empty() ? "" : " + ") + f;
    }
    const CliRun r = compare(args + "--json --threads 2");
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    const std::string& j = r.out;
    for (const char* key : kTopKeys) EXPECT_NE(raw_value(j, key), "") << key << " missing: " << j;
    for (const char* key : {"native", "tritri"}) {
      const std::string obj = raw_value(j, key);
      ASSERT_FALSE(obj.empty()) << key;
      EXPECT_EQ(obj.front(), '{') << key;
      for (const char* k : kRunKeys) EXPECT_NE(raw_value(obj, k), "") << key << "." << k << " missing: " << obj;
      EXPECT_GE(std::stod(raw_value(obj, "t_classify_s")), 0.0);
      EXPECT_GE(std::stod(raw_value(obj, "t_total_s")), std::stod(raw_value(obj, "t_classify_s")));
      // Classified pairs cost counted predicates (coplanar grids: only orient2d, since stage 2
      // settles every non-coplanar pair; aligned grids, once their duplicates are removed, have
      // no pair left to classify).
      if (integer(obj, "classified_pairs") > 0) {
        EXPECT_GT(integer(obj, "orient3d_calls") + integer(obj, "orient2d_calls"), 0) << key;
      }
    }
    for (const char* key : {"agree", "points_equal", "segments_equal", "counts_equal", "euler_equal"})
      EXPECT_EQ(raw_value(j, key), "true") << key << ": " << j;
    EXPECT_EQ(raw_value(j, "differences"), "[]");
    EXPECT_EQ(raw_value(j, "file"), "\"" + file_list + "\"");

    // The same model through the pipeline in this process.
    const TriangleSoup input = load_triangle_soups(files);
    ArrangeOptions options;
    options.threads = 2;
    for (Classifier c : {Classifier::Native, Classifier::Tritri}) {
      options.classifier = c;
      PipelineInternals internals;
      const ArrangeResult res = run_pipeline(input, options, &internals);
      const long long new_points =
          static_cast<long long>(internals.graph.points.size()) - internals.graph.num_input_vertices;
      EXPECT_EQ(integer(j, "intersection_points"), new_points) << (c == Classifier::Native ? "native" : "tritri");
      const std::string obj = raw_value(j, c == Classifier::Native ? "native" : "tritri");
      EXPECT_EQ(integer(obj, "out_vertices"), static_cast<long long>(res.mesh.vertices.size()));
      EXPECT_EQ(integer(obj, "out_triangles"), static_cast<long long>(res.mesh.triangles.size()));
      EXPECT_EQ(integer(obj, "euler"), res.stats.euler);
    }
    EXPECT_EQ(integer(j, "in_vertices"), static_cast<long long>(input.vertices.size()));
    EXPECT_EQ(integer(j, "in_triangles"), static_cast<long long>(input.triangles.size()));
    EXPECT_EQ(integer(raw_value(j, "native"), "euler"), integer(raw_value(j, "tritri"), "euler"));
  }

  const tritri_test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(TritriCompare, TwoSpheresAgree) {
  const TriangleSoup s = concatenate(uv_sphere({0, 0, 0}, 1, 10, 16), uv_sphere({0.5, 0.25, 0.125}, 1, 12, 14));
  expect_agreement({write("two_spheres.off", s)});
}

TEST_F(TritriCompare, CubeThroughCubeAgrees) {
  // A bar through a cube (crossing faces), and a cube overlapping it with coplanar faces.
  expect_agreement({write("bar_through_cube.off", concatenate(box({0, 0, 0}, {4, 4, 4}), box({-1, 1, 1}, {5, 3, 3})))});
  expect_agreement({write("coplanar_cubes.off", concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 0}, {3, 3, 2})))});
}

TEST_F(TritriCompare, CoplanarGridsAgree) {
  // Two grids in z = 0, shifted by dyadic offsets: edges cross edges in the common plane.
  expect_agreement({write("coplanar_grids.off", concatenate(grid(4, 1, 0), grid(4, 1, 0, 0.5, 0.25)))});
  // Same lattice, shifted by whole cells: shared vertices and overlapping edges.
  expect_agreement({write("aligned_grids.off", concatenate(grid(4, 0.5, 0), grid(4, 0.5, 0, 1, 0.5)))});
}

TEST_F(TritriCompare, TwoFilesFormOneModel) {
  // One triangle per file: A in z = 0; B in the plane y = 1 pierces A with its edge 0
  // (vertical at (1,1)) and its edge 2 (from (2,1,1) to (1,1,-1), through z = 0 at
  // x = 3/2): two intersection points, neither file alone has any.
  TriangleSoup a, b;
  a.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  a.triangles = {{0, 1, 2}};
  b.vertices = {{1, 1, -1}, {1, 1, 1}, {2, 1, 1}};
  b.triangles = {{0, 1, 2}};
  const std::string fa = write("a.off", a), fb = write("b.off", b);
  expect_agreement({fa, fb});
  const CliRun r = compare(fa + " " + fb + " --json");
  EXPECT_EQ(integer(r.out, "intersection_points"), 2);
  EXPECT_EQ(integer(r.out, "in_triangles"), 2);
  EXPECT_EQ(integer(r.out, "in_vertices"), 6);
  for (const std::string& f : {fa, fb}) {
    const CliRun one = compare(f + " --json");
    EXPECT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(integer(one.out, "intersection_points"), 0) << f;
    EXPECT_EQ(integer(one.out, "in_triangles"), 1) << f;
  }
  // Two spheres in two files agree too.
  expect_agreement(
      {write("s1.off", uv_sphere({0, 0, 0}, 1, 8, 12)), write("s2.off", uv_sphere({0.75, 0, 0}, 1, 8, 12))});
}

TEST_F(TritriCompare, InjectedDisagreementIsReported) {
  const std::string f = write("bar.off", concatenate(box({0, 0, 0}, {4, 4, 4}), box({-1, 1, 1}, {5, 3, 3})));
  const CliRun r = compare(f + " --json --inject-disagreement");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_EQ(raw_value(r.out, "agree"), "false") << r.out;
  EXPECT_EQ(raw_value(r.out, "points_equal"), "false") << r.out;
  const std::string diffs = raw_value(r.out, "differences");
  ASSERT_GE(diffs.size(), 2u) << r.out;
  EXPECT_EQ(diffs.front(), '[');
  EXPECT_NE(diffs, "[]") << r.out;
  EXPECT_NE(diffs.find('"'), std::string::npos) << "a listed difference: " << diffs;
  // The text summary says so too.
  const CliRun text = compare(f + " --inject-disagreement");
  EXPECT_EQ(text.status, 1);
  EXPECT_NE(text.out.find("DISAGREE"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("difference:"), std::string::npos) << text.out;
  // Without the option the same model agrees.
  EXPECT_EQ(compare(f + " --json").status, 0);
}

TEST_F(TritriCompare, BadInputExitsWithTwoAndAMessage) {
  const std::string missing = (dir_ / "no_such_mesh.off").string();
  const std::string truncated = write_text("truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n");
  const std::string garbage = write_text("garbage.off", "OFF\n3 1 0\n0 0 zero\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string unknown = write_text("mesh.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  const std::string good = write("good.off", box({0, 0, 0}, {1, 1, 1}));
  for (const std::string& f : {missing, truncated, garbage, unknown}) {
    const std::string name = fs::path(f).filename().string();
    const CliRun r = compare(f + " --json");
    EXPECT_EQ(r.status, 2) << f << ": " << r.out << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << "stderr names the file: " << r.err;
    EXPECT_EQ(r.out.find("\"agree\""), std::string::npos) << "no JSON on failure: " << r.out;
    // A bad file among good ones still fails the model.
    EXPECT_EQ(compare(good + " " + f + " --json").status, 2) << f;
  }
  EXPECT_EQ(compare(good + " --json").status, 0);
}

TEST_F(TritriCompare, BadOptionsExitWithTwo) {
  const std::string good = write("good.off", box({0, 0, 0}, {1, 1, 1}));
  for (const std::string& args : {std::string(""), std::string("--json"), good + " --no-such-option",
                                  good + " --threads", good + " --threads two", good + " --threads -1",
                                  good + " --max-differences", good + " --max-differences 1.5"}) {
    const CliRun r = compare(args);
    EXPECT_EQ(r.status, 2) << "'" << args << "': " << r.out;
    EXPECT_FALSE(r.err.empty()) << "'" << args << "' gives a message";
  }
}

TEST_F(TritriCompare, HelpExitsWithZeroAndNamesTheContract) {
  const CliRun r = compare("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* word :
       {"--json", "--inject-disagreement", "--threads", "intersection_points", "agree", "exit status"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

// Output that cannot be written (a full device, a closed stdout) is an error: status 2 (1
// would say the classifiers disagree) and a message, never status 0 with the output lost.
TEST_F(TritriCompare, AFailedWriteToStandardOutputExitsWithTwo) {
  const std::string good = write("cubes.off", concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3})));
  for (const std::string& args : {good + " --json", good, std::string("--help")})
    for (const std::string redirect : {" >/dev/full", " >&-"}) {
      if (redirect == " >/dev/full" && !fs::exists("/dev/full")) continue;
      const auto r = tritri_test::run_command(std::string(COMPARE_BIN) + " " + args + " 2>&1" + redirect);
      EXPECT_EQ(r.status, 2) << args << redirect << ": " << r.out;
      EXPECT_NE(r.out.find("tritri-compare: cannot write to standard output"), std::string::npos)
          << args << redirect << ": " << r.out;
    }
}

// Runs the tool with exactly `args` (no shell: empty arguments pass unchanged); status 2 and
// a message on stderr expected, no signal, nothing on stdout.
void expect_usage_error(const std::vector<std::string>& args, const fs::path& dir) {
  const tritri_test::Exit e = tritri_test::spawn(COMPARE_BIN, args, dir);
  std::string shown;
  for (const auto& a : args) shown += "'" + a + "' ";
  EXPECT_TRUE(e.exited) << shown << ": killed by signal " << e.signal;
  EXPECT_EQ(e.code, 2) << shown << ": " << e.err;
  EXPECT_NE(e.err.find("tritri-compare: "), std::string::npos) << shown << ": " << e.err;
  EXPECT_EQ(e.out, "") << shown;
}

TEST_F(TritriCompare, EveryHostileOptionValueIsAUsageError) {
  const std::string good = write("good.off", box({0, 0, 0}, {1, 1, 1}));
  const std::vector<std::string> bad_integers = tritri_test::bad_integer_values("--json");
  std::vector<std::vector<std::string>> cases;
  for (const char* opt : {"--threads", "--repeat", "--max-differences"}) {
    for (const std::string& v : bad_integers) cases.push_back({good, "--json", opt, v});
    cases.push_back({good, "--json", opt});                 // missing value
    cases.push_back({good, "--json", opt, "1", opt, "1"});  // given twice
  }
  // Beyond each option's range: threads above the shared cap (65536 and more crashed oneTBB),
  // no runs, more differences than listed.
  for (const char* v : {"1025", "4096", "65536", "70000", "100000", "1000000"})
    cases.push_back({good, "--json", "--threads", v});
  cases.push_back({good, "--json", "--repeat", "0"});
  cases.push_back({good, "--json", "--repeat", "1000001"});
  cases.push_back({good, "--json", "--max-differences", "1000001"});
  for (const char* opt : {"--bogus", "-x", "--threads=2", "--", "---", "--JSON"})
    cases.push_back({good, "--json", opt});
  cases.push_back({good, "--json", ""});  // an empty input file name
  cases.push_back({"", "--json"});
  cases.push_back({});
  cases.push_back({"--json"});
  for (const auto& args : cases) expect_usage_error(args, dir_);
}

TEST_F(TritriCompare, ThreadCountsUpToTheCapRun) {
  const std::string good = write("good.off", concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, -1, 0.5}, {3, 3, 2})));
  for (const int t : {0, 1, arrangements::kMaxThreads}) {
    const CliRun r = compare(good + " --json --repeat 2 --max-differences 0 --threads " + std::to_string(t));
    EXPECT_EQ(r.status, 0) << t << ": " << r.err;
    EXPECT_EQ(raw_value(r.out, "agree"), "true") << r.out;
    if (t > 0) {
      EXPECT_EQ(integer(raw_value(r.out, "tritri"), "threads"), t);
    }
  }
  EXPECT_NE(compare("--help").out.find("to " + std::to_string(arrangements::kMaxThreads)), std::string::npos);
}

}  // namespace
