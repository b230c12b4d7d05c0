// tritri-compare: runs the arrangement pipeline with both classifiers (native and tritri)
// on the same input and compares their results exactly. See --help.
#include <algorithm>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numeric>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <tritri/implicit_predicates.h>

#include "pipeline.h"
#include "arrangements/arrange_stats.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "io/standard_output.h"
#include "support/command_line.h"
#include "support/process_usage.h"
#include "support/worker_threads.h"
#include "arrangements/thread_count.h"

namespace {

const char* kUsage = R"(usage: tritri-compare INPUT... [options]

Runs the mesh-arrangement pipeline twice on the same input, once with the native
classifier (the 2020 case analysis) and once with tritri (tritri::classify through the
adapter), and compares exactly:
  - the intersection points, as sets of exact points (exact lexicographic order);
  - per triangle, the constraint segments, as pairs of those points;
  - the output counts: vertices, edges, triangles, Euler characteristic.
Several INPUT files form one model (concatenated, labelled by position).

options:
  --json                  print one JSON object (below) instead of a summary
  --threads N             worker threads: 0 (the default: all cores) to )" ARRANGEMENTS_MAX_THREADS_STR R"(;
                          larger values are refused (oneTBB cannot run them safely)
  --scale                 scale coordinates by a power of two (exact)
  --max-differences N     list at most N differences, 0 to 1000000 (default 10)
  --repeat N              run each classifier N times, alternating, 1 to 1000000 (default
                          1); the times reported are each stage's minimum over the runs
  --inject-disagreement   testing aid: drop one tritri intersection point and one of its
                          segments before comparing (the comparison must then fail)
  --help                  this text
An option that takes a value may be given once; numbers are plain decimal digits.

JSON keys: file, in_vertices, in_triangles, intersection_points, points_equal,
segments_equal, counts_equal, euler_equal, agree, differences (list), native and tritri
(each the `arrange --stats` object: t_classify_s, t_total_s, out_vertices, out_edges,
out_triangles, euler, orient3d_calls, orient2d_calls, ...), ratio_classify
(tritri / native classification time), ratio_total (tritri / native t_total_s - t_load_s:
the pipeline without the shared load).

exit status: 0 the classifiers agree, 1 they disagree (the first differences are listed),
2 error (bad input, standard output that cannot be written, worker threads the system
refuses, or a bad command line: unknown option, missing, empty or out-of-range value, option
given twice).
)";

constexpr long long kMaxRepeat = 1000000, kMaxDifferences = 1000000;


std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// Canonical ids: input vertices keep theirs; new points are numbered by their rank in
// the exact lexicographic order.
template <class M, class Graph>
std::vector<int> canonical_ids(const Graph& g, std::vector<int>& sorted_new) {
  const int nv = g.num_input_vertices;
  sorted_new.resize(g.points.size() - nv);
  std::iota(sorted_new.begin(), sorted_new.end(), nv);
  std::sort(sorted_new.begin(), sorted_new.end(),
            [&](int a, int b) { return M::compare_xyz(g.points[a], g.points[b]) < 0; });
  std::vector<int> id(g.points.size());
  std::iota(id.begin(), id.begin() + nv, 0);
  for (std::size_t r = 0; r < sorted_new.size(); ++r) id[sorted_new[r]] = nv + static_cast<int>(r);
  return id;
}

