// arrangements/arrange_stats.h
//
// The statistics of one pipeline run, defined once: ArrangeStats holds them and
// kArrangeStats is the one table of their public keys, in output order, each with its
// member, the digits a double is printed with, and a one-line meaning. Everything that
// shows them is generated from that table:
//   for_each_stat(s, f)      calls f(key, value, decimals) for every key, in order: value
//                            is the member (a std::size_t, long long, int, double or
//                            std::string); decimals is 0 for all but the doubles
//   stats_json(s)            one JSON object: the `arrange --stats` line, and the native /
//                            tritri objects of `tritri-compare --json`; always valid JSON
//                            (a double that is not finite is written null)
//   stats_key_list(...)      the keys with their meanings as text: the key list of
//                            `arrange --help` and of the docstring of tritri.arrange
//   the Python dict          tritri.arrange(...)["stats"] (python/tritri_module.cpp, with
//                            for_each_stat)
// A new statistic is a member of ArrangeStats plus one row of kArrangeStats.
//
// arrange() fills every field itself except the work its caller does around it; a caller
// that reads the input or writes the output reports those through:
//   add_load_time(s, seconds)   reading the input before arrange(): adds to t_load_s and
//                               to t_total_s
//   add_write_time(s, seconds)  writing the output after it: adds to t_output_s and to
//                               t_total_s, and takes peak_rss_mb again (writing can raise it)
// Cost: O(1) each (stats_key_list: O(length of the text)).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace arrangements {

struct ArrangeStats {
  std::size_t in_vertices = 0, in_triangles = 0;
  std::size_t merged_vertices = 0, removed_degenerate = 0, removed_duplicate = 0;
  std::size_t candidate_pairs = 0, classified_pairs = 0, intersecting_pairs = 0, coplanar_pairs = 0;
  std::size_t intersection_points = 0;  // distinct new points of classification (LPIs)
  std::size_t segments = 0, tri_segments = 0;
  std::size_t tpi = 0;
  std::size_t whole_clusters = 0;  // coplanar clusters triangulated at once (stage 5)
  std::size_t out_vertices = 0, out_edges = 0, out_triangles = 0;
  long long euler = 0;
  std::size_t orient3d_calls = 0, orient2d_calls = 0;  // in the classification stage
  int threads = 0;
  std::string classifier;
  double t_load_s = 0, t_preprocess_s = 0, t_detect_s = 0, t_classify_s = 0, t_triangulate_s = 0, t_output_s = 0,
         t_total_s = 0;
  double peak_rss_mb = 0;
  int round_passes = 0;  // filled by the caller that rounds (round_mesh.h), else 0
  double round_max_move = 0, round_max_move_rel = 0;
  std::size_t round_rerouted = 0;
  std::size_t round_merged_input = 0;
  std::size_t round_snapped_vertices = 0;
  std::size_t round_nudged = 0;
  std::size_t winding_cells = 0, winding_components = 0;  // Booleans (boolean.h), else 0
  double t_winding_s = 0;
};

// One row of the table.
template <class T>
struct StatEntry {
  const char* key;
  T ArrangeStats::*member;
  int decimals;  // doubles: digits after the decimal point, or -d: d digits after the point
                 // of the exponent form (1.234e-16); 0 for the others
  const char* meaning;
};

template <class T>
constexpr StatEntry<T> stat_entry(const char* key, T ArrangeStats::*member, int decimals, const char* meaning) {
  return {key, member, decimals, meaning};
}

