// arrangements/arrange.h
//
// arrange(input, options): the whole mesh-arrangement pipeline on a loaded soup:
// preprocess, candidate pairs, classification (native or tritri), intersection graph,
// triangulation into the output mesh. The command-line tool `arrange`, the comparison
// tool `tritri-compare`, the Eigen API and the Python module are layers over it.
//
// Inputs:  input   a TriangleSoup (double coordinates: the fast path, new points are
//                  implicit) or an ExactTriangleSoup (rational coordinates: every point
//                  is a rational, CGAL::Epeck; for re-arranging an exact arrangement,
//                  or any rational input); checked here, once (validate_soup below); the
//                  stages then assume it
//          options classifier, threads (<= 0: all cores; at most kMaxThreads, see
//                  thread_count.h, else std::invalid_argument; the caller's TBB arena
//                  limit also applies), scale (exact power-of-two scaling by the
//                  preprocessing; double input only, ignored for exact input),
//                  count_predicates (count the classification stage's orient3d /
//                  orient2d calls)
// Output:  ArrangeResult (ExactArrangeResult for exact input, its vertices rationals):
//          the output mesh (in the input's coordinates, also with scale:
//          its points are rebuilt from the unscaled defining points, exactly) and the
//          statistics (counts and stage times; arrange_stats.h lists them). Of those,
//          t_load_s (0 here) and writing the output are the caller's to add
//          (add_load_time, add_write_time).
// The stages themselves are internal (arrangements/src/stages/, in the order they run;
// docs/ARCHITECTURE.md describes each one's contract).
// A soup with no triangle left after preprocessing (all degenerate, or none at all) is
// valid: its arrangement is empty. Valid input is never refused, with one documented
// exception: a cluster of coplanar triangles that pairwise may overlap in more than
// 1,000,000 triples (thousands of overlapping coplanar wedges, the fan of a self-intersecting
// polygon face of thousands of corners) throws InputError (too_large) after stage 2, before
// its arrangement's cubic cost and memory (arrangements/src/arrange.cpp, issue 36).
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

template <class Mesh>
struct BasicArrangeResult {
  Mesh mesh;
  ArrangeStats stats;
};
using ArrangeResult = BasicArrangeResult<OutputMesh>;
using ExactArrangeResult = BasicArrangeResult<ExactOutputMesh>;

ArrangeResult arrange(const TriangleSoup& input, const ArrangeOptions& options);
ExactArrangeResult arrange(const ExactTriangleSoup& input, const ArrangeOptions& options);

// validate_soup(soup): throws std::invalid_argument, naming the first violation, unless
// every coordinate is finite (exact soups: at most the largest double in magnitude, so
// that doubles bound every point), every index is in range (triangles into vertices, label_set
// into label_sets), and label_set, source and polygon (when not empty) have one entry per
// triangle. Cost: O(#V + #F).
void validate_soup(const TriangleSoup& soup);
void validate_soup(const ExactTriangleSoup& soup);

namespace detail {
// arrange() without validate_soup, for entry points that have checked the same facts at
// their own boundary (the file loader, arrange_eigen.h): every fact is checked once.
ArrangeResult arrange_validated(const TriangleSoup& input, const ArrangeOptions& options);
ExactArrangeResult arrange_validated(const ExactTriangleSoup& input, const ArrangeOptions& options);
}  // namespace detail

}  // namespace arrangements
