// arrangements/arrange.h
//
// arrange(input, options): the whole mesh-arrangement pipeline on a loaded soup:
// preprocess, candidate pairs, classification (native or tritri), intersection graph,
// coplanar propagation, triangulation, output mesh. The command-line tool `arrange`, the
// comparison tool `tritri-compare`, the Eigen API and the Python module are layers over it.
//
// Inputs:  input   a TriangleSoup (e.g. load_triangle_soups); finite coordinates, valid
//                  indices (otherwise std::invalid_argument)
//          options classifier, threads (<= 0: all cores; at most kMaxThreads, see
//                  thread_count.h, else std::invalid_argument; the caller's TBB arena
//                  limit also applies), scale (exact power-of-two scaling by the
//                  preprocessing), count_predicates (count the classification stage's
//                  orient3d / orient2d calls)
// Output:  ArrangeResult: the output mesh (in the input's coordinates, also with scale:
//          its points are rebuilt from the unscaled defining points, exactly) and the
//          statistics (counts and stage times; arrange_stats.h lists them). Of those,
//          t_load_s (0 here) and writing the output are the caller's to add
//          (add_load_time, add_write_time).
// The stages themselves are internal (arrangements/src/stages/, in the order they run;
// docs/ARCHITECTURE.md describes each one's contract).
// A soup with no triangle left after preprocessing (all degenerate, or none at all) is
// valid: its arrangement is empty. Valid input is never refused.
// Exact throughout; deterministic for any number of threads.
#pragma once

#include <cstddef>
#include <string>

#include "arrangements/arrange_stats.h"
#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

// Native: the 2020 case analysis; Tritri: tritri::classify through the adapter. Both give
// the same arrangement; they differ in speed and in the predicates they call.
enum class Classifier { Native, Tritri };

struct ArrangeOptions {
  Classifier classifier = Classifier::Tritri;
  int threads = 0;
  bool scale = false;
  bool count_predicates = false;  // fill orient3d_calls / orient2d_calls (classification)
};

struct ArrangeResult {
  OutputMesh mesh;
  ArrangeStats stats;
};

ArrangeResult arrange(const TriangleSoup& input, const ArrangeOptions& options);

}  // namespace arrangements
