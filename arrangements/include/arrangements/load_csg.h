// arrangements/load_csg.h
//
// load_csg_file(path): read a CSG tree over mesh files from an OpenSCAD CSG file (the
// subset below), load its operands and apply its transforms exactly: the input of
// boolean(soup, tree, options) (boolean.h).
//   path  a .csg file
// returns CsgScene
//   tree           the CSG tree; its leaves are the labels 0 .. n-1 of the n import()
//                  statements, numbered in file order (a file imported twice is two operands)
//   soup           every operand, operand i with label i, concatenated as load_mesh_files
//                  (load_triangle_soup.h) concatenates its files (label sets {{0}, {1}, ...},
//                  `source` and `polygon` across the operands) after its transform; a
//                  TriangleSoup when every coordinate, loaded and transformed, is exactly a
//                  double, else an ExactTriangleSoup with every coordinate exactly
//   operand_files  operand i's resolved path: the name in the file, relative to the .csg
//                  file's folder (absolute names as they are)
//
// Grammar (what OpenSCAD writes for meshes; whitespace, newlines, "// ..." and "/* ... */"
// anywhere between tokens):
//   union() { ... }          group() { ... }: the same      difference() { ... }
//   intersection() { ... }
//   multmatrix(m = [[a, b, c, d], [e, f, g, h], [i, j, k, l], [0, 0, 0, 1]]) { ... }
//   import(file = "name.off");    or import("name.off"); any mesh load_mesh_files reads
// A statement with children takes a block { ... }, a single child statement without
// braces (multmatrix(m = ...) import("a.off");), or ';' for none. A ';' after a block (or
// anywhere between statements) is allowed. Arguments may be named or positional: the
// first positional argument is import's file and multmatrix's m; other arguments
// (convexity = 10, $fn = 0, layer = "", origin = [0, 0], ...) are read and ignored, as are
// the arguments of union, group, difference and intersection. Values: numbers
// [+-]? digits [. digits] [e [+-] digits], strings "..." (escapes \" \\ \n \r \t), words
// (true, false, undef) and vectors [v, ...]. Several top-level statements are their union.
// Tree: union/group -> Union, difference -> Difference (the first child minus the others),
// intersection -> Intersection, each with its children as written (also a single child);
// multmatrix is its child (or the Union of its children); an import is a leaf. Empty sets:
// a Union with no children is the empty set: union() {}, group() {}, difference() {}
// (nothing minus nothing) and multmatrix(...) {} become one. intersection() {} has no
// meaning (everything?) and is refused.
//
// Transforms, exact: each matrix entry is the exact rational value of its decimal text
// (0.1 is 1/10, 6.123233995736766e-17 is what it says, not 0); nested multmatrix statements
// compose (the outer applied last); every vertex of an operand is mapped by the composed
// matrix in rational arithmetic. An operand stays in doubles when every mapped coordinate
// is exactly a double (identity, integer translations, scalings by powers of 2, ...);
// otherwise the whole soup becomes exact. A matrix with negative determinant (a mirror)
// also reverses the corner order of every triangle it maps, so an outward-oriented operand
// stays outward. The last row must be exactly 0 0 0 1 (affine maps only), and a matrix of
// determinant 0 is refused. Operand files with exact rational coordinates (what
// `arrange --exact` writes) are read exactly, as load_mesh_files reads them.
//
// Throws InputError (input_error.h); the message names the .csg file and the line,
// "scene.csg: line 12: expected '{', ';' or a statement after union(...), found 'x'":
//   malformed          syntax (an unknown statement, a missing or extra symbol, unbalanced
//                      braces, an unterminated comment or string, a malformed number), a
//                      bad matrix (not 4 x 4 numbers, last row not 0 0 0 1, determinant 0),
//                      intersection() of nothing, import() without a file name
//   unreadable_file    the .csg file cannot be read; an imported file that does not exist
//                      or is not a regular file (the message names its resolved path)
//   unknown_format     an imported file's extension is not .obj .off .stl .ply
//   empty_mesh         no operand: no import() statement in the file (an empty file too)
//   too_large          statements nested more than 10000 deep (or vectors more than 64),
//                      a matrix entry of more than 100000 digits or an exponent beyond 4096,
//                      operands together beyond INT_MAX vertices or triangles
//   non_finite_coordinate  a transformed coordinate beyond the largest finite double
//   and any error of loading an operand, its message prefixed with the .csg file and the
//   import's line ("scene.csg: line 3: import: mesh.off: line 7: ...") and its kind kept.
// Never throws anything else (except std::bad_alloc).
//
// Cost: one streaming pass over the .csg file (linear in its size; memory: the tree and
// the statements open at a time), then load_mesh_files' cost for each operand, plus up to
// 9 rational products per vertex of a transformed operand (none for the identity).
#pragma once

#include <string>
#include <vector>

#include "arrangements/boolean.h"
#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"

namespace arrangements {

struct CsgScene {
  CsgNode tree;
  AnyTriangleSoup soup;
  std::vector<std::string> operand_files;
};

CsgScene load_csg_file(const std::string& path);

}  // namespace arrangements
