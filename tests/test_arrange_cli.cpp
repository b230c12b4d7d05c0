// The `arrange` command line: exit codes, messages and the --stats JSON contract, run as a
// separate process (the path of the binary comes from CMake).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include "shared_meshes.h"
#include "test_support.h"

namespace {

using CliRun = tritri_test::CommandRun;

CliRun run(const std::string& args) { return tritri_test::run_command(std::string(ARRANGE_BIN) + " " + args + " 2>&1"); }

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
      {bad("empty_file.obj"), "empty_file.obj"},
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
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "no shared meshes";
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

}  // namespace
