// arrangements/read_exact_mesh.h
//
// read_exact_mesh(path): read an OBJ or OFF mesh with exact rational coordinates, as
// write_mesh(path, mesh, {.exact = true}) writes them (write_mesh.h), or with ordinary
// decimal coordinates, each read as the exact rational value of its decimal text (so
// "0.1" is 1/10, not the double nearest to it). For the pipeline's input use
// load_mesh_files (load_triangle_soup.h): it reads the same rationals (with the same
// grammar) but decimals as doubles, triangulates polygons and accepts more of the formats.
//
//   path     an .obj or .off file (the extension decides, any case)
// returns ExactMesh
//   vertices   #V exact coordinates, in file order
//   triangles  #F vertex indices into `vertices`; a face with n > 3 corners becomes the
//              fan (c0, c_i, c_(i+1)), i = 1 .. n-2 (what load_triangle_soup makes of a
//              convex polygon; arrange writes triangles only)
//
// Numbers (one whitespace-free token each):
//   rational  [+-]? digits ( "/" digits )?   the denominator not zero; need not be reduced
//   decimal   [+-]? ( digits ( "." digits? )? | "." digits ) ( [eE] [+-]? digits )?
//             with a decimal exponent of at most 4096 in absolute value (larger ones would
//             make huge numbers; no double needs one)
// OBJ: one statement per line; "v X Y Z" (exactly three numbers), "f c1 c2 c3 ..." with
//   corners "i", "i/t", "i/t/n" or "i//n" (1-based, negative = relative to the vertices
//   defined so far); '#' starts a comment; vt, vn, vp, g, o, s, usemtl, mtllib are
//   ignored; any other statement is refused.
// OFF: the line "OFF" (the counts may follow on the same line), the line "#V #F #E", #V
//   lines "X Y Z", #F lines "n i1 ... in" (0-based), then nothing but blank lines and
//   comments; '#' starts a comment. Other OFF variants (COFF, NOFF, binary, ...) are
//   refused.
// A mesh without faces is returned as it is (write_mesh writes empty meshes too).
//
// Throws InputError (input_error.h) naming the file and the line: a missing or unreadable
// file (unreadable_file), another extension (unknown_format), another OFF variant
// (unsupported_variant), a malformed number, line or count (malformed), an index out of
// range (index_out_of_range), a face with fewer than 3 corners (too_few_corners), more than
// INT_MAX vertices or triangles (too_large). Never crashes on any input.
//
// Exact: no rounding anywhere. Cost: linear in the file size (plus the rational
// arithmetic of the decimal exponents).
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
