// The inputs of the fuzz targets (tests/fuzz/README.md), loaded exactly as the targets load
// them (tests/fuzz/fuzz_common.h: written to a file of the reader's extension, beside the
// CSG operands a.off, b.obj, c.stl, d.ply), in the ordinary builds (Release and the
// ASan/UBSan build):
// - tests/fuzz/regressions/<reader>/: inputs that once found a bug; each must load or be
//   refused with an InputError (fuzz_file catches it), never crash or throw anything else;
// - tests/fuzz/corpus/<reader>/: the seeds, valid files of every variant; each must load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "arrangements/load_csg.h"
#include "arrangements/load_triangle_soup.h"
#include "fuzz/fuzz_common.h"

namespace {

namespace fs = std::filesystem;
const char* const kReaders[] = {"obj", "off", "stl", "ply", "csg"};

void load(const std::string& reader, const std::string& path) {
  if (reader == "csg")
    arrangements::load_csg_file(path);
  else
    arrangements::load_mesh_files({path});
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  return files;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzRegressions, LoadOrRefuseCleanly) {
  for (const char* reader : kReaders) {
    for (const fs::path& file : files_in(fs::path(TRITRI_TESTS_DIR) / "fuzz" / "regressions" / reader)) {
      SCOPED_TRACE(file.string());
      const std::string bytes = bytes_of(file);
      tritri_fuzz::fuzz_file(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), reader,
                             [&](const std::string& path) { load(reader, path); });
    }
  }
}

TEST(FuzzRegressions, SeedsLoad) {
  for (const char* reader : kReaders) {
    const std::vector<fs::path> seeds = files_in(fs::path(TRITRI_TESTS_DIR) / "fuzz" / "corpus" / reader);
    EXPECT_FALSE(seeds.empty()) << reader;
    for (const fs::path& file : seeds) {
      if (file.filename() == "missing.csg") continue;  // an import of a missing file: refused
      SCOPED_TRACE(file.string());
      const std::string path = tritri_fuzz::temp_dir() + "/input." + reader;
      tritri_fuzz::write_file(path, bytes_of(file));
      EXPECT_NO_THROW(load(reader, path));
    }
  }
}

}  // namespace
