// arrange(): the stages of src/stages/ in order, timed, with their counts collected into
// ArrangeStats.
#include "pipeline.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <span>
#include <string>
#include <type_traits>

#include "arrangements/memory_budget.h"
#include "arrangements/thread_count.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/1_preprocess.h"
#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "stages/4_intersection_graph.h"
#include "stages/5_triangulate.h"
#include "stages/6_boolean.h"
#include "support/mesh_counts.h"
#include "support/process_usage.h"

namespace arrangements {
namespace {

// The model's output mesh as the public one: the same for doubles (implicit points),
// rationals for the exact model.
OutputMesh public_mesh(OutputMesh&& mesh) { return std::move(mesh); }
ExactOutputMesh public_mesh(BasicOutputMesh<ExactModel::Point>&& mesh) {
  ExactOutputMesh out;
  out.vertices.resize(mesh.vertices.size());
  tbb::parallel_for(std::size_t{0}, mesh.vertices.size(),
                    [&](std::size_t i) { out.vertices[i] = ExactModel::to_input(mesh.vertices[i]); });
  mesh.vertices = {};
  out.triangles = std::move(mesh.triangles);
  out.source = std::move(mesh.source);
  out.label_set = std::move(mesh.label_set);
  out.label_sets = std::move(mesh.label_sets);
  return out;
}

// The stages for point model M; keep (double model only) receives the soup and graph.
template <class M, class Result>
Result run_stages(const BasicTriangleSoup<typename M::Input>& input, const ArrangeOptions& options,
                  BasicPipelineInternals<M>* keep, const CsgNode* tree) {
  if (options.threads > kMaxThreads)  // oneTBB crashes or aborts on huge arenas (thread_count.h)
    throw std::invalid_argument("arrange: threads must be at most " + std::to_string(kMaxThreads) + ", got " +
                                std::to_string(options.threads));
  const int workers = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, workers);
  Result r;
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
  std::vector<int> kept_as;
  if (tree) popt.kept_as = &kept_as;
  BasicTriangleSoup<typename M::Vertex> soup = preprocess<M>(input, popt, pre);
  s.merged_vertices = pre.merged_vertices;
  s.removed_degenerate = pre.removed_degenerate;
  s.removed_duplicate = pre.removed_duplicate;
  s.t_preprocess_s = seconds_since(t0);

  // Stage 2: the pairs to classify (overlapping bounding boxes, exact early-outs).
  t0 = std::chrono::steady_clock::now();
  BasicDetectedPairs<M> detected =
      detect_pairs<M>(soup.vertices, soup.triangles, workers, soup.polygon, /*coplanar_budget=*/true);
  s.candidate_pairs = detected.box_pairs;
  s.classified_pairs = detected.pairs.size();
  s.t_detect_s = seconds_since(t0);
  detail::memory_checkpoint();
  detail::memory_checkpoint();

  // Stages 3 and 4 (timed together as "classify"): classify every candidate pair, then
  // merge the records into the intersection graph. Each intermediate is freed as soon as
  // the next stage has consumed it (peak memory).
  t0 = std::chrono::steady_clock::now();
  tritri::PredicateCounts counts;
  PairRecords records =
      classify_pairs<M>(soup.vertices, soup.triangles, detected.pairs, options.classifier,
                        options.count_predicates ? &counts : nullptr,
                        std::span<const typename M::PlaneCache>(detected.planes));
  detected = BasicDetectedPairs<M>{};
  s.orient3d_calls = counts.orient3d;
  s.orient2d_calls = counts.orient2d;
  auto graph = build_intersection_graph<M>(soup.vertices, soup.triangles, records);
  records = PairRecords{};
  s.t_classify_s = seconds_since(t0);
  detail::memory_checkpoint();
  detail::memory_checkpoint();
  s.intersecting_pairs = graph.intersecting_pairs;
  s.coplanar_pairs = graph.coplanar_pairs;
  s.intersection_points = graph.new_points;
  s.segments = graph.segments;
  for (const auto& v : graph.triangle_segments) s.tri_segments += v.size();