// The table: every public key, in output order. `lpi` repeats intersection_points (the new
// points of classification are LPIs).
inline constexpr auto kArrangeStats = std::make_tuple(
    stat_entry("in_vertices", &ArrangeStats::in_vertices, 0, "input vertices, all files together"),
    stat_entry("in_triangles", &ArrangeStats::in_triangles, 0, "input triangles (an n-gon counts n - 2)"),
    stat_entry("merged_vertices", &ArrangeStats::merged_vertices, 0,
               "input vertices at the exact position of an earlier one (merged)"),
    stat_entry("removed_degenerate", &ArrangeStats::removed_degenerate, 0,
               "degenerate triangles removed (repeated or collinear corners)"),
    stat_entry("removed_duplicate", &ArrangeStats::removed_duplicate, 0,
               "duplicate triangles removed (the same three positions)"),
    stat_entry("candidate_pairs", &ArrangeStats::candidate_pairs, 0,
               "triangle pairs the broad phase kept: boxes overlap, they share no vertex whose star is embedded (doubles), and they share a corner or their extents along 10 diagonal directions overlap (around a hub vertex: those whose directions from it meet)"),
    stat_entry("classified_pairs", &ArrangeStats::classified_pairs, 0,
               "candidate pairs left to classify (not settled by a plane or as neighbours)"),
    stat_entry("intersecting_pairs", &ArrangeStats::intersecting_pairs, 0,
               "pairs that meet beyond what they share in the mesh"),
    stat_entry("intersection_points", &ArrangeStats::intersection_points, 0, "distinct new points of classification"),
    stat_entry("lpi", &ArrangeStats::intersection_points, 0, "the same (they are LPIs)"),
    stat_entry("tpi", &ArrangeStats::tpi, 0, "new points of triangulation (TPIs)"),
    stat_entry("whole_clusters", &ArrangeStats::whole_clusters, 0,
               "clusters of overlapping coplanar triangles triangulated at once, not per triangle"),
    stat_entry("segments", &ArrangeStats::segments, 0, "distinct constraint segments"),
    stat_entry("tri_segments", &ArrangeStats::tri_segments, 0, "constraint segments summed over triangles"),
    stat_entry("coplanar_pairs", &ArrangeStats::coplanar_pairs, 0, "intersecting pairs that are coplanar"),
    stat_entry("out_vertices", &ArrangeStats::out_vertices, 0, "output vertices (referenced)"),
    stat_entry("out_edges", &ArrangeStats::out_edges, 0, "output edges"),
    stat_entry("out_triangles", &ArrangeStats::out_triangles, 0, "output triangles"),
    stat_entry("euler", &ArrangeStats::euler, 0, "out_vertices - out_edges + out_triangles"),
    stat_entry("orient3d_calls", &ArrangeStats::orient3d_calls, 0,
               "orient3d calls of classification (0 unless counted)"),
    stat_entry("orient2d_calls", &ArrangeStats::orient2d_calls, 0,
               "orient2d calls of classification (0 unless counted)"),
    stat_entry("classifier", &ArrangeStats::classifier, 0, "tritri or native"),
    stat_entry("threads", &ArrangeStats::threads, 0, "worker threads"),
    stat_entry("t_load_s", &ArrangeStats::t_load_s, 6, "seconds reading the input files"),
    stat_entry("t_preprocess_s", &ArrangeStats::t_preprocess_s, 6, "seconds of preprocessing"),
    stat_entry("t_detect_s", &ArrangeStats::t_detect_s, 6,
               "seconds finding the pairs to classify (box search and exact early-outs)"),
    stat_entry("t_classify_s", &ArrangeStats::t_classify_s, 6,
               "seconds classifying pairs, building the intersection graph"),
    stat_entry("t_triangulate_s", &ArrangeStats::t_triangulate_s, 6, "seconds triangulating"),
    stat_entry("t_winding_s", &ArrangeStats::t_winding_s, 6,
               "seconds finding winding numbers and the Boolean's boundary (0 without a Boolean)"),
    stat_entry("t_output_s", &ArrangeStats::t_output_s, 6,
               "seconds making (rounding with --round safe, writing) the output mesh"),
    stat_entry("t_total_s", &ArrangeStats::t_total_s, 6, "seconds in all, loading and writing included"),
    stat_entry("peak_rss_mb", &ArrangeStats::peak_rss_mb, 1, "peak resident memory of the process, MB"),
    stat_entry("round_passes", &ArrangeStats::round_passes, 0,
               "passes of rounding and re-arranging of --round safe (0 without it)"),
    stat_entry("round_max_move", &ArrangeStats::round_max_move, -3,
               "--round safe: every output vertex lies within this distance of the exact arrangement"),
    stat_entry("round_max_move_rel", &ArrangeStats::round_max_move_rel, -3,
               "round_max_move divided by the diagonal of the bounding box"),
    stat_entry("round_rerouted", &ArrangeStats::round_rerouted, 0,
               "--round safe: vertices its last resort put on a nearby edge or face, each staying at its "
               "nearest double (0 unless the passes failed)"),
    stat_entry("round_merged_input", &ArrangeStats::round_merged_input, 0,
               "--round safe: input vertices its last resort merged into another (within 4 to 256 ulps), the "
               "merged input arranged again (0 unless every other way failed)"),
    stat_entry("round_snapped_vertices", &ArrangeStats::round_snapped_vertices, 0,
               "--round safe: input vertices its last resort moved onto the plane of a nearly coplanar layer "
               "or of a face they touch (exactly), the input arranged again (0 unless every other way failed)"),
    stat_entry("round_nudged", &ArrangeStats::round_nudged, 0,
               "--round safe: moves of vertices by 1 to 1024 ulps where that left fewer conflicts, its last "
               "resort, summed over that step's cycles (0 unless every other way failed)"),
    stat_entry("winding_cells", &ArrangeStats::winding_cells, 0,
               "Booleans: cells of space the arrangement's triangles bound, per connected component (0 without)"),
    stat_entry("winding_components", &ArrangeStats::winding_components, 0,
               "Booleans: connected components of the arrangement (triangles joined by edges; 0 without)"));

