// bench/bench_exact_path.cpp
//
// The exact path's cost against the double path, on the same meshes, in one process:
//   double   arrange(TriangleSoup) of the file as loaded
//   exact    arrange(ExactTriangleSoup) of the same coordinates as rationals (what a mixed
//            input, some files exact, costs: everything takes the exact path)
//   again    arrange(ExactTriangleSoup) of the double run's exact output (iterating: the
//            arrangement arranged again; finds nothing new)
// Runs alternate (double, exact, again), the minimum of --runs is kept; t_total_s of the
// pipeline (loading excluded). One JSON object per file on stdout, a table on stderr.
//
// usage: bench_exact_path MESH... [--runs N] [--threads N]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/load_triangle_soup.h"

namespace {

using namespace arrangements;

[[noreturn]] void usage(int status) {
  std::fputs("usage: bench_exact_path MESH... [--runs N] [--threads N]\n", status ? stderr : stdout);
  std::exit(status);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  int runs = 3, threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") usage(0);
    if ((a == "--runs" || a == "--threads") && i + 1 < argc) {
      char* end = nullptr;
      const long v = std::strtol(argv[++i], &end, 10);
      if (*end || v < (a == "--runs" ? 1 : 0) || v > 1024) usage(2);
      (a == "--runs" ? runs : threads) = static_cast<int>(v);
    } else if (!a.empty() && a[0] == '-') {
      usage(2);
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) usage(2);
  ArrangeOptions options;
  options.threads = threads;
  std::fprintf(stderr, "%-40s %9s %9s %9s %7s %7s\n", "mesh", "double s", "exact s", "again s", "exact/d", "again/d");
  for (const std::string& f : files) {
    try {
      const TriangleSoup soup = load_triangle_soup(f);
      const ExactTriangleSoup exact = to_exact(soup);
      double t[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity()};
      ExactTriangleSoup again_input;
      std::size_t points = 0, again_points = 0;
      for (int r = 0; r < runs; ++r) {
        const ArrangeResult d = arrange(soup, options);
        t[0] = std::min(t[0], d.stats.t_total_s);
        points = d.stats.intersection_points;
        if (r == 0) again_input = as_input(d.mesh);
        t[1] = std::min(t[1], arrange(exact, options).stats.t_total_s);
        const ExactArrangeResult a = arrange(again_input, options);
        t[2] = std::min(t[2], a.stats.t_total_s);
        again_points = a.stats.intersection_points + a.stats.tpi;
      }
      std::fprintf(stderr, "%-40s %9.3f %9.3f %9.3f %7.2f %7.2f\n", f.c_str(), t[0], t[1], t[2], t[1] / t[0],
                   t[2] / t[0]);
      std::printf(
          "{\"file\": \"%s\", \"triangles\": %zu, \"intersection_points\": %zu, \"double_s\": %.6f, \"exact_s\": %.6f, "
          "\"again_s\": %.6f, \"exact_ratio\": %.4f, \"again_ratio\": %.4f, \"again_new_points\": %zu}\n",
          f.c_str(), soup.triangles.size(), points, t[0], t[1], t[2], t[1] / t[0], t[2] / t[0], again_points);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_exact_path: %s: %s\n", f.c_str(), e.what());
      return 1;
    }
  }
  return 0;
}
