// tests/support/exact_soups.h
//
// Conversions for the exact-path tests, each exact (no rounding):
//   with_vertices<To>(soup, convert)  the soup with its vertices converted
//   exact_soup(soup)      a TriangleSoup with its doubles as rationals (ExactTriangleSoup)
//   exact_mesh(mesh)      an OutputMesh with its implicit points' exact coordinates
//   as_soup(mesh)         an exact (or rounded) arrangement as the input of the next one
//                         (labels, label sets and sources carried)
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

inline arrangements::ExactTriangleSoup exact_soup(const arrangements::TriangleSoup& s) {
  return with_vertices<arrangements::ExactVec3>(
      s, [](const arrangements::Vec3& v) { return arrangements::ExactVec3{CGAL::Gmpq(v[0]), CGAL::Gmpq(v[1]), CGAL::Gmpq(v[2])}; });
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

template <class Point>
arrangements::BasicTriangleSoup<Point> as_soup(const arrangements::BasicOutputMesh<Point>& m) {
  arrangements::BasicTriangleSoup<Point> s;
  s.vertices = m.vertices;
  s.triangles = m.triangles;
  s.label_set = m.label_set;
  s.label_sets = m.label_sets;
  s.source = m.source;
  return s;
}

inline std::vector<arrangements::ExactVec3> sorted_vertices(const arrangements::ExactOutputMesh& m) {
  std::vector<arrangements::ExactVec3> v = m.vertices;
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace tritri_test
