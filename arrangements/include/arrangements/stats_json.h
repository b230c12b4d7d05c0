// arrangements/stats_json.h
//
// stats_json(s): ArrangeStats as one JSON object (the `arrange --stats` line; also the
// per-classifier objects of tritri-compare). Keys are the field names; `lpi` repeats
// intersection_points (the new points of classification are LPIs). Cost: O(1).
#pragma once

#include <cstdio>
#include <string>

#include "arrangements/arrange.h"

namespace arrangements {

inline std::string stats_json(const ArrangeStats& s) {
  char buf[2048];
  std::snprintf(
      buf, sizeof buf,
      "{\"in_vertices\": %zu, \"in_triangles\": %zu, \"merged_vertices\": %zu, \"removed_degenerate\": %zu, "
      "\"removed_duplicate\": %zu, \"candidate_pairs\": %zu, \"intersecting_pairs\": %zu, "
      "\"intersection_points\": %zu, \"lpi\": %zu, \"tpi\": %zu, \"segments\": %zu, \"tri_segments\": %zu, "
      "\"coplanar_pairs\": %zu, \"out_vertices\": %zu, \"out_edges\": %zu, \"out_triangles\": %zu, "
      "\"euler\": %lld, \"orient3d_calls\": %zu, \"orient2d_calls\": %zu, \"classifier\": \"%s\", \"threads\": %d, "
      "\"t_load_s\": %.6f, \"t_preprocess_s\": %.6f, \"t_detect_s\": %.6f, \"t_classify_s\": %.6f, "
      "\"t_triangulate_s\": %.6f, \"t_output_s\": %.6f, \"t_total_s\": %.6f, \"peak_rss_mb\": %.1f}",
      s.in_vertices, s.in_triangles, s.merged_vertices, s.removed_degenerate, s.removed_duplicate, s.candidate_pairs,
      s.intersecting_pairs, s.intersection_points, s.intersection_points, s.tpi, s.segments, s.tri_segments,
      s.coplanar_pairs, s.out_vertices, s.out_edges, s.out_triangles, s.euler, s.orient3d_calls, s.orient2d_calls,
      s.classifier.c_str(), s.threads, s.t_load_s, s.t_preprocess_s, s.t_detect_s, s.t_classify_s, s.t_triangulate_s,
      s.t_output_s, s.t_total_s, s.peak_rss_mb);
  return buf;
}

}  // namespace arrangements
