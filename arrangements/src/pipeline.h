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
#include "arrangements/triangle_soup.h"
#include "stages/4_intersection_graph.h"

namespace arrangements {

struct PipelineInternals {
  TriangleSoup soup;        // after preprocessing (stage 1)
  IntersectionGraph graph;  // after the intersection graph (stage 4)
};

ArrangeResult run_pipeline(const TriangleSoup& input, const ArrangeOptions& options, PipelineInternals* keep);

// The exact path (ExactModel): the same stages on rational points.
ExactArrangeResult run_pipeline(const ExactTriangleSoup& input, const ArrangeOptions& options);

}  // namespace arrangements
