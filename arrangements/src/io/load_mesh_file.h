// arrangements/src/io/load_mesh_file.h (internal: the two steps of load_mesh_files, for
// loaders that work on each file between them, as load_csg_file transforms its operands)
//
// AnyTriangleSoup load_mesh_file(path, label)
//   One file exactly as load_mesh_files (load_triangle_soup.h) loads it, alone: the
//   TriangleSoup when every coordinate is a double, else the ExactTriangleSoup; every
//   triangle carries `label` (label_set all 0, label_sets {{label}}), source 0, 1, ...
//   Throws InputError as load_mesh_files does for the file.
//
// void append_mesh_file(all, one, i, path)
//   all   files 0 .. i-1 concatenated by earlier calls (anything when i == 0)
//   one   file i, loaded with label i (by load_mesh_file; it may have been changed since,
//         keeping its triangles' indices into its own vertices)
//   path  file i's name, for the message below
//   Appends one to all as load_mesh_files concatenates its files: vertex indices,
//   `source` and `polygon` offset, label set {i}; all becomes an ExactTriangleSoup (every
//   coordinate converted exactly) when one is one. i == 0: all = one.
//   Throws InputError (too_large, naming path) when the files together have more than
//   INT_MAX vertices or triangles.
//   Cost: O(size of one), plus converting all once when it becomes exact.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "arrangements/load_triangle_soup.h"

namespace arrangements::detail {

AnyTriangleSoup load_mesh_file(const std::string& path, std::uint32_t label);

void append_mesh_file(AnyTriangleSoup& all, AnyTriangleSoup&& one, std::size_t i, const std::string& path);

}  // namespace arrangements::detail
