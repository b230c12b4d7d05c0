// arrangements/stats_json.h
//
// The statistics of one pipeline run under their public key names, defined once:
//   for_each_stat(s, f)  calls f(key, value, decimals) for every key, in order: value is a
//                        std::size_t, long long, int, double or std::string; decimals is
//                        how many digits a double is printed with (0 for the others)
//   stats_json(s)        those keys as one JSON object (the `arrange --stats` line; also the
//                        per-classifier objects of tritri-compare)
// The Python module's stats dict (tritri.arrange) is filled by for_each_stat too, so the
// CLI JSON and the Python dict have the same keys. Keys are the ArrangeStats field names;
// `lpi` repeats intersection_points (the new points of classification are LPIs).
// Cost: O(1).
#pragma once

#include <cstdio>
#include <string>
#include <type_traits>

#include "arrangements/arrange.h"

namespace arrangements {

template <class F>
void for_each_stat(const ArrangeStats& s, F&& f) {
  f("in_vertices", s.in_vertices, 0);
  f("in_triangles", s.in_triangles, 0);
  f("merged_vertices", s.merged_vertices, 0);
  f("removed_degenerate", s.removed_degenerate, 0);
  f("removed_duplicate", s.removed_duplicate, 0);
  f("candidate_pairs", s.candidate_pairs, 0);
  f("intersecting_pairs", s.intersecting_pairs, 0);
  f("intersection_points", s.intersection_points, 0);
  f("lpi", s.intersection_points, 0);
  f("tpi", s.tpi, 0);
  f("segments", s.segments, 0);
  f("tri_segments", s.tri_segments, 0);
  f("coplanar_pairs", s.coplanar_pairs, 0);
  f("out_vertices", s.out_vertices, 0);
  f("out_edges", s.out_edges, 0);
  f("out_triangles", s.out_triangles, 0);
  f("euler", s.euler, 0);
  f("orient3d_calls", s.orient3d_calls, 0);
  f("orient2d_calls", s.orient2d_calls, 0);
  f("classifier", s.classifier, 0);
  f("threads", s.threads, 0);
  f("t_load_s", s.t_load_s, 6);
  f("t_preprocess_s", s.t_preprocess_s, 6);
  f("t_detect_s", s.t_detect_s, 6);
  f("t_classify_s", s.t_classify_s, 6);
  f("t_triangulate_s", s.t_triangulate_s, 6);
  f("t_output_s", s.t_output_s, 6);
  f("t_total_s", s.t_total_s, 6);
  f("peak_rss_mb", s.peak_rss_mb, 1);
}

inline std::string stats_json(const ArrangeStats& s) {
  std::string out = "{";
  for_each_stat(s, [&out](const char* key, const auto& value, int decimals) {
    using T = std::decay_t<decltype(value)>;
    if (out.size() > 1) out += ", ";
    out += '"';
    out += key;
    out += "\": ";
    if constexpr (std::is_same_v<T, std::string>) {
      out += '"';
      for (const char c : value) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
      }
      out += '"';
    } else if constexpr (std::is_floating_point_v<T>) {
      char buf[400];  // %.6f of any finite double fits
      std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
      out += buf;
    } else {
      out += std::to_string(value);
    }
  });
  return out + "}";
}

}  // namespace arrangements
