// Load (before stage 1) from a CSG file (load_csg.h): parse the tree and its imports
// (csg_parser.h), then load each operand, map it by its transform (csg_transform.h) and
// append it with its label, as load_mesh_files appends its files (load_mesh_file.h).
#include "arrangements/load_csg.h"

#include <cstdint>
#include <string>
#include <utility>

#include "io/csg_parser.h"
#include "io/csg_transform.h"
#include "io/load_mesh_file.h"
#include "io/mesh_file_checks.h"

namespace arrangements {

CsgScene load_csg_file(const std::string& path) {
  detail::CsgProgram program = detail::parse_csg(path);
  CsgScene scene;
  scene.tree = std::move(program.tree);
  scene.operand_files.reserve(program.imports.size());
  for (std::size_t i = 0; i < program.imports.size(); ++i) {
    const detail::CsgImport& operand = program.imports[i];
    const std::string at = path + ": line " + std::to_string(operand.line) + ": ";
    try {
      AnyTriangleSoup one = detail::load_mesh_file(operand.path, static_cast<std::uint32_t>(i));
      if (operand.transform && !detail::transform_soup(one, *operand.transform))
        detail::refuse(InputErrorKind::non_finite_coordinate, operand.path,
                       "multmatrix moves a vertex beyond the largest finite double");
      detail::append_mesh_file(scene.soup, std::move(one), i, operand.path);
    } catch (const InputError& e) {  // name the import statement too
      throw InputError(e.kind, at + "import: " + e.what());
    }
    scene.operand_files.push_back(operand.path);
  }
  return scene;
}

}  // namespace arrangements
