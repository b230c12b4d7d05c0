// arrangements/src/pipeline.h (internal)
//
// run_pipeline: arrange() with access to what the stages built on the way, for the tools
// that compare classifiers (tritri-compare) and for tests. arrange() is validate_soup,
// then run_pipeline without `keep`.
//   keep  when not null, receives the preprocessed soup and its intersection graph
// Precondition: a valid soup (validate_soup; the file loader's soups are valid by
// construction). Same output and exactness as arrange() (arrangements/arrange.h).
#pragma once

#include "arrangements/arrange.h"
#include "arrangements/boolean.h"
#include "arrangements/triangle_soup.h"
#include "models/double_model.h"
#include "models/exact_model.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

template <class M>
struct BasicPipelineInternals {
  BasicTriangleSoup<typename M::Vertex> soup;         // after preprocessing (stage 1)
  BasicIntersectionGraph<typename M::Point> graph;    // after the intersection graph (stage 4)
};
using PipelineInternals = BasicPipelineInternals<DoubleModel>;

// tree: when not null, stage 6 turns the arrangement into the boundary of the tree's
// solid (arrangements/boolean.h; the input's labels name the operands).
ArrangeResult run_pipeline(const TriangleSoup& input, const ArrangeOptions& options, PipelineInternals* keep,
                           const CsgNode* tree = nullptr);

// The exact path (ExactModel): the same stages on rational points.
ExactArrangeResult run_pipeline(const ExactTriangleSoup& input, const ArrangeOptions& options,
                                BasicPipelineInternals<ExactModel>* keep, const CsgNode* tree = nullptr);

}  // namespace arrangements
