// csg(): a CSG file's tree over its operands, by boolean() (arrangements/csg.h).
#include "arrangements/csg.h"

#include "arrangements/boolean.h"
#include "arrangements/load_csg.h"

namespace arrangements {

AnyArrangeResult csg(const std::string& path, const ArrangeOptions& options) {
  const CsgScene scene = load_csg_file(path);
  // The loader checked the soup as it read it (as load_mesh_files does).
  return std::visit([&](const auto& soup) -> AnyArrangeResult { return detail::boolean_validated(soup, scene.tree, options); },
                    scene.soup);
}

}  // namespace arrangements