  // Stage 5: triangulate every cut triangle; the result is the output mesh.
  t0 = std::chrono::steady_clock::now();
  TriangulationInfo info;
  info.keep_covers = tree != nullptr;
  auto mesh = triangulate<M>(soup, graph, pre.scale_exponent, info);
  s.tpi = info.new_tpi;
  s.whole_clusters = info.whole_clusters;
  if (!keep) graph = {};
  s.t_triangulate_s = seconds_since(t0);
  detail::memory_checkpoint();
  detail::memory_checkpoint();

  // Stage 6 (Booleans only): winding numbers per cell, the tree's boundary.
  if (tree) {
    t0 = std::chrono::steady_clock::now();
    boolean_stage<M>(mesh, soup, kept_as, input, info, *tree, pre.scale_exponent, s);
    s.t_winding_s = seconds_since(t0);
  }
  info = TriangulationInfo{};
  r.mesh = public_mesh(std::move(mesh));

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

// The checks of validate_soup that do not depend on the coordinates.
template <class Soup>
void validate_indices(const Soup& in) {
  const std::size_t nf = in.triangles.size();
  if (in.label_set.size() != nf || in.source.size() != nf || (!in.polygon.empty() && in.polygon.size() != nf))
    throw std::invalid_argument("arrange: label_set, source (and polygon) must have one entry per triangle");
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

}  // namespace

ArrangeResult run_pipeline(const TriangleSoup& input, const ArrangeOptions& options, PipelineInternals* keep,
                           const CsgNode* tree) {
  return run_stages<DoubleModel, ArrangeResult>(input, options, keep, tree);
}

ExactArrangeResult run_pipeline(const ExactTriangleSoup& input, const ArrangeOptions& options,
                                BasicPipelineInternals<ExactModel>* keep, const CsgNode* tree) {
  return run_stages<ExactModel, ExactArrangeResult>(input, options, keep, tree);
}

void validate_soup(const TriangleSoup& in) {
  validate_indices(in);
  for (std::size_t v = 0; v < in.vertices.size(); ++v)
    for (double c : in.vertices[v])
      if (!std::isfinite(c))
        throw std::invalid_argument("arrange: vertex " + std::to_string(v) + " has a non-finite coordinate");
}

void validate_soup(const ExactTriangleSoup& in) {
  validate_indices(in);
  // The box search bounds every point by doubles: coordinates must lie in the double
  // range (as the file loader, Eigen and Python require too).
  const CGAL::Gmpq largest(std::numeric_limits<double>::max());
  for (std::size_t v = 0; v < in.vertices.size(); ++v)
    for (const CGAL::Gmpq& c : in.vertices[v])
      if (c > largest || c < -largest)
        throw std::invalid_argument("arrange: vertex " + std::to_string(v) +
                                    " has a coordinate beyond the double range (largest magnitude " +
                                    "1.7976931348623157e308)");
}

ArrangeResult arrange(const TriangleSoup& input, const ArrangeOptions& options) {
  validate_soup(input);
  return run_pipeline(input, options, nullptr);
}

ExactArrangeResult arrange(const ExactTriangleSoup& input, const ArrangeOptions& options) {
  validate_soup(input);
  return run_pipeline(input, options, nullptr);
}

ArrangeResult detail::arrange_validated(const TriangleSoup& input, const ArrangeOptions& options) {
  return run_pipeline(input, options, nullptr);
}

ExactArrangeResult detail::arrange_validated(const ExactTriangleSoup& input, const ArrangeOptions& options) {
  return run_pipeline(input, options, nullptr);
}

void add_write_time(ArrangeStats& s, double seconds) {
  s.t_output_s += seconds;
  s.t_total_s += seconds;
  s.peak_rss_mb = peak_rss_mb();
}

}  // namespace arrangements
