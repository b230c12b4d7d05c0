// arrange: the mesh-arrangement pipeline from the command line (classification stage).
// See --help.
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "arrangements/candidate_pairs.h"
#include "arrangements/classify_pairs.h"
#include "arrangements/input_error.h"
#include "arrangements/intersection_graph.h"
#include "arrangements/load_triangle_soup.h"
#include "arrangements/preprocess.h"
#include "arrangements/propagate_coplanar.h"

namespace {

const char* kUsage = R"(usage: arrange INPUT... [options]

Resolves the intersections of one or more triangle soups exactly (mesh arrangement after
Cherchi et al. 2020). Each INPUT (.obj .off .stl .ply, ASCII or binary) is labelled by its
position: the first file has label 0, the second label 1, ...

Stages: load, exact preprocessing (merge duplicate vertices, remove degenerate and
duplicate triangles), candidate pairs (bounding boxes), classification of every candidate
pair into intersection points and segments (implicit points, never rounded).

options:
  --stats                 print one JSON object with counts and stage times on stdout
  --classifier NAME       pair classifier: native (the 2020 case analysis; default) or
                          tritri (tritri::classify through the adapter)
  --threads N             worker threads (default: all cores)
  --scale                 scale coordinates by a power of two into a safe range (exact)
  --help                  this text

JSON keys (--stats): in_vertices, in_triangles, merged_vertices, removed_degenerate,
removed_duplicate, candidate_pairs, intersecting_pairs, intersection_points (distinct new
points), lpi, segments (distinct constraint segments), tri_segments (summed over
triangles), coplanar_pairs, classifier, threads, t_load_s, t_preprocess_s, t_detect_s,
t_classify_s, t_total_s, peak_rss_mb.

exit status: 0 success, 1 bad input (unreadable, unknown format, malformed, NaN/Inf,
out-of-range indices, empty mesh), 2 bad command line.
)";

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // kilobytes on Linux
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace arrangements;
  std::vector<std::string> inputs;
  bool stats = false, scale = false;
  int threads = 0;
  std::string classifier = "native";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "arrange: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--stats") {
      stats = true;
    } else if (a == "--scale") {
      scale = true;
    } else if (a == "--classifier") {
      classifier = value("--classifier");
    } else if (a == "--threads") {
      const std::string v = value("--threads");
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < 0 || n > 4096) {
        std::fprintf(stderr, "arrange: --threads needs a non-negative integer, got '%s'\n", v.c_str());
        return 2;
      }
      threads = static_cast<int>(n);
    } else if (a.size() > 1 && a[0] == '-') {
      std::fprintf(stderr, "arrange: unknown option '%s' (see --help)\n", a.c_str());
      return 2;
    } else {
      inputs.push_back(a);
    }
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "arrange: no input file (see --help)\n");
    return 2;
  }
  if (classifier != "native" && classifier != "tritri") {
    std::fprintf(stderr, "arrange: unknown classifier '%s' (known: native, tritri)\n", classifier.c_str());
    return 2;
  }
  const int workers = threads > 0 ? threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, workers);

  try {
    const auto start = std::chrono::steady_clock::now();
    auto t0 = start;
    const TriangleSoup input = load_triangle_soups(inputs);
    const double t_load = seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    PreprocessStats pre;
    PreprocessOptions options;
    options.scale = scale;
    const TriangleSoup soup = preprocess(input, options, pre);
    const double t_preprocess = seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    const auto pairs = candidate_pairs(soup.vertices, soup.triangles, workers);
    const double t_detect = seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    const auto records = classify_pairs(soup.vertices, soup.triangles, pairs,
                                        classifier == "tritri" ? Classifier::Tritri : Classifier::Native);
    IntersectionGraph graph = build_intersection_graph(soup.vertices, soup.triangles, records);
    propagate_coplanar(soup.vertices, soup.triangles, graph);
    const double t_classify = seconds_since(t0);

    std::size_t tri_segments = 0;
    for (const auto& s : graph.triangle_segments) tri_segments += s.size();
    if (stats) {
      std::printf(
          "{\"in_vertices\": %zu, \"in_triangles\": %zu, \"merged_vertices\": %zu, "
          "\"removed_degenerate\": %zu, \"removed_duplicate\": %zu, \"candidate_pairs\": %zu, "
          "\"intersecting_pairs\": %zu, \"intersection_points\": %zu, \"lpi\": %zu, \"segments\": %zu, "
          "\"tri_segments\": %zu, \"coplanar_pairs\": %zu, \"classifier\": \"%s\", \"threads\": %d, "
          "\"t_load_s\": %.6f, \"t_preprocess_s\": %.6f, \"t_detect_s\": %.6f, \"t_classify_s\": %.6f, "
          "\"t_total_s\": %.6f, \"peak_rss_mb\": %.1f}\n",
          input.vertices.size(), input.triangles.size(), static_cast<std::size_t>(pre.merged_vertices),
          static_cast<std::size_t>(pre.removed_degenerate), static_cast<std::size_t>(pre.removed_duplicate),
          pairs.size(), graph.intersecting_pairs, graph.new_points, graph.new_points, graph.segments, tri_segments,
          graph.coplanar_pairs, classifier.c_str(), workers, t_load, t_preprocess, t_detect, t_classify,
          seconds_since(start), peak_rss_mb());
    }
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "arrange: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "arrange: error: %s\n", e.what());
    return 1;
  }
}
