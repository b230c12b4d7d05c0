#include "pipeline.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "stages/2_candidate_pairs.h"
#include "stages/3_classify_pairs.h"
#include "arrangements/input_error.h"
#include "support/process_usage.h"
#include "support/mesh_counts.h"
#include "stages/1_preprocess.h"
#include "arrangements/thread_count.h"
#include "stages/5_triangulate.h"

namespace arrangements {
namespace {

// The point p of a model scaled by 2^k, in the unscaled model's frame: its defining
// points scaled by 2^-k (exact: preprocessing only scales when that is exact both ways).
tritri::ImplicitPoint unscaled(const tritri::ImplicitPoint& p, int k) {
  auto back = [k](const Vec3& c) { return Vec3{std::ldexp(c[0], -k), std::ldexp(c[1], -k), std::ldexp(c[2], -k)}; };
  using Kind = tritri::ImplicitPoint::Kind;
  if (p.kind() == Kind::Explicit) return tritri::ImplicitPoint::explicit_point(back(p.approx()));
  Vec3 in[9];
  for (int i = 0; i < p.input_count(); ++i) in[i] = back(p.input(i));
  if (p.kind() == Kind::LPI) return tritri::ImplicitPoint::lpi(in[0], in[1], in[2], in[3], in[4]);
  return tritri::ImplicitPoint::tpi(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8]);
}

// The referenced points only, renumbered in first-use order (in the input's frame);
// provenance mapped back to the input's triangle numbering.
OutputMesh make_output(const TriangleSoup& soup, Triangulation&& tr, int scale_exponent) {
  OutputMesh m;
  std::vector<int> new_id(tr.points.size(), -1);
  m.triangles.reserve(tr.triangles.size());
  for (Tri t : tr.triangles) {
    for (int& v : t) {
      if (new_id[v] < 0) {
        new_id[v] = static_cast<int>(m.vertices.size());
        m.vertices.push_back(tr.points[v]);
      }
      v = new_id[v];
    }
    m.triangles.push_back(t);
  }
  if (scale_exponent != 0)
    tbb::parallel_for(std::size_t{0}, m.vertices.size(),
                      [&](std::size_t i) { m.vertices[i] = unscaled(m.vertices[i], scale_exponent); });
  m.source.reserve(tr.owner.size());
  for (int o : tr.owner) m.source.push_back(soup.source[o]);
  m.label_set = std::move(tr.label_set);
  m.label_sets = std::move(tr.label_sets);
  return m;
}

}  // namespace

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

  auto t0 = std::chrono::steady_clock::now();
  PreprocessStats pre;
  PreprocessOptions popt;
  popt.scale = options.scale;
  TriangleSoup soup = preprocess(input, popt, pre);
  s.merged_vertices = pre.merged_vertices;
  s.removed_degenerate = pre.removed_degenerate;
  s.removed_duplicate = pre.removed_duplicate;
  s.t_preprocess_s = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  const auto pairs = candidate_pairs(soup.vertices, soup.triangles, workers, soup.polygon);
  s.candidate_pairs = pairs.size();
  s.t_detect_s = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  tritri::PredicateCounts counts;
  const auto records = classify_pairs(soup.vertices, soup.triangles, pairs, options.classifier,
                                      options.count_predicates ? &counts : nullptr);
  s.orient3d_calls = counts.orient3d;
  s.orient2d_calls = counts.orient2d;
  IntersectionGraph graph = build_intersection_graph(soup.vertices, soup.triangles, records);
  s.t_classify_s = seconds_since(t0);
  s.intersecting_pairs = graph.intersecting_pairs;
  s.coplanar_pairs = graph.coplanar_pairs;
  s.intersection_points = graph.new_points;
  s.segments = graph.segments;
  for (const auto& v : graph.triangle_segments) s.tri_segments += v.size();

  t0 = std::chrono::steady_clock::now();
  Triangulation tr = triangulate(soup, graph);
  s.tpi = tr.num_tpi;
  s.t_triangulate_s = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  r.mesh = make_output(soup, std::move(tr), pre.scale_exponent);
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

ArrangeResult arrange(const TriangleSoup& input, const ArrangeOptions& options) {
  return run_pipeline(input, options, nullptr);
}

void add_write_time(ArrangeStats& s, double seconds) {
  s.t_output_s += seconds;
  s.t_total_s += seconds;
  s.peak_rss_mb = peak_rss_mb();
}

}  // namespace arrangements
