// arrangements/write_mesh.h
//
// Output of the pipeline (after stage 5): write the arrangement (OutputMesh) to a mesh
// file, with its provenance.
//
// write_mesh(path, mesh, options = {})
//   path     where to write; the extension (any case) chooses the format: .obj, .off, .ply
//   mesh     an OutputMesh, an ExactOutputMesh or a RoundedMesh (output_mesh.h; the same
//            files either way; a RoundedMesh's doubles are written as they are)
//   options  exact = false: each coordinate is to_double() of the vertex (the nearest
//            double), printed with 17 significant digits, so that reading it back as a
//            double gives the same double (binary doubles in PLY);
//            exact = true (OBJ and OFF only): the exact rational coordinates (below)
//
// Files
//   OBJ  "v X Y Z" per vertex, then "f a b c" per triangle (1-based indices).
//   OFF  "OFF", then "#V #F 0", then "X Y Z" per vertex, then "3 a b c" per triangle.
//   PLY  binary_little_endian 1.0:
//          element vertex #V: property double x, y, z
//          element face #F:   property list uchar int vertex_indices
//                             property int source (double when some source does not fit
//                               in int; every int64 up to 2^53 is then exact)
//                             property list uint uint labels (the label set)
//        load_triangle_soup reads it back (the extra face properties are skipped).
//   A mesh without triangles gives a file without vertices and faces (an empty .obj),
//   which the loaders read back as an empty mesh.
//   OBJ and OFF carry no provenance; it goes to the side file path + ".provenance.csv":
//        the header line "triangle,source,labels", then per triangle t (in order) the line
//        "t,source[t],l1 l2 ... lk" with label_sets[label_set[t]] space-separated
//        (empty for an empty label set).
//
// Exact coordinates (options.exact): each coordinate X is the rational number (to_exact()
// of an implicit point)
// written in lowest terms as "N/D" (N, D decimal integers, N with a '-' when negative,
// D >= 1) or as "N" when it is an integer that is exactly a double (a larger integer keeps
// "/1": the loaders read a decimal as its nearest double). Explicit vertices are written the same
// way (a double is the dyadic rational it holds, e.g. 0.1 is
// 3602879701896397/36028797018963968). read_exact_mesh (read_exact_mesh.h) reads these
// files back exactly, and so does load_mesh_files (load_triangle_soup.h), into an
// ExactTriangleSoup; load_triangle_soup reads them only when every coordinate is a double.
//
// Atomic: every file is written to a new temporary file in the same folder (a short name
// of its own, ".tritri-XXXXXX", so any file name the system takes can be written) and
// renamed into place once complete (not synced to disk: atomic_file.h), the side file just before the
// mesh file. A file replaced keeps its permission bits; a new one has 0666 minus the umask.
// On any failure the temporary files are removed and nothing is left at the final paths by
// this call (an old file there is replaced only on success; if the mesh file's final rename
// fails after its side file was placed, the side file is removed).
//
// Throws, before any file is created:
//   InputError (kind unknown_format)       the extension is not .obj .off .ply
//   InputError (kind unsupported_variant)  options.exact with .ply
//   std::invalid_argument                  an inconsistent mesh (an index out of range, or
//                                          per-triangle arrays of the wrong size); for PLY,
//                                          a source beyond +-2^53 (not exact as a double)
//   std::runtime_error                     a coordinate that overflows double (without
//                                          options.exact), or the path is a folder
// and std::runtime_error naming the path and the system's reason when writing fails
// (missing or unwritable folder, disk full, ...).
//
// Cost: linear in the output size. to_double / to_exact evaluate each implicit vertex
// exactly once (rational arithmetic: by far the dominant cost for LPIs and TPIs). In
// parallel (oneTBB, as many workers as the caller allows): the rounding, and the text's
// lines in chunks, appended in order; the bytes do not depend on the thread count.
#pragma once

#include <string>

#include "arrangements/input_error.h"
#include "arrangements/output_mesh.h"

namespace arrangements {

struct WriteOptions {
  bool exact = false;
};

void write_mesh(const std::string& path, const OutputMesh& mesh, const WriteOptions& options = {});
void write_mesh(const std::string& path, const ExactOutputMesh& mesh, const WriteOptions& options = {});
void write_mesh(const std::string& path, const RoundedMesh& mesh, const WriteOptions& options = {});

}  // namespace arrangements
