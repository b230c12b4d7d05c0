// arrangements/input_error.h
//
// InputError: the exception every pipeline stage throws for input it refuses (a file that
// cannot be read, a malformed or empty mesh, coordinates that are not finite, ...).
//   what()  one line that names the file (when there is one), the place (line, vertex or
//           face number, as far as the format allows) and what is wrong, e.g.
//           "x.obj: line 12: vertex index 57 out of range (the file has 40 vertices)"
//   kind    the reason, for callers that react differently (and for tests and reports)
//
// Programming errors (a TriangleSoup with out-of-range indices passed to a stage) are not
// InputErrors: they throw std::invalid_argument.
#pragma once

#include <stdexcept>
#include <string>

namespace arrangements {

enum class InputErrorKind {
  unreadable_file,        // missing, not a regular file, or cannot be opened / read
  unknown_format,         // the extension is not .obj .off .stl .ply (any case)
  unsupported_variant,    // a valid file in a variant the reader does not handle
  malformed,              // the file does not follow its format
  non_finite_coordinate,  // NaN or infinite coordinate (or a decimal that overflows double, or a
                          // rational N/D beyond the largest finite double)
  index_out_of_range,     // a face refers to a vertex that does not exist
  too_few_corners,        // a face with fewer than 3 corners
  empty_mesh,             // vertices but no faces, or an empty file of a format with a header
  too_large,              // more vertices or triangles than the pipeline's int indices allow
                          // (or a decimal exponent beyond +-4096 where decimals are read
                          // exactly, a CSG matrix entry of more than 100000 digits, a
                          // coplanar cluster beyond arrange()'s budget: arrange.h)
};

// A short stable name for the kind ("non_finite_coordinate", ...).
const char* to_string(InputErrorKind kind) noexcept;

struct InputError : std::runtime_error {
  InputError(InputErrorKind k, const std::string& message) : std::runtime_error(message), kind(k) {}
  InputErrorKind kind;
};

}  // namespace arrangements
