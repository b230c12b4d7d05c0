// tests/support/shared_meshes.h
//
// Where tests find data that is not part of the project:
//   shared_meshes_dir()  the shared mesh collection (../shared/meshes beside the checkout;
//                        override with the environment variable TRITRI_MESHES_DIR)
//   TRITRI_REQUIRE_DATA(path)  in a test that needs `path`: when it does not exist, the test
//                        fails in CI (environment CI=true, as .ci/run runs, or
//                        TRITRI_REQUIRE_SHARED_MESHES=1) and is skipped elsewhere, so a
//                        green CI run never means "not run"
//   mesh_files(dir)      the mesh files under dir, sorted
//   bad_input_dir()      tests/bad_input, small hand-written files that must be refused
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tritri_test {

inline std::filesystem::path shared_meshes_dir() {
  if (const char* dir = std::getenv("TRITRI_MESHES_DIR")) return dir;
  // TRITRI_TESTS_DIR (tests/CMakeLists.txt) is <checkout>/tests, absolute (__FILE__ may be
  // relative, e.g. under ccache's base_dir).
  return std::filesystem::path(TRITRI_TESTS_DIR).parent_path().parent_path() / "shared" / "meshes";
}

inline bool shared_meshes_required() {
  const char* ci = std::getenv("CI");
  const char* req = std::getenv("TRITRI_REQUIRE_SHARED_MESHES");
  return (ci && std::string_view(ci) == "true") || (req && std::string_view(req) == "1");
}

#define TRITRI_REQUIRE_DATA(path)                                   \
  do {                                                              \
    if (!std::filesystem::exists(path)) {                           \
      if (tritri_test::shared_meshes_required()) {                  \
        FAIL() << "missing test data (required in CI): " << (path); \
      }                                                             \
      GTEST_SKIP() << "no test data at " << (path);                 \
    }                                                               \
  } while (0)

// The mesh files (.obj .off .stl .ply, any case) under dir, sorted.
inline std::vector<std::filesystem::path> mesh_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::string ext = entry.path().extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == ".obj" || ext == ".off" || ext == ".stl" || ext == ".ply") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

inline std::filesystem::path bad_input_dir() { return std::filesystem::path(TRITRI_TESTS_DIR) / "bad_input"; }

}  // namespace tritri_test
