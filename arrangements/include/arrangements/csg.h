// arrangements/csg.h
//
// csg(path, options): the Boolean of an OpenSCAD CSG file: load_csg_file(path) (load_csg.h:
// the tree, its operand files loaded, multmatrix applied exactly), then boolean() on that
// soup (boolean.h). Returns the double path's result (ArrangeResult) when every transformed
// coordinate is a double, else the exact path's (ExactArrangeResult).
// Errors: InputError for the file or an operand file (with the .csg line), OpenOperandError
// for an operand that is not closed (operand = its import's position in the file).
// Exact; cost: loading plus boolean().
#pragma once

#include <string>
#include <variant>

#include "arrangements/arrange.h"

namespace arrangements {

using AnyArrangeResult = std::variant<ArrangeResult, ExactArrangeResult>;

AnyArrangeResult csg(const std::string& path, const ArrangeOptions& options);

}  // namespace arrangements
