// tests/fuzz/fuzz_csg.cpp: libFuzzer target for the OpenSCAD .csg reader and the loading of
// its operands (tests/fuzz/README.md; the operands a.off, b.obj, c.stl, d.ply are beside it).
#include "arrangements/load_csg.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return tritri_fuzz::fuzz_file(data, size, "csg", [](const std::string& path) { arrangements::load_csg_file(path); });
}