// The keys and meanings alone, in order.
struct StatKey {
  const char* key;
  const char* meaning;
};
inline constexpr auto kArrangeStatKeys = std::apply(
    [](const auto&... e) {
      return std::array<StatKey, sizeof...(e)>{StatKey{e.key, e.meaning}...};
    },
    kArrangeStats);

template <class F>
void for_each_stat(const ArrangeStats& s, F&& f) {
  std::apply([&](const auto&... e) { (f(e.key, s.*(e.member), e.decimals), ...); }, kArrangeStats);
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
      if (!std::isfinite(value))  // JSON has no inf or nan: null (never expected; valid JSON always)
        std::snprintf(buf, sizeof buf, "null");
      else if (decimals >= 0)
        std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
      else
        std::snprintf(buf, sizeof buf, "%.*e", -decimals, value);
      out += buf;
    } else {
      out += std::to_string(value);
    }
  });
  return out + "}";
}

// The keys in order, one per line: `indent` spaces, the key, its meaning from column
// `column` (on the next line if the key reaches it), the meaning's words wrapped so that
// no line passes `width` characters (unless one word is longer), continued at `column`.
inline std::string stats_key_list(std::size_t indent, std::size_t column, std::size_t width) {
  std::string out;
  for (const StatKey& k : kArrangeStatKeys) {
    std::string line(indent, ' ');
    line += k.key;
    auto new_line = [&] {
      out += line;
      out += '\n';
      line.assign(column, ' ');
    };
    if (line.size() + 1 > column) new_line();
    line.resize(column, ' ');
    bool first = true;  // no word on this line yet
    for (std::string_view rest = k.meaning; !rest.empty();) {
      const std::size_t space = rest.find(' ');
      const std::string_view word = rest.substr(0, space);
      rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
      if (!first && line.size() + 1 + word.size() > width) {
        new_line();
        first = true;
      }
      if (!first) line += ' ';
      line += word;
      first = false;
    }
    out += line;
    out += '\n';
  }
  return out;
}

inline void add_load_time(ArrangeStats& s, double seconds) {
  s.t_load_s += seconds;
  s.t_total_s += seconds;
}

void add_write_time(ArrangeStats& s, double seconds);  // src/arrange.cpp

}  // namespace arrangements
