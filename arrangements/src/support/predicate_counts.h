// arrangements/src/support/predicate_counts.h
//
// classification_counts(): the current thread's predicate counter for the classification
// stage, or nullptr (the default: nothing is counted). classify_pairs sets it per worker
// when asked for counts; both classifiers (native and the tritri adapter) add their
// orient3d / orient2d calls to it. Cost: one thread-local load per predicate call.
#pragma once

#include <tritri/counting_kernel.h>

namespace arrangements {

inline tritri::PredicateCounts*& classification_counts() {
  thread_local tritri::PredicateCounts* counts = nullptr;
  return counts;
}

}  // namespace arrangements
