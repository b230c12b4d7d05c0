// make_test_meshes: writes the project's embedded default meshes (generated, no download)
// into a folder, as OFF files. See --help.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "support/command_line.h"
#include "support/mesh_generators.h"
#include "io/write_off.h"

namespace {

const char* kUsage = R"(usage: make_test_meshes OUTDIR [--rotated-copies K]

Writes generated test meshes into OUTDIR (created if needed):
  two_spheres.off          two overlapping UV spheres (curves of edge-face crossings)
  cube_through_cube.off    a box pushed through another (crossings and coplanar contact)
  coplanar_grids.off       two flat grids overlapping in one plane (coplanar crossings)
  grid_through_sphere.off  a flat grid cutting a sphere
  sphere_copies_K.off      K copies of a sphere rotated about the z axis (only with
                           --rotated-copies K; intersections grow like K^2: K = 8 with the
                           default resolution gives over a million intersection points;
                           K from 1 to 128)
--rotated-copies may be given once; K is plain decimal digits.
exit status: 0 success, 1 the files could not be written, 2 bad command line.
)";

// Each copy has about 39,000 triangles: 128 copies write about 5 million triangles.
constexpr long long kMaxCopies = 128;

}  // namespace

int main(int argc, char** argv) {
  using namespace arrangements;
  std::optional<std::string> out;
  int copies = 0;
  detail::CommandLine args("make_test_meshes", argc, argv);
  while (args.next()) {
    const std::string& a = args.current();
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--rotated-copies") {
      copies = static_cast<int>(args.count("--rotated-copies", 1, kMaxCopies));
    } else {
      const std::string& dir = args.operand("OUTDIR");
      if (out) args.usage_error("one OUTDIR only, got '" + *out + "' and '" + dir + "'");
      out = dir;
    }
  }
  if (!out) args.usage_error("no OUTDIR");
  try {
    std::filesystem::create_directories(*out);
    auto write = [&](const std::string& name, const TriangleSoup& s) {
      write_off((std::filesystem::path(*out) / name).string(), s.vertices, s.triangles);
      std::printf("%s: %zu triangles\n", name.c_str(), s.triangles.size());
    };
    write("two_spheres.off", concatenate(uv_sphere({0, 0, 0}, 1.0, 24, 48), uv_sphere({0.6, 0.25, 0.15}, 0.8, 20, 40)));
    write("cube_through_cube.off", concatenate(box({0, 0, 0}, {2, 2, 2}), box({1, -1, 0.5}, {3, 3, 2})));
    write("coplanar_grids.off", concatenate(grid(16, 0.5, 0.0), grid(15, 0.5, 0.0, 0.25, 0.125)));
    write("grid_through_sphere.off", concatenate(grid(32, 0.0625, 0.0, -1, -1), uv_sphere({0, 0, 0}, 0.9, 24, 48)));
    if (copies > 0)
      write("sphere_copies_" + std::to_string(copies) + ".off",
            rotated_copies(uv_sphere({0, 0, 0}, 1.0, 100, 197), copies));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_test_meshes: %s\n", e.what());
    return 1;
  }
}
