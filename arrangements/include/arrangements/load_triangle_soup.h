// arrangements/load_triangle_soup.h
//
// Input to the pipeline (before stage 1): read a polygon soup from mesh files into a
// TriangleSoup (double coordinates) or, with load_mesh_files, into an ExactTriangleSoup when
// a file has exact rational coordinates (as `arrange --exact` writes them).
//
// TriangleSoup load_triangle_soup(path, label = 0)
//   path   an .obj, .off, .stl or .ply file (the extension decides the format, in any case)
//   label  the label every triangle of this file carries
// returns
//   vertices    #V the file's vertices in file order, unmerged (STL: one vertex per
//               distinct corner position, below)
//   triangles   #F the faces, polygons triangulated (below), in file order
//   label_set   #F all 0, label_sets = {{label}}
//   source      #F 0, 1, ..., #F-1: the triangle's index in the file's triangle list
//   polygon     #F or empty: for the triangles of a polygon face split without overlap,
//               the source index of the face's first triangle; -1 for the others (empty
//               when there is no such face). Provenance: an output triangle's `source`
//               names its input triangle; the face is the one whose n - 2 entries hold it.
//
// TriangleSoup load_triangle_soups(paths)
//   File i is loaded with label i; the soups are concatenated in order (vertex indices are
//   offset; `source` and `polygon` continue across files, so they index the concatenated
//   triangle lists); label_sets = {{0}, {1}, ...}, label_set[t] = the index of t's file. No paths:
//   an empty soup.
//
// AnyTriangleSoup load_mesh_files(paths)
//   The same files, labels, `source`, `polygon` and concatenation as load_triangle_soups,
//   except that in OBJ and OFF files a vertex coordinate may also be an exact rational
//   (below). Returns
//     TriangleSoup       when every coordinate of every file is a double: exactly what
//                        load_triangle_soups(paths) returns (the same readers and speed)
//     ExactTriangleSoup  otherwise: every coordinate of every file exactly (decimals as
//                        their correctly rounded doubles, converted exactly; rationals as
//                        they are), polygons triangulated on the exact coordinates
//   No paths: an empty TriangleSoup.
//
// Rational coordinates (OBJ "v" x y z, OFF vertex x y z; not normals, colours, STL or PLY):
//   a token [+-]? digits "/" digits, e.g. -462951018488861/2305843009213693952 (what
//   write_mesh writes with exact = true), need not be reduced ("2/6" is 1/3). Decimal
//   tokens keep their meaning (the correctly rounded double). A rational that is exactly a
//   double (e.g. "1/4", "6/3") is that double, so such files still give a TriangleSoup; a
//   zero numerator with a '-' ("-0/3") is -0.0, as the decimal "-0" is (exactly: 0).
//   load_triangle_soup and load_triangle_soups read only files whose rationals are all
//   doubles: a rational that is not a double is refused (unsupported_variant, "... the
//   file has exact rational coordinates, which load_mesh_files reads ...").
//   Refused (InputError naming the file and line, for every loader): a zero denominator
//   (malformed, "has a zero denominator"); a token that is neither a decimal nor the
//   rational grammar, e.g. "1/", "/2", "1/2/3", "1.5/2", "0x1/3" (malformed, "is not a
//   number"); a rational whose absolute value exceeds the largest finite double
//   (non_finite_coordinate, "is beyond the largest finite double": the pipeline needs
//   finite bounding boxes). A numerator or denominator may have any number of digits (its
//   value is no larger than the file's text, and costs GMP's subquadratic conversion):
//   what write_mesh writes with exact = true is always read back.
//
// Polygons: a face with corners c0 c1 ... c(n-1), n > 3, becomes the n - 2 triangles of
// triangulate_polygon (arrangements/src/io/triangulate_polygon.h) in place of the face, so every
// face keeps n - 2 consecutive entries of `source`; a triangle is kept as it is. Faces with
// repeated corners are kept (preprocess removes degenerate triangles).
//
// Formats: each file is read once, as a stream (1 MiB at a time), by a reader of our own
// that validates it and fills the arrays in the same pass, so loading needs about the
// memory of the arrays it returns (plus, for polygons, their corner lists until they are
// triangulated at the end of the file, and a buffer of about 3 times the longest line).
// Nothing is reserved from a count in a header beyond what the rest of the file can hold,
// so a file that is not its format is refused after its first bytes (a file of NUL bytes
// at the first one, of any size) in time and memory that do not grow with its size.
//   Text files (OBJ, OFF, ASCII STL, the PLY header and ASCII PLY): lines end in LF, CRLF
//   or CR; a UTF-8 byte order mark (EF BB BF) at the start of the file is skipped. A NUL
//   byte is refused (malformed, "line L: a NUL byte: ...") as soon as it is read. A line
//   is at most 1 MiB (1048576 bytes) long, except OBJ v and f statements, OFF vertex and
//   face records and the lines of an ASCII PLY body, whose exact rationals and polygons
//   have no size limit: those may go on beyond their first MiB with numbers and blanks
//   only (digits, + - . / e E, space, tab). Any other line longer than 1 MiB is refused
//   (malformed, "line L: longer than 1048576 bytes (1 MiB)"), as is a long line with
//   anything else after its first MiB (a comment, a letter); so are OBJ lines joined by
//   backslashes, by the same rule.
//   Numbers are decimal (one optional sign, digits, '.', exponent; "+-1" is refused) and
//   fill their whole whitespace-separated token; they are rounded correctly (std::from_chars); values that
//   underflow become the correctly rounded subnormal or zero (as strtod makes them). OBJ
//   and OFF vertex coordinates may also be rationals (above).
//   OBJ  v / f statements (f corners i, i/t, i/t/n or i//n; negative = relative to the
//        vertices defined so far; positive indices may name vertices defined later in the
//        file); numbers after x y z of a v are ignored; vt, vn, comments and the other
//        geometry and grouping statements (g, o, s, usemtl, mtllib, vp, curv, surf, ...)
//        are ignored. A backslash right before a line's end joins the next line to it
//        ("f 1 2 \" + newline + "3" is one face), except inside a '#' comment.
//        Index 0, an index beyond the vertices (positive: of the file; negative: defined
//        so far) and other statements (e.g. l) are refused.
//   OFF  ASCII OFF, COFF, NOFF, CNOFF with "V F E" on one line; a record is a line with
//        something before its '#' comment; colours (COFF) as 3 or 4 numbers in [0, 255]
//        (or [0, 1]) after a vertex's or face's numbers, and once a vertex (face) line
//        has colours all later vertex (face) lines need them too. Binary OFF and the ST /
//        4 / n / SKEL variants are refused as unsupported.
//   STL  binary when the size is exactly 84 + 50 x (the header's triangle count, checked
//        before anything is reserved), else ASCII when its first word begins with "solid"
//        (any case), no byte is NUL and no line exceeds 1 MiB, else refused ("neither an
//        ASCII STL ... nor a binary STL of the right size: the binary STL size does not
//        match its triangle count ..."; a file of NULs at its first byte). ASCII keywords (solid, facet, vertex,
//        endfacet, endsolid) in any case; the rest of a solid or endsolid line is the
//        solid's name, free text ("solid facet"). Corners at equal positions (exact comparison,
//        -0.0 equals 0.0) become one vertex, in the order of first appearance.
//   PLY  ascii, binary_little_endian, binary_big_endian; element vertex with float or
//        double x, y, z; element face with a list vertex_indices (or vertex_index) of
//        any integer type (char, uchar, short, ushort, int, uint) with any integer count
//        type. Other elements and properties are skipped.
//
// Throws InputError (input_error.h), naming the file and, where the format has them, the
// line (text formats) or vertex / face / triangle number, for: a missing or unreadable
// file, an unknown extension, a malformed or truncated file (a NUL byte or a line too long
// in a text file among them, above), NaN or infinite coordinates
// (also decimals beyond the double range), out-of-range indices, faces with fewer than 3
// corners, a file with vertices but no faces, an empty file of a format with a header (OFF,
// STL, PLY), and more than INT_MAX vertices or triangles. A file with neither vertices nor
// faces (an empty .obj, "OFF 0 0 0", an STL without facets, ...) is a valid empty mesh, as
// write_mesh writes an empty arrangement: no vertices, no triangles, label_sets {{label}}. Tokens in
// messages are quoted as they are, bytes that are not printable ASCII escaped (\xEF).
// Never crashes and throws nothing else (except std::bad_alloc when memory runs out).
// Rational coordinates are refused as listed above.
//
// Cost: one pass over the file, linear in its size. Rational tokens cost GMP's conversion
// of their digits (subquadratic) and an exact comparison; an ExactTriangleSoup costs a rational per
// coordinate (an order of magnitude more memory than a double) and exact polygon
// triangulation.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "arrangements/input_error.h"
#include "arrangements/triangle_soup.h"

namespace arrangements {

TriangleSoup load_triangle_soup(const std::string& path, std::uint32_t label = 0);

TriangleSoup load_triangle_soups(const std::vector<std::string>& paths);

using AnyTriangleSoup = std::variant<TriangleSoup, ExactTriangleSoup>;

AnyTriangleSoup load_mesh_files(const std::vector<std::string>& paths);

}  // namespace arrangements
