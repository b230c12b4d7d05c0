// tests/support/safe_rounding_checks.h
//
// expect_safe_rounding(exact, name, nearest_ok, input, rounded): round_safe on an arrangement
// (OutputMesh or ExactOutputMesh; with its input when given) and every fact the rounding
// tests check of it, independently of round_safe's own loop: check_arrangement on the
// rounded doubles is clean; arranging them again finds nothing (no LPI, TPI, intersecting
// pair, nothing merged or removed, the same triangles); provenance (every triangle keeps a
// source and label set of the exact arrangement, or where layers may have merged, labels
// the exact arrangement has); area per source kept (to rounding), or never gained where
// layers may have merged; the move within 1e-6 of the model's size; and when rounding to
// nearest was not valid, more than one pass unless cleaning it made it valid. area_per_source measures in doubles (a
// measure, not a decision).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/arrange.h"
#include "arrangements/as_input.h"
#include "arrangements/check_arrangement.h"
#include "arrangements/round_mesh.h"
#include "rounding/mesh_on_positions.h"

namespace tritri_test::rounding {

using namespace ::arrangements;

inline Vec3 as_double(const tritri::ImplicitPoint& p) { return tritri::to_double(p); }
inline Vec3 as_double(const ExactVec3& p) { return tritri::to_double(p); }
inline Vec3 as_double(const Vec3& p) { return p; }

// Area of the triangle (a, b, c) (doubles: a measure, not a decision).
inline double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

// Area of every triangle summed per source.
template <class Mesh>
std::map<std::int64_t, double> area_per_source(const Mesh& m, double& total) {
  std::vector<Vec3> V;
  for (const auto& p : m.vertices) V.push_back(as_double(p));
  std::map<std::int64_t, double> area;
  total = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const double at = triangle_area(V[m.triangles[t][0]], V[m.triangles[t][1]], V[m.triangles[t][2]]);
    area[m.source[t]] += at;
    total += at;
  }
  return area;
}

// Every fact above for the safe rounding of `exact` (an OutputMesh or ExactOutputMesh; of
// `input`, passed to round_safe when given). Returns the report; `nearest_ok` receives
// whether rounding to nearest alone was valid, `rounded` (when given) the rounded mesh.
template <class Mesh>
RoundReport expect_safe_rounding(const Mesh& exact, const std::string& name, bool& nearest_ok,
                                 const TriangleSoup* input = nullptr, RoundedMesh* rounded = nullptr) {
  RoundReport report;
  const RoundedMesh r = round_safe(exact, RoundSafeOptions{.input = input}, &report);
  EXPECT_GE(report.passes, 1) << name;
  const ArrangementCheck c = check_arrangement(r);
  EXPECT_TRUE(c.ok()) << name << ": " << (c.examples.empty() ? "" : c.examples.front());

  const ArrangeResult again = arrange(arrangements::as_input(r), ArrangeOptions{});
  const ArrangeStats& s = again.stats;
  EXPECT_EQ(s.intersection_points, 0u) << name;
  EXPECT_EQ(s.tpi, 0u) << name;
  EXPECT_EQ(s.intersecting_pairs, 0u) << name;
  EXPECT_EQ(s.merged_vertices + s.removed_degenerate + s.removed_duplicate, 0u) << name;
  EXPECT_EQ(s.out_triangles, r.triangles.size()) << name;
  EXPECT_EQ(s.out_vertices, r.vertices.size()) << name;

  // Provenance: (source, label set) pairs of the rounded mesh are those of the exact one;
  // on level 1's grid, with merged or snapped input vertices, or where rerouting put two
  // triangles on the same three vertices, layers merged into
  // one carry the union of their labels.
  // Also at the nearest doubles, two triangles of layers 1e-17 apart may land on the same
  // three vertices: one triangle with its own source, its label set and more.
  std::set<std::pair<std::int64_t, LabelSet>> exact_provenance;
  std::map<std::int64_t, std::vector<LabelSet>> exact_sets;  // per source
  std::set<std::uint32_t> exact_labels;
  for (std::size_t t = 0; t < exact.triangles.size(); ++t) {
    const LabelSet& labels = exact.label_sets[exact.label_set[t]];
    if (exact_provenance.insert({exact.source[t], labels}).second) exact_sets[exact.source[t]].push_back(labels);
    exact_labels.insert(labels.begin(), labels.end());
  }
  bool coincident_layers = false;
  for (std::size_t t = 0; t < r.triangles.size() && !coincident_layers; ++t) {
    const LabelSet& labels = r.label_sets[r.label_set[t]];
    if (exact_provenance.count({r.source[t], labels})) continue;
    for (const LabelSet& own : exact_sets[r.source[t]])
      coincident_layers = coincident_layers || std::includes(labels.begin(), labels.end(), own.begin(), own.end());
  }
  const bool layers_may_merge = report.grid > 0 || report.merged_input > 0 || report.reroute_cycles > 0 ||
                                report.snapped_vertices > 0 || report.rerouted > 0 ||
                                coincident_layers;
  for (std::size_t t = 0; t < r.triangles.size(); ++t) {
    const LabelSet& labels = r.label_sets[r.label_set[t]];
    const bool ok = !layers_may_merge ? exact_provenance.count({r.source[t], labels}) > 0
                                      : std::all_of(labels.begin(), labels.end(),
                                                   [&](std::uint32_t l) { return exact_labels.count(l) > 0; });
    if (!ok) {
      ADD_FAILURE() << name << ": rounded triangle " << t << " has provenance the exact arrangement lacks";
      break;
    }
  }
  double total_exact = 0, total_rounded = 0;
  const auto ae = area_per_source(exact, total_exact);
  const auto ar = area_per_source(r, total_rounded);
  // Rounded to nearest doubles, every input triangle keeps its area (to rounding); on a
  // coarser grid, layers thinner than a cell may merge into one (the region keeps one
  // source), so a source may lose area but never gains any.
  int sources_off = 0;
  for (const auto& [source, area] : ae) {
    const auto it = ar.find(source);
    const double rounded = it == ar.end() ? 0.0 : it->second;
    const bool ok = !layers_may_merge ? std::abs(rounded - area) <= 1e-9 * total_exact
                                      : rounded <= area + 1e-9 * total_exact;
    if (!ok && sources_off++ < 3)
      ADD_FAILURE() << name << ": source " << source << " has area " << rounded << ", exact " << area;
  }
  for (const auto& [source, area] : ar)
    EXPECT_TRUE(ae.count(source)) << name << ": source " << source << " is new";
  // Level 1's grid is 2^8 ulps of the largest magnitude; nudging moves by at most 1024 ulps.
  EXPECT_LE(report.max_move_relative, 1e-6) << name;
  EXPECT_EQ(report.max_move == 0, report.max_move_relative == 0) << name;

  // Rounding to nearest that is not valid settles in one pass only where cleaning it (one
  // vertex per position, no triangle without area or twice) makes it valid.
  nearest_ok = check_arrangement(round_nearest(exact)).ok();
  if (!nearest_ok && report.passes == 1) {
    EXPECT_TRUE(check_arrangement(arrangements::mesh_on_positions(round_nearest(exact))).ok())
        << name << ": rounding to nearest was not valid";
  }
  if (rounded) *rounded = r;
  return report;
}

}  // namespace tritri_test::rounding
