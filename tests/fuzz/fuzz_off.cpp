// tests/fuzz/fuzz_off.cpp: libFuzzer target for the .off reader (tests/fuzz/README.md).
#include "arrangements/load_triangle_soup.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tritri_fuzz::fuzz_file(data, size, "off", [](const std::string& path) { arrangements::load_mesh_files({path}); });
}
