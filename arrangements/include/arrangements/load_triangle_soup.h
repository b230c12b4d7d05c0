// arrangements/load_triangle_soup.h
//
// Stage 1 of the pipeline: read a polygon soup from a mesh file into a TriangleSoup.
//
// TriangleSoup load_triangle_soup(path, label = 0)
//   path   an .obj, .off, .stl or .ply file (the extension decides the format, in any case)
//   label  the label every triangle of this file carries
// returns
//   vertices    #V the file's vertices in file order, unmerged (STL: CGAL's reader keeps
//               one vertex per distinct corner position)
//   triangles   #F the faces, polygons fan-triangulated (below), in file order
//   labels      #F all 0, label_sets = {{label}}
//   source      #F 0, 1, ..., #F-1: the triangle's index in the file's fan-triangle list
//
// TriangleSoup load_triangle_soups(paths)
//   File i is loaded with label i; the soups are concatenated in order (vertex indices are
//   offset; `source` continues across files, so it indexes the concatenated fan-triangle
//   lists); label_sets = {{0}, {1}, ...}, labels[t] = the index of t's file. No paths:
//   an empty soup.
//
// Polygons: a face with corners c0 c1 ... c(n-1), n > 3, becomes the fan from its first
// corner, (c0, c_i, c_(i+1)) for i = 1 .. n-2, in that order. This is exact (no new
// points) and keeps the polygon's orientation, but for a non-convex or non-planar polygon
// the fan triangles may overlap or fold; the pipeline then treats them like any other
// triangles. Faces with repeated corners are kept (preprocess removes degenerate triangles).
//
// Formats: read by CGAL's polygon-soup readers (CGAL::IO::read_OBJ, read_OFF, read_PLY;
// STL through the two halves of read_STL, parse_ASCII_STL / parse_binary_STL). Because
// those readers crash, loop or silently misread on some bad input, every file is first
// checked by a small validator of our own (which also finds line numbers for the
// messages), and the readers' output is checked again afterwards:
//   Numbers in text files are decimal (what C++ streams read as one whole token); values
//   that underflow become subnormal or zero, as the streams make them.
//   OBJ  v / f statements (f corners i, i/t, i/t/n, i//n; negative = relative); vt, vn,
//        comments and the statements CGAL accepts (g, o, s, usemtl, ...) are ignored.
//        Index 0, an index beyond the vertices (positive: of the file; negative: defined
//        so far) and statements CGAL does not accept (e.g. l) are refused.
//   OFF  ASCII OFF, COFF, NOFF, CNOFF with "V F E" on one line; COFF colours as 3 or 4
//        numbers in [0, 255] (or [0, 1]), and once a vertex (face) line has colours all
//        later vertex (face) lines need them too (CGAL reads them from then on).
//        Binary OFF and the ST / 4 / n / SKEL variants are refused as unsupported.
//   STL  binary when the size is exactly 84 + 50 x (the header's triangle count), else
//        ASCII when it begins with "solid" and has no NUL byte, else refused (truncated
//        or malformed).
//   PLY  ascii, binary_little_endian, binary_big_endian; element vertex with float or
//        double x, y, z; element face with a list vertex_indices (or vertex_index) of
//        int or uint. Other elements and properties are skipped.
//
// Throws InputError (input_error.h), naming the file and, where the format has them, the
// line (text formats) or vertex / face / triangle number, for: a missing or unreadable
// file, an unknown extension, a malformed or truncated file, NaN or infinite coordinates
// (also decimals beyond the double range), out-of-range indices, faces with fewer than 3
// corners, a file without faces, and more than INT_MAX vertices or triangles. Never
// crashes and throws nothing else (except std::bad_alloc when memory runs out).
//
// Cost: linear in the file size; the text formats are scanned twice (validator, reader).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arrangements/input_error.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

TriangleSoup load_triangle_soup(const std::string& path, std::uint32_t label = 0);

TriangleSoup load_triangle_soups(const std::vector<std::string>& paths);

}  // namespace arrangements
