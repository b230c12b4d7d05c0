// tests/support/exact_soups.h
//
// Conversions for the exact-path tests, each exact (no rounding); the public ones
// (arrangements::as_input, arrangements::to_exact) are in arrangements/as_input.h:
//   with_vertices<To>(soup, convert)  the soup with its vertices converted
//   exact_mesh(mesh)      an OutputMesh with its implicit points' exact coordinates
//   sorted_vertices(mesh) the vertex coordinates, sorted lexicographically (comparing
//                         two arrangements' vertex sets whatever their numbering)
#pragma once

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <vector>

#include <tritri/implicit_point.h>

#include "arrangements/output_mesh.h"
#include "arrangements/triangle_soup.h"

namespace tritri_test {

// The soup with every vertex converted by `convert`, everything else copied.
template <class To, class From, class Convert>
arrangements::BasicTriangleSoup<To> with_vertices(const arrangements::BasicTriangleSoup<From>& s, Convert convert) {
  arrangements::BasicTriangleSoup<To> e;
  for (const auto& v : s.vertices) e.vertices.push_back(convert(v));
  e.triangles = s.triangles;
  e.label_set = s.label_set;
  e.label_sets = s.label_sets;
  e.source = s.source;
  e.polygon = s.polygon;
  return e;
}

inline arrangements::ExactOutputMesh exact_mesh(const arrangements::OutputMesh& m) {
  arrangements::ExactOutputMesh e;
  for (const auto& p : m.vertices) e.vertices.push_back(tritri::to_exact(p));
  e.triangles = m.triangles;
  e.source = m.source;
  e.label_set = m.label_set;
  e.label_sets = m.label_sets;
  return e;
}

inline std::vector<arrangements::ExactVec3> sorted_vertices(const arrangements::ExactOutputMesh& m) {
  std::vector<arrangements::ExactVec3> v = m.vertices;
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace tritri_test
