// tests/fuzz/fuzz_common.h: what the fuzz targets share (tests/fuzz/README.md).
//
// The readers take paths, so fuzz_file(data, size, ext, load) writes the input to
// <private temp dir in /dev/shm or /tmp>/input.<ext> and calls load(path). InputError is the expected answer to
// bad input and returns normally; any other exception escapes and aborts, which libFuzzer
// reports as a finding, as it does a crash, a sanitizer report, a leak, a timeout or an
// out-of-memory. The temp dir also holds small valid operands (a.off, b.obj, c.stl, d.ply)
// for the import() statements of fuzz_csg's inputs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

#include "arrangements/input_error.h"

namespace tritri_fuzz {

inline void write_file(const std::string& path, const void* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
}

inline void write_file(const std::string& path, const std::string& text) { write_file(path, text.data(), text.size()); }

// The process's temp dir, made (with the operands) on first use and removed at exit.
inline const std::string& temp_dir() {
  static const std::string dir = [] {
    // /dev/shm when there is one: every execution writes its input, and a disk-backed
    // /tmp made that write most of an execution's time.
    std::error_code shm_ec;
    const bool shm = std::filesystem::is_directory("/dev/shm", shm_ec) && access("/dev/shm", W_OK) == 0;
    std::string pattern = std::string(shm ? "/dev/shm" : "/tmp") + "/tritri-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) {
      std::perror("mkdtemp");
      std::abort();
    }
    write_file(pattern + "/a.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    write_file(pattern + "/b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    write_file(pattern + "/c.stl",
               "solid c\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\n"
               "endfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\n"
               "endfacet\nendsolid c\n");
    write_file(pattern + "/d.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
               "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
               "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    static const std::string removed = pattern;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(removed, ec);
    });
    return pattern;
  }();
  return dir;
}

template <class Load>
int fuzz_file(const std::uint8_t* data, std::size_t size, const char* ext, Load load) {
  const std::string path = temp_dir() + "/input." + ext;
  write_file(path, data, size);
  try {
    load(path);
  } catch (const arrangements::InputError&) {
  }
  return 0;
}

}  // namespace tritri_fuzz
