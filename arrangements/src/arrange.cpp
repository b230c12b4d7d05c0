// arrange(): the stages of src/stages/ in order, timed, with their counts collected into
// ArrangeStats.
#include "pipeline.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "arrangements/thread_count.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate.h"
#include "support/mesh_counts.h"
#include "support/process_usage.h"

namespace arrangements {

ArrangeResult run_pipeline(const TriangleSoup& input, const ArrangeOptions& options, PipelineInternals* keep) {
  if (options.threads > kMaxThreads)  // oneTBB crashes or aborts on huge arenas (thread_count.h)
    throw std::invalid_argument("arrange: threads must be at most " + std::to_string(kMaxThreads) + ", got " +
                                std::to_string(options.threads));
  const int workers = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, workers);
  ArrangeResult r;
  ArrangeStats& s = r.stats;
  s.threads = workers;
  s.classifier = options.classifier == Classifier::Tritri ? "tritri" : "native";
  s.in_vertices = input.vertices.size();
  s.in_triangles = input.triangles.size();
  const auto start = std::chrono::steady_clock::now();

  // Stage 1: exact preprocessing (merge, drop degenerate and duplicate triangles, scale).
  auto t0 = std::chrono::steady_clock::now();
  PreprocessStats pre;
  PreprocessOptions popt;
  popt.scale = options.scale;
  TriangleSoup soup = preprocess(input, popt, pre);
  s.merged_vertices = pre.merged_vertices;
  s.removed_degenerate = pre.removed_degenerate;
  s.removed_duplicate = pre.removed_duplicate;
  s.t_preprocess_s = seconds_since(t0);

  // Stage 2: the pairs to classify (overlapping bounding boxes, exact early-outs).
  t0 = std::chrono::steady_clock::now();
  DetectedPairs detected = detect_pairs(soup.vertices, soup.triangles, workers, soup.polygon);
  s.candidate_pairs = detected.box_pairs;
  s.classified_pairs = detected.pairs.size();
  s.t_detect_s = seconds_since(t0);

  // Stages 3 and 4 (timed together as "classify"): classify every candidate pair, then
  // merge the records into the intersection graph. Each intermediate is freed as soon as
  // the next stage has consumed it (peak memory).
  t0 = std::chrono::steady_clock::now();
  tritri::PredicateCounts counts;
  PairRecords records = classify_pairs(soup.vertices, soup.triangles, detected.pairs, options.classifier,
                                       options.count_predicates ? &counts : nullptr, detected.planes);
  detected = DetectedPairs{};
  s.orient3d_calls = counts.orient3d;
  s.orient2d_calls = counts.orient2d;
  IntersectionGraph graph = build_intersection_graph(soup.vertices, soup.triangles, records);
  records = PairRecords{};
  s.t_classify_s = seconds_since(t0);
  s.intersecting_pairs = graph.intersecting_pairs;
  s.coplanar_pairs = graph.coplanar_pairs;
  s.intersection_points = graph.new_points;
  s.segments = graph.segments;
  for (const auto& v : graph.triangle_segments) s.tri_segments += v.size();

  // Stage 5: triangulate every cut triangle; the result is the output mesh.
  t0 = std::chrono::steady_clock::now();
  TriangulationInfo info;
  r.mesh = triangulate(soup, graph, pre.scale_exponent, info);
  s.tpi = info.new_tpi;
  if (!keep) graph = IntersectionGraph{};
  s.t_triangulate_s = seconds_since(t0);

  // Output counts (the writers are the caller's: arrangements/write_mesh.h).
  t0 = std::chrono::steady_clock::now();
  const MeshCounts c = mesh_counts(r.mesh.triangles);
  s.out_vertices = c.vertices;
  s.out_edges = c.edges;
  s.out_triangles = c.triangles;
  s.euler = c.euler;
  s.t_output_s = seconds_since(t0);

  if (keep) {
    keep->soup = std::move(soup);
    keep->graph = std::move(graph);
  }
  s.t_total_s = seconds_since(start);
  s.peak_rss_mb = peak_rss_mb();
  return r;
}

void validate_soup(const TriangleSoup& in) {
  const std::size_t nf = in.triangles.size();
  if (in.label_set.size() != nf || in.source.size() != nf || (!in.polygon.empty() && in.polygon.size() != nf))
    throw std::invalid_argument("arrange: label_set, source (and polygon) must have one entry per triangle");
  for (std::size_t v = 0; v < in.vertices.size(); ++v)
    for (double c : in.vertices[v])
      if (!std::isfinite(c))
        throw std::invalid_argument("arrange: vertex " + std::to_string(v) + " has a non-finite coordinate");
  const long long nv = static_cast<long long>(in.vertices.size());
  const long long ns = static_cast<long long>(in.label_sets.size());
  for (std::size_t t = 0; t < nf; ++t) {
    for (int i : in.triangles[t])
      if (i < 0 || i >= nv)
        throw std::invalid_argument("arrange: triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(i) + " out of range");
    if (in.label_set[t] < 0 || in.label_set[t] >= ns)
      throw std::invalid_argument("arrange: triangle " + std::to_string(t) + " has label set index " +
                                  std::to_string(in.label_set[t]) + " out of range");
  }
}

ArrangeResult arrange(const TriangleSoup& input, const ArrangeOptions& options) {
  validate_soup(input);
  return run_pipeline(input, options, nullptr);
}

ArrangeResult detail::arrange_validated(const TriangleSoup& input, const ArrangeOptions& options) {
  return run_pipeline(input, options, nullptr);
}

void add_write_time(ArrangeStats& s, double seconds) {
  s.t_output_s += seconds;
  s.t_total_s += seconds;
  s.peak_rss_mb = peak_rss_mb();
}

}  // namespace arrangements
