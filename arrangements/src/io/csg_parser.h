// arrangements/src/io/csg_parser.h (internal to load_csg_file)
//
// parse_csg(path): an OpenSCAD CSG file (the subset load_csg.h describes) read into its
// tree and the list of its imports, without loading any mesh.
//   path  the .csg file
// returns CsgProgram
//   tree     the CSG tree; leaf i names imports[i] (label i), in file order
//   imports  one per import() statement, in file order:
//              path       the file's name relative to the .csg file's folder (as written
//                         when absolute); the file exists, is a regular file and has a
//                         mesh extension (.obj .off .stl .ply, any case)
//              line       the statement's line, for messages
//              transform  the composition of the enclosing multmatrix statements (outer
//                         ones applied last), exact; null when it is the identity
// Tree: union() and group() are Union nodes of their children, intersection()
// Intersection, difference() Difference, as written (one child too); multmatrix() is its
// only child, or a Union of its children when it has none or several; the file is its
// only top-level statement, or the Union of them. difference() of nothing is the empty
// Union (no children); intersection() of nothing is refused.
// Throws InputError naming the file and line (load_csg.h lists the cases).
// Cost: one pass over the file as a stream (csg_tokens.h), linear in its size; memory: the
// tree, the imports and the open statements (at most kMaxCsgDepth of them).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "arrangements/boolean.h"
#include "io/csg_transform.h"

namespace arrangements::detail {

inline constexpr std::size_t kMaxCsgDepth = 10000;

struct CsgImport {
  std::string path;
  long line = 0;
  std::shared_ptr<const ExactAffine> transform;
};

struct CsgProgram {
  CsgNode tree;
  std::vector<CsgImport> imports;
};

CsgProgram parse_csg(const std::string& path);

}  // namespace arrangements::detail
