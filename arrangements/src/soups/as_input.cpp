// as_input / to_exact (arrangements/as_input.h).
#include "arrangements/as_input.h"

#include <tbb/parallel_for.h>

namespace arrangements {
namespace {

// The mesh's topology, labels and sources as a soup's, with vertices from `point(i)`.
template <class Coordinates, class Mesh, class Point>
BasicTriangleSoup<Coordinates> soup_of(const Mesh& mesh, Point point) {
  BasicTriangleSoup<Coordinates> s;
  s.vertices.resize(mesh.vertices.size());
  tbb::parallel_for(std::size_t{0}, mesh.vertices.size(), [&](std::size_t i) { s.vertices[i] = point(i); });
  s.triangles = mesh.triangles;
  s.label_set = mesh.label_set;
  s.label_sets = mesh.label_sets;
  s.source = mesh.source;
  return s;
}

}  // namespace

ExactTriangleSoup as_input(const OutputMesh& mesh) {
  return soup_of<ExactVec3>(mesh, [&](std::size_t i) { return tritri::to_exact(mesh.vertices[i]); });
}

ExactTriangleSoup as_input(const ExactOutputMesh& mesh) {
  return soup_of<ExactVec3>(mesh, [&](std::size_t i) { return mesh.vertices[i]; });
}

TriangleSoup as_input(const RoundedMesh& mesh) {
  return soup_of<Vec3>(mesh, [&](std::size_t i) { return mesh.vertices[i]; });
}

ExactVec3 to_exact(const Vec3& v) { return {CGAL::Gmpq(v[0]), CGAL::Gmpq(v[1]), CGAL::Gmpq(v[2])}; }

ExactTriangleSoup to_exact(TriangleSoup soup) {
  ExactTriangleSoup out;
  out.vertices.resize(soup.vertices.size());
  tbb::parallel_for(std::size_t{0}, soup.vertices.size(),
                    [&](std::size_t i) { out.vertices[i] = to_exact(soup.vertices[i]); });
  std::vector<Vec3>().swap(soup.vertices);
  out.triangles = std::move(soup.triangles);
  out.label_set = std::move(soup.label_set);
  out.label_sets = std::move(soup.label_sets);
  out.source = std::move(soup.source);
  out.polygon = std::move(soup.polygon);
  return out;
}

}  // namespace arrangements
