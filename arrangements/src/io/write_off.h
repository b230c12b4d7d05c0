// arrangements/src/io/write_off.h
//
// write_off(path, V, F): writes a triangle soup as an ASCII OFF file, atomically (a
// temporary file in the same folder, then rename), with coordinates printed exactly
// (17 significant digits round-trip every double). Throws std::runtime_error on failure;
// a failed write leaves no partial file.
#pragma once

#include <string>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

void write_off(const std::string& path, const std::vector<Vec3>& V, const std::vector<Tri>& F);

}  // namespace arrangements
