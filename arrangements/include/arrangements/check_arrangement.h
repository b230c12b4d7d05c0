// arrangements/check_arrangement.h
//
// check_arrangement(mesh): verifies exactly that the triangles of an arrangement meet only
// in shared vertices and shared edges: every pair of output triangles whose (conservative)
// bounding boxes overlap, and that share a vertex or whose extents along 10 diagonal
// directions overlap too (tritri/direction_slabs.h: a certified test; pairs apart there
// do not meet), is classified with tritri on the implicit points
// (tritri::ImplicitKernel; rational points of an ExactOutputMesh: CGAL::Epeck; the doubles
// of a RoundedMesh as explicit points), and the pair is a violation unless its intersection is
// exactly what it shares by vertex id (nothing, a common vertex, or a common edge). Two
// triangles with the same three vertices, two distinct vertices at one position, a
// vertex inside another triangle or on its edge, crossing or overlapping triangles are
// all violations. Degenerate output triangles are violations too.
//
// Returns the violations (described up to max_reported, all counted; every violating pair
// of triangles listed). Exact. Cost: one box
// self-intersection search plus one exact classification per pair kept, counted in
// pairs_checked (the filters make most of them as cheap as double arithmetic); parallel (TBB). Memory: the
// boxes plus batches of 2^20 pairs (classified as the search finds them), whatever the
// number of overlapping pairs. A RoundedMesh with distinct positions, no degenerate and no
// repeated triangle (what round_safe makes) goes through the pipeline's stage 2 instead
// (stages/2_candidate_pairs.h: its search, its embedded vertex stars and its exact
// early-outs settle the pairs that meet only in what they share, before any
// classification; pairs_checked counts the pairs its broad phase keeps, so neighbours
// around embedded stars are not counted); memory: the pairs it keeps. On EMBER 88566's rounded mesh (49k triangles)
// that is 0.29 s instead of 0.88 s.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "arrangements/output_mesh.h"

namespace arrangements {

struct ArrangementCheck {
  std::size_t pairs_checked = 0;
  std::size_t violations = 0;
  std::size_t degenerate_triangles = 0;
  std::vector<std::string> examples;  // human-readable, at most max_reported
  std::vector<std::pair<int, int>> violating_pairs;  // all of them: triangles i < j, sorted
  bool ok() const { return violations == 0 && degenerate_triangles == 0; }
};

ArrangementCheck check_arrangement(const OutputMesh& mesh, std::size_t max_reported = 10);
ArrangementCheck check_arrangement(const ExactOutputMesh& mesh, std::size_t max_reported = 10);
ArrangementCheck check_arrangement(const RoundedMesh& mesh, std::size_t max_reported = 10);

// The same check restricted to the pairs (and degenerate triangles) with a triangle marked
// in `changed` (one mark per triangle, else std::invalid_argument): after a local change
// to a mesh whose other pairs were checked before. Cost: one box search of the marked
// triangles against all, plus one classification per overlapping pair found that stage
// 2's early-outs do not settle (where they apply, as above: 1.1 s instead of 5.5 s for 5,128
// changed triangles of EMBER 79741's rounded mesh, 16.4M box pairs).
ArrangementCheck check_arrangement_touching(const RoundedMesh& mesh, const std::vector<char>& changed,
                                            std::size_t max_reported = 10);

}  // namespace arrangements
