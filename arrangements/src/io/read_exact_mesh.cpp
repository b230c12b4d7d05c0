// read_exact_mesh (read_exact_mesh.h): the OBJ and OFF readers of load_mesh_files, with
// every coordinate taken exactly (decimals too), never through a double.
#include "arrangements/read_exact_mesh.h"

#include <string>
#include <utility>

#include "arrangements/as_input.h"
#include "io/mesh_format.h"
#include "io/mesh_reader.h"

namespace arrangements {

ExactMesh read_exact_mesh(const std::string& path) {
  const detail::MeshFormat format = detail::format_of_or_refuse(path, detail::kExactFormats, "read_exact_mesh reads");
  detail::FileBytes in(path);
  detail::SoupBuilder builder(path, /*exact=*/true, /*decimals_exact=*/true);
  if (format == detail::MeshFormat::obj)
    detail::read_obj(in, builder);
  else
    detail::read_off(in, builder);
  builder.finish();
  ExactMesh mesh;
  if (builder.exact_vertices.empty()) {
    mesh.vertices.reserve(builder.vertices.size());
    for (const Vec3& v : builder.vertices) mesh.vertices.push_back(to_exact(v));
  } else {
    mesh.vertices = std::move(builder.exact_vertices);
  }
  mesh.triangles = std::move(builder.triangles);
  return mesh;
}

}  // namespace arrangements
