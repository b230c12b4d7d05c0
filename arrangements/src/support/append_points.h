// arrangements/src/support/append_points.h
//
// append_points(out, count, make): appends make(0), ..., make(count - 1) to out. For
// tritri::ImplicitPoint in parallel (oneTBB, the caller's arena): its copies share
// immutable data through atomic reference counts, and copying a stage's points one by one
// took most of the step. Other points (the exact model's CGAL points, counted atomically
// too, CGAL >= 5.5) are copied by one thread, as before: a path whose speed this does not
// measure. Stages 4 and 5 copy and move their points through it.
// Cost: O(count) copies.
#pragma once

#include <tbb/parallel_for.h>

#include <cstddef>
#include <type_traits>
#include <vector>

#include <tritri/implicit_point.h>

namespace arrangements {

template <class Point, class Make>
void append_points(std::vector<Point>& out, std::size_t count, const Make& make) {
  const std::size_t first = out.size();
  if constexpr (std::is_same_v<Point, tritri::ImplicitPoint>) {
    out.resize(first + count);
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) { out[first + i] = make(i); });
  } else {
    out.reserve(first + count);
    for (std::size_t i = 0; i < count; ++i) out.push_back(make(i));
  }
}

}  // namespace arrangements