int run(int argc, char** argv) {
  using namespace arrangements;
  std::vector<std::string> inputs;
  bool json = false, scale = false, inject = false;
  int threads = 0;
  std::size_t max_differences = 10;
  int repeat = 1;
  detail::CommandLine args("tritri-compare", argc, argv);
  while (args.next()) {
    const std::string& a = args.current();
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--scale") {
      scale = true;
    } else if (a == "--inject-disagreement") {
      inject = true;
    } else if (a == "--threads") {
      threads = static_cast<int>(args.count("--threads", 0, kMaxThreads));
    } else if (a == "--repeat") {
      repeat = static_cast<int>(args.count("--repeat", 1, kMaxRepeat));
    } else if (a == "--max-differences") {
      max_differences = static_cast<std::size_t>(args.count("--max-differences", 0, kMaxDifferences));
    } else {
      inputs.push_back(args.operand("an input file name"));
    }
  }
  if (inputs.empty()) args.usage_error("no input file");
  std::string file;
  for (const auto& in : inputs) file += (file.empty() ? "" : " + ") + in;

  try {
    const auto t0 = std::chrono::steady_clock::now();
    // Double input takes the fast path (DoubleModel); any rational coordinate the exact one.
    const AnyTriangleSoup any_input = load_mesh_files(inputs);
    const double t_load = seconds_since(t0);
    return std::visit([&](const auto& input) -> int {
    using M = std::conditional_t<std::is_same_v<std::decay_t<decltype(input)>, TriangleSoup>, DoubleModel, ExactModel>;
    // Start TBB's workers before timing anything, so that the first run (native) does not
    // pay for creating them, and so that a refused thread is a message (worker_threads.h).
    {
      const int workers = threads > 0 ? threads : tbb::info::default_concurrency();
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, workers);
      detail::exit_on_worker_failure("tritri-compare", workers, 2);
      detail::start_worker_threads(workers);
    }
    ArrangeOptions options;
    options.threads = threads;
    options.scale = scale;
    options.count_predicates = true;
    options.classifier = Classifier::Native;
    BasicPipelineInternals<M> native_internals, tritri_internals;
    auto native = run_pipeline(input, options, &native_internals);
    options.classifier = Classifier::Tritri;
    auto tritri_run = run_pipeline(input, options, &tritri_internals);
    // Repeated runs, alternating, keep each stage's fastest time (less noise on a busy
    // machine); the results themselves are deterministic.
    auto keep_min = [](ArrangeStats& best, const ArrangeStats& s) {
      for (auto field : {&ArrangeStats::t_preprocess_s, &ArrangeStats::t_detect_s, &ArrangeStats::t_classify_s,
                         &ArrangeStats::t_triangulate_s, &ArrangeStats::t_output_s, &ArrangeStats::t_total_s})
        best.*field = std::min(best.*field, s.*field);
    };
    for (int r = 1; r < repeat; ++r) {
      ArrangeOptions timing = options;
      timing.classifier = Classifier::Native;
      keep_min(native.stats, run_pipeline(input, timing, nullptr).stats);
      timing.classifier = Classifier::Tritri;
      keep_min(tritri_run.stats, run_pipeline(input, timing, nullptr).stats);
    }
    add_load_time(native.stats, t_load);  // the one load, shared by both
    add_load_time(tritri_run.stats, t_load);

    auto& gn = native_internals.graph;
    auto& gt = tritri_internals.graph;
    if (inject && gt.points.size() > static_cast<std::size_t>(gt.num_input_vertices)) {
      gt.points.pop_back();
      const int dropped = static_cast<int>(gt.points.size());
      for (auto& segs : gt.triangle_segments)
        std::erase_if(segs, [&](const std::array<int, 2>& s) { return s[0] == dropped || s[1] == dropped; });
    }

    std::vector<std::string> differences;
    auto differ = [&](std::string what) {
      if (differences.size() < max_differences) differences.push_back(std::move(what));
    };
    if (native_internals.soup.vertices != tritri_internals.soup.vertices ||
        native_internals.soup.triangles != tritri_internals.soup.triangles)
      throw std::logic_error("the two runs preprocessed the input differently");

    // Points, as exact sets.
    std::vector<int> sorted_n, sorted_t;
    const std::vector<int> id_n = canonical_ids<M>(gn, sorted_n);
    const std::vector<int> id_t = canonical_ids<M>(gt, sorted_t);
    bool points_equal = sorted_n.size() == sorted_t.size();
    if (!points_equal)
      differ("intersection points: native " + std::to_string(sorted_n.size()) + ", tritri " +
             std::to_string(sorted_t.size()));
    for (std::size_t r = 0, e = std::min(sorted_n.size(), sorted_t.size()); r < e; ++r)
      if (M::compare_xyz(gn.points[sorted_n[r]], gt.points[sorted_t[r]]) != 0) {
        if (points_equal) {
          const auto p = M::to_double(gn.points[sorted_n[r]]);
          const auto q = M::to_double(gt.points[sorted_t[r]]);
          char buf[256];
          std::snprintf(buf, sizeof buf,
                        "intersection point %zu in exact order: native (%.17g, %.17g, %.17g), tritri (%.17g, %.17g, "
                        "%.17g)",
                        r, p[0], p[1], p[2], q[0], q[1], q[2]);
          differ(buf);
        }
        points_equal = false;
      }

    // Segments per triangle, on canonical ids (meaningful when the points are equal).
    bool segments_equal = points_equal;
    std::size_t segment_differences = 0;
    for (std::size_t t = 0; t < gn.triangle_segments.size(); ++t) {
      auto canon = [](const std::vector<std::array<int, 2>>& segs, const std::vector<int>& id) {
        std::vector<std::array<int, 2>> out;
        for (const auto& s : segs) out.push_back({std::min(id[s[0]], id[s[1]]), std::max(id[s[0]], id[s[1]])});
        std::sort(out.begin(), out.end());
        return out;
      };
      if (canon(gn.triangle_segments[t], id_n) != canon(gt.triangle_segments[t], id_t)) {
        segments_equal = false;
        if (segment_differences++ == 0 || points_equal)
          differ("constraint segments of triangle " + std::to_string(t) + ": native " +
                 std::to_string(gn.triangle_segments[t].size()) + ", tritri " +
                 std::to_string(gt.triangle_segments[t].size()));
      }
    }

    const ArrangeStats& sn = native.stats;
    const ArrangeStats& st = tritri_run.stats;
    const bool counts_equal =
        sn.out_vertices == st.out_vertices && sn.out_edges == st.out_edges && sn.out_triangles == st.out_triangles;
    const bool euler_equal = sn.euler == st.euler;
    if (!counts_equal)
      differ("output counts (V, E, F): native (" + std::to_string(sn.out_vertices) + ", " +
             std::to_string(sn.out_edges) + ", " + std::to_string(sn.out_triangles) + "), tritri (" +
             std::to_string(st.out_vertices) + ", " + std::to_string(st.out_edges) + ", " +
             std::to_string(st.out_triangles) + ")");
    const bool agree = points_equal && segments_equal && counts_equal && euler_equal;
    auto ratio = [](double a, double b) { return b > 0 && std::isfinite(a / b) ? a / b : 0.0; };  // JSON: finite
    // Totals without the shared load (in both t_total_s): the pipelines' own times.
    const double total_n = sn.t_total_s - sn.t_load_s, total_t = st.t_total_s - st.t_load_s;

    if (json) {
      std::string diffs = "[";
      for (std::size_t i = 0; i < differences.size(); ++i) diffs += (i ? ", " : "") + json_string(differences[i]);
      diffs += "]";
      std::printf(
          "{\"file\": %s, \"in_vertices\": %zu, \"in_triangles\": %zu, \"intersection_points\": %zu, "
          "\"points_equal\": %s, \"segments_equal\": %s, \"counts_equal\": %s, \"euler_equal\": %s, \"agree\": %s, "
          "\"differences\": %s, \"ratio_classify\": %.6f, \"ratio_total\": %.6f, \"native\": %s, \"tritri\": %s}\n",
          json_string(file).c_str(), sn.in_vertices, sn.in_triangles, st.intersection_points,
          points_equal ? "true" : "false", segments_equal ? "true" : "false", counts_equal ? "true" : "false",
          euler_equal ? "true" : "false", agree ? "true" : "false", diffs.c_str(),
          ratio(st.t_classify_s, sn.t_classify_s), ratio(total_t, total_n), stats_json(sn).c_str(),
          stats_json(st).c_str());
    } else {
      std::printf("%s: %s\n", file.c_str(), agree ? "native and tritri agree" : "native and tritri DISAGREE");
      std::printf("  intersection points %zu, output V %zu E %zu F %zu, Euler %lld\n", st.intersection_points,
                  st.out_vertices, st.out_edges, st.out_triangles, st.euler);
      std::printf(
          "  classification: native %.4f s (%zu orient3d, %zu orient2d), tritri %.4f s (%zu orient3d, %zu "
          "orient2d), ratio %.3f\n",
          sn.t_classify_s, sn.orient3d_calls, sn.orient2d_calls, st.t_classify_s, st.orient3d_calls, st.orient2d_calls,
          ratio(st.t_classify_s, sn.t_classify_s));
      std::printf("  total: native %.4f s, tritri %.4f s\n", sn.t_total_s, st.t_total_s);
      for (const auto& d : differences) std::printf("  difference: %s\n", d.c_str());
    }
    return agree ? 0 : 1;
    }, any_input);
  } catch (const InputError& e) {
    std::fprintf(stderr, "tritri-compare: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tritri-compare: error: %s\n", e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  arrangements::detail::keep_standard_streams_open();
  const int status = run(argc, argv);
  return arrangements::detail::finish_standard_output("tritri-compare", status, 2);
}
