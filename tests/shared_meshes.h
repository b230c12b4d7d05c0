// Where tests find data that is not part of the project:
//   shared_meshes_dir()  the shared mesh collection (../shared/meshes beside the checkout;
//                        override with the environment variable TRITRI_MESHES_DIR); tests
//                        that need it call GTEST_SKIP when it does not exist
//   bad_input_dir()      tests/bad_input, small hand-written files that must be refused
#pragma once

#include <cstdlib>
#include <filesystem>

namespace tritri_test {

inline std::filesystem::path shared_meshes_dir() {
  if (const char* dir = std::getenv("TRITRI_MESHES_DIR")) return dir;
  // __FILE__ is <checkout>/tests/shared_meshes.h.
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "shared" / "meshes";
}

inline std::filesystem::path bad_input_dir() { return std::filesystem::path(__FILE__).parent_path() / "bad_input"; }

}  // namespace tritri_test
