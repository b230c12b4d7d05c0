// arrangements/src/stages/1_preprocess.h
//
// Stage 1 of the pipeline: clean a TriangleSoup exactly, and optionally scale it by a
// power of two.
//
// preprocess<M>(in, options, stats), for a point model M (models/point_model.h): from
// the input soup (M::Input coordinates) to the stages' soup (M::Vertex);
// preprocess(in, options, stats) on a TriangleSoup is preprocess<DoubleModel>.
//   in       a valid soup (validate_soup in arrangements/arrange.h: finite coordinates,
//            indices in range, per-triangle lists of the right size; not checked again)
//   options  .scale: multiply every coordinate by 2^k (below; double models only: exact
//            input is never scaled, scale_exponent stays 0)
// returns the soup with
//   vertices    the distinct positions used by a kept triangle, in first-use order (the
//               order in which the kept triangles, in order, first name them); identical
//               coordinates are one vertex (exact comparison, -0.0 == 0.0; a -0.0
//               coordinate is written as +0.0)
//   triangles   the input triangles in input order, minus
//                 degenerate ones: two corners at the same position, or three exactly
//                 collinear corners (tritri::orient2d is Zero in the XY, YZ and ZX
//                 projections: three points are collinear iff all three projections are);
//                 duplicates: a triangle with the same three positions as an earlier kept
//                 one, in any order or orientation; the earlier one absorbs its labels;
//               each with its first occurrence's corner order (so its orientation)
//   labels, label_sets   each kept triangle's label set is the union of its own and its
//               duplicates' sets (no cap on the number of labels); label_sets holds the
//               distinct sets in first-use order
//   source      the kept triangle's own (first occurrence's) source
// and fills stats (every field is overwritten):
//   merged_vertices        input vertices whose position equals an earlier input vertex's
//   unreferenced_vertices  distinct positions that no kept triangle uses (also those of
//                          removed triangles only); so #out.V = #in.V - merged - unreferenced
//   removed_degenerate     degenerate triangles removed
//   removed_duplicate      duplicate triangles removed; #out.F = #in.F - both
//   scale_exponent         the k of the scaling (0 without scaling)
//
// Scaling (options.scale): with M the largest |coordinate| of the output, k is chosen so
// that M * 2^k lies in [2^9, 2^10), whatever M is (also below 1 and subnormal; k is found
// with std::frexp, no integer shifts). Scaling by a power of two is exact, so it changes
// no predicate, but it puts every model in one known exponent range, which is what
// floating-point filters with precomputed error bounds for later stages rely on: any
// polynomial of degree d in the coordinates then stays below 2^(10 d) (no overflow for
// the degrees of implicit-point predicates), and tiny models are lifted away from the
// underflow range. k < 0 can push small coordinates of a model with a huge dynamic range
// into the subnormal range, where they would be rounded: then nothing is scaled
// (scale_exponent 0; the later stages are exact at any magnitude, only slower). All-zero coordinates (no triangle
// survives anyway) give k = 0.
//
// Cost: O(#V log #V + #F log #F + total labels of duplicates) (parallel sorts of the
// positions' and corner sets' hashes), plus one to three exact orient2d per triangle, in
// parallel; distinct label sets are kept in a std::map. The result does not depend on the
// number of threads.
#pragma once

#include <cstddef>
#include <vector>

#include "arrangements/input_error.h"
#include "arrangements/triangle_soup.h"
#include "models/double_model.h"

namespace arrangements {

struct PreprocessOptions {
  bool scale = false;
  // When not null, receives one entry per input triangle: -1 for a removed degenerate
  // one, else 2 k + r where k is the output triangle it became or was merged into as a
  // duplicate and r is 1 when its corners run the other way round (opposite orientation),
  // 0 otherwise. Stage 6 (winding numbers) counts every copy with its orientation.
  std::vector<int>* kept_as = nullptr;
};

struct PreprocessStats {
  std::size_t merged_vertices = 0;
  std::size_t removed_degenerate = 0;
  std::size_t removed_duplicate = 0;
  std::size_t unreferenced_vertices = 0;
  int scale_exponent = 0;
};

template <class M>
BasicTriangleSoup<typename M::Vertex> preprocess(const BasicTriangleSoup<typename M::Input>& in,
                                                 const PreprocessOptions& options, PreprocessStats& stats);

inline TriangleSoup preprocess(const TriangleSoup& in, const PreprocessOptions& options, PreprocessStats& stats) {
  return preprocess<DoubleModel>(in, options, stats);
}

}  // namespace arrangements
