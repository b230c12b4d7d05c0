// arrangements/src/io/write_off.h (internal: for tools and tests)
//
// write_off(path, V, F): writes a triangle soup as an ASCII OFF file: "OFF", "#V #F 0",
// "X Y Z" per vertex (17 significant digits: every double reads back as itself), "3 a b c"
// per triangle (0-based). The bytes are those of write_mesh for an .off file without
// provenance; defined in write_mesh.cpp, with the one OFF writer.
// Atomic, with AtomicFile (atomic_file.h): a failed write leaves no file, partial or
// temporary; throws std::runtime_error naming the path and the system's reason.
#pragma once

#include <string>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

void write_off(const std::string& path, const std::vector<Vec3>& V, const std::vector<Tri>& F);

}  // namespace arrangements
