// arrangements/read_exact_mesh.h
//
// read_exact_mesh(path): read an OBJ or OFF mesh with exact rational coordinates, as
// write_mesh(path, mesh, {.exact = true}) writes them (write_mesh.h), or with ordinary
// decimal coordinates, each read as the exact rational value of its decimal text (so
// "0.1" is 1/10, not the double nearest to it). The files are read by the OBJ and OFF
// readers of load_mesh_files (load_triangle_soup.h), with its grammar, checks and
// messages; only the decimals differ: load_mesh_files reads them as the nearest double
// (for the pipeline's input), read_exact_mesh as their exact value.
//
//   path     an .obj or .off file (the extension decides, any case)
// returns ExactMesh
//   vertices   #V exact coordinates, in file order
//   triangles  #F vertex indices into `vertices`; a face with n > 3 corners becomes n - 2
//              triangles, as load_mesh_files triangulates it (on the exact coordinates;
//              arrange writes triangles only)
//
// Numbers (one whitespace-free token each), as load_triangle_soup.h describes them:
//   rational  [+-]? digits "/" digits, the denominator not zero; need not be reduced
//   decimal   [+-]? ( digits ( "." digits? )? | "." digits ) ( [eE] [+-]? digits )?
//   any number of digits (in a numerator, a denominator or a decimal: what write_mesh
//   writes is always read back), and a decimal exponent of at most 4096 in absolute value
//   (larger ones would make numbers far larger than their text; no double needs one).
//   Unlike load_mesh_files, any magnitude is kept (a coordinate beyond the double range is
//   refused there, since the pipeline needs finite boxes). Lines: as load_triangle_soup.h
//   describes them (NUL bytes refused; at most 1 MiB, except vertex and face lines of numbers).
// A file without faces is returned as it is (write_mesh writes empty meshes too).
//
// Throws InputError (input_error.h) naming the file and the line, of the kind
// load_mesh_files gives for the same text: unreadable_file, unknown_format (another
// extension), unsupported_variant (e.g. OBJ "l" statements, 4OFF), malformed,
// non_finite_coordinate ("nan", "inf"), index_out_of_range, too_few_corners, too_large
// (a larger exponent, more than INT_MAX vertices or triangles). Never
// crashes on any input.
//
// Exact: no rounding anywhere. Cost: linear in the file size, plus the rational arithmetic
// of every coordinate (GMP; a few times slower than reading doubles).
#pragma once

#include <CGAL/Gmpq.h>

#include <array>
#include <string>
#include <vector>

#include "arrangements/input_error.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

struct ExactMesh {
  std::vector<std::array<CGAL::Gmpq, 3>> vertices;
  std::vector<Tri> triangles;
};

ExactMesh read_exact_mesh(const std::string& path);

}  // namespace arrangements
