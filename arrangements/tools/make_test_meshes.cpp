// make_test_meshes: writes the project's embedded default meshes (generated, no download)
// into a folder, as OFF files. See --help.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "arrangements/mesh_generators.h"
#include "arrangements/write_off.h"

namespace {

const char* kUsage = R"(usage: make_test_meshes OUTDIR [--rotated-copies K]

Writes generated test meshes into OUTDIR (created if needed):
  two_spheres.off          two overlapping UV spheres (curves of edge-face crossings)
  cube_through_cube.off    a box pushed through another (crossings and coplanar contact)
  coplanar_grids.off       two flat grids overlapping in one plane (coplanar crossings)
  grid_through_sphere.off  a flat grid cutting a sphere
  sphere_copies_K.off      K copies of a sphere rotated about the z axis (only with
                           --rotated-copies K; intersections grow like K^2: K = 8 with the
                           default resolution gives over a million intersection points)
)";

}  // namespace

int main(int argc, char** argv) {
  using namespace arrangements;
  std::string out;
  int copies = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--rotated-copies" && i + 1 < argc) {
      copies = std::atoi(argv[++i]);
      if (copies < 1) {
        std::fprintf(stderr, "make_test_meshes: --rotated-copies needs a positive integer\n");
        return 2;
      }
    } else if (a[0] == '-') {
      std::fprintf(stderr, "make_test_meshes: unknown option '%s' (see --help)\n", a.c_str());
      return 2;
    } else {
      out = a;
    }
  }
  if (out.empty()) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  try {
    std::filesystem::create_directories(out);
    auto write = [&](const std::string& name, const TriangleSoup& s) {
      write_off((std::filesystem::path(out) / name).string(), s.vertices, s.triangles);
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
