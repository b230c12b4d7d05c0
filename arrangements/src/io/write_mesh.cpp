// Output: OutputMesh / ExactOutputMesh -> OBJ / OFF / PLY file and provenance (see write_mesh.h).
#include "arrangements/write_mesh.h"

#include <gmp.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "arrangements/as_input.h"
#include "io/atomic_file.h"
#include "io/mesh_file_checks.h"
#include "io/mesh_format.h"
#include "io/rational_token.h"
#include "io/write_off.h"
#include "support/vertex_coordinates.h"

namespace arrangements {
namespace {

namespace fs = std::filesystem;
using detail::AtomicFile;
using detail::MeshFormat;

template <class Mesh>
void check_mesh(const std::string& path, const Mesh& mesh) {
  const std::size_t nt = mesh.triangles.size();
  if (mesh.source.size() != nt || mesh.label_set.size() != nt)
    throw std::invalid_argument(path + ": OutputMesh has " + std::to_string(nt) + " triangles but " +
                                std::to_string(mesh.source.size()) + " sources and " +
                                std::to_string(mesh.label_set.size()) + " label sets");
  for (std::size_t t = 0; t < nt; ++t) {
    for (int i : mesh.triangles[t])
      if (i < 0 || static_cast<std::size_t>(i) >= mesh.vertices.size())
        throw std::invalid_argument(path + ": OutputMesh triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(i) + " out of range (" + std::to_string(mesh.vertices.size()) +
                                    " vertices)");
    const int s = mesh.label_set[t];
    if (s < 0 || static_cast<std::size_t>(s) >= mesh.label_sets.size())
      throw std::invalid_argument(path + ": OutputMesh triangle " + std::to_string(t) + " has label set " +
                                  std::to_string(s) + " out of range (" + std::to_string(mesh.label_sets.size()) +
                                  " label sets)");
  }
}

// rename() would replace an empty folder by the file: refuse that up front.
void refuse_folder(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw std::runtime_error(path + ": is a folder, cannot write a file there");
}

// ---- text formatting -------------------------------------------------------------------

// A chunk of lines formatted apart from the file (append_lines), with AtomicFile's appends.
struct Text {
  std::string bytes;
  void append(std::string_view v) { bytes.append(v); }
  void append(char c) { bytes.push_back(c); }
};

// Lines 0 .. count-1 of a section: format(i, text) appends line i to a Text. Chunks of
// lines are formatted in parallel (formatting, not writing, is what takes the time: 7.3 M
// triangles and their provenance) and appended to f in order, so the bytes are those of
// one loop; at most two chunks per worker are held at once.
template <class FormatLine>
void append_lines(AtomicFile& f, std::size_t count, const FormatLine& format) {
  constexpr std::size_t kLinesPerChunk = 8192;
  const std::size_t chunks = (count + kLinesPerChunk - 1) / kLinesPerChunk;
  std::size_t next = 0;
  const auto tokens = static_cast<std::size_t>(2 * tbb::this_task_arena::max_concurrency());
  tbb::parallel_pipeline(
      tokens,
      tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                          [&](tbb::flow_control& control) -> std::size_t {
                                            if (next == chunks) control.stop();
                                            return next++;
                                          }) &
          tbb::make_filter<std::size_t, Text>(tbb::filter_mode::parallel,
                                              [&](std::size_t chunk) {
                                                Text text;
                                                text.bytes.reserve(64 * kLinesPerChunk);
                                                const std::size_t end =
                                                    std::min(count, (chunk + 1) * kLinesPerChunk);
                                                for (std::size_t i = chunk * kLinesPerChunk; i < end; ++i)
                                                  format(i, text);
                                                return text;
                                              }) &
          tbb::make_filter<Text, void>(tbb::filter_mode::serial_in_order,
                                       [&](const Text& text) { f.append(text.bytes); }));
}

template <class Out, class Int>
void append_integer(Out& f, Int v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  f.append(std::string_view(buf, r.ptr - buf));
}

// 17 significant digits: enough for every double to read back as itself.
template <class Out>
void append_double(Out& f, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  f.append(std::string_view(buf, r.ptr - buf));
}

void append_mpz(Text& f, const mpz_t z, std::string& scratch) {
  scratch.resize(mpz_sizeinbase(z, 10) + 2);  // digits (may be one too many), sign, NUL
  mpz_get_str(scratch.data(), 10, z);
  f.append(std::string_view(scratch.c_str()));
}

// Gmpq is always in lowest terms with a positive denominator. An integer that is not a
// double keeps its "/1": the loaders read a decimal "N" as the double nearest to it.
void append_rational(Text& f, const CGAL::Gmpq& q, std::string& scratch) {
  append_mpz(f, mpq_numref(q.mpq()), scratch);
  double unused;
  if (mpz_cmp_ui(mpq_denref(q.mpq()), 1) != 0 || !detail::exact_double(q, unused)) {
    f.append('/');
    append_mpz(f, mpq_denref(q.mpq()), scratch);
  }
}

// The vertex coordinates as doubles (correctly rounded), refusing those that overflow.
template <class Mesh>
std::vector<Vec3> rounded_vertices(const std::string& path, const Mesh& mesh) {
  // In parallel: implicit points that the filter cannot round take exact arithmetic.
  std::vector<Vec3> out(mesh.vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), 256), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) out[v] = nearest_double(mesh.vertices[v]);
  });
  for (std::size_t v = 0; v < out.size(); ++v)
    for (double c : out[v])
      if (!std::isfinite(c))
        throw std::runtime_error(path + ": vertex " + std::to_string(v) +
                                 " has a coordinate beyond the double range (write it with exact coordinates)");
  return out;
}

// "X Y Z": 17 significant digits each.
void append_coordinates(Text& f, const Vec3& v) {
  for (int k = 0; k < 3; ++k) {
    if (k) f.append(' ');
    append_double(f, v[k]);
  }
}

// "X Y Z" of vertex i: exact rationals, or the rounded doubles.
template <class Mesh>
void append_coordinates(Text& f, const Mesh& mesh, const std::vector<Vec3>& rounded, bool exact, std::size_t i,
                        std::string& scratch) {
  if (!exact) {
    append_coordinates(f, rounded[i]);
    return;
  }
  const std::array<CGAL::Gmpq, 3> q = exact_coordinates(mesh.vertices[i]);
  for (int k = 0; k < 3; ++k) {
    if (k) f.append(' ');
    append_rational(f, q[k], scratch);
  }
}

// One line per triangle: `lead`, then its three vertex indices plus `base` (OBJ counts
// from 1, OFF from 0).
void append_triangle_lines(AtomicFile& f, const std::vector<Tri>& triangles, char lead, long long base) {
  append_lines(f, triangles.size(), [&](std::size_t t, Text& text) {
    text.append(lead);
    for (int i : triangles[t]) {
      text.append(' ');
      append_integer(text, i + base);
    }
    text.append('\n');
  });
}

template <class Mesh>
void write_obj(AtomicFile& f, const Mesh& mesh, const std::vector<Vec3>& rounded, bool exact) {
  append_lines(f, mesh.vertices.size(), [&](std::size_t i, Text& text) {
    thread_local std::string scratch;
    text.append("v ");
    append_coordinates(text, mesh, rounded, exact, i, scratch);
    text.append('\n');
  });
  append_triangle_lines(f, mesh.triangles, 'f', 1);
}

// The one OFF writer (write_mesh and write_off): "OFF", "#V #F 0", one line per vertex
// (append_vertex(i, text) writes its coordinates), then "3 a b c" per triangle.
template <class AppendVertex>
void write_off_text(AtomicFile& f, std::size_t vertex_count, const std::vector<Tri>& triangles,
                    const AppendVertex& append_vertex) {
  f.append("OFF\n");
  append_integer(f, vertex_count);
  f.append(' ');
  append_integer(f, triangles.size());
  f.append(" 0\n");
  append_lines(f, vertex_count, [&](std::size_t i, Text& text) {
    append_vertex(i, text);
    text.append('\n');
  });
  append_triangle_lines(f, triangles, '3', 0);
}

template <class Mesh>
void write_off(AtomicFile& f, const Mesh& mesh, const std::vector<Vec3>& rounded, bool exact) {
  write_off_text(f, mesh.vertices.size(), mesh.triangles, [&](std::size_t i, Text& text) {
    thread_local std::string scratch;
    append_coordinates(text, mesh, rounded, exact, i, scratch);
  });
}

template <class Mesh>
void write_provenance(AtomicFile& f, const Mesh& mesh) {
  f.append("triangle,source,labels\n");
  append_lines(f, mesh.triangles.size(), [&](std::size_t t, Text& text) {
    append_integer(text, t);
    text.append(',');
    append_integer(text, mesh.source[t]);
    text.append(',');
    const LabelSet& labels = mesh.label_sets[mesh.label_set[t]];
    for (std::size_t k = 0; k < labels.size(); ++k) {
      if (k) text.append(' ');
      append_integer(text, labels[k]);
    }
    text.append('\n');
  });
}

// ---- binary PLY ------------------------------------------------------------------------

// Little endian whatever the host's byte order.
void append_le(AtomicFile& f, std::uint64_t bits, int bytes) {
  char b[8];
  for (int i = 0; i < bytes; ++i) b[i] = static_cast<char>((bits >> (8 * i)) & 0xff);
  f.append(std::string_view(b, bytes));
}
void append_le_double(AtomicFile& f, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  append_le(f, bits, 8);
}
void append_le_int32(AtomicFile& f, std::int32_t v) { append_le(f, static_cast<std::uint32_t>(v), 4); }

template <class Mesh>
bool sources_fit_int(const Mesh& mesh) {
  for (std::int64_t s : mesh.source)
    if (s < std::numeric_limits<std::int32_t>::min() || s > std::numeric_limits<std::int32_t>::max()) return false;
  return true;
}

template <class Mesh>
void check_ply_limits(const std::string& path, const Mesh& mesh) {
  constexpr std::int64_t kExactInDouble = std::int64_t{1} << 53;
  for (std::size_t t = 0; t < mesh.source.size(); ++t)
    if (mesh.source[t] > kExactInDouble || mesh.source[t] < -kExactInDouble)
      throw std::invalid_argument(path + ": triangle " + std::to_string(t) + " has source " +
                                  std::to_string(mesh.source[t]) + ", which PLY (int or double) cannot hold exactly");
  for (const LabelSet& s : mesh.label_sets)
    if (s.size() > std::numeric_limits<std::uint32_t>::max())
      throw std::invalid_argument(path + ": a label set has more than 2^32 - 1 labels");
}

template <class Mesh>
void write_ply(AtomicFile& f, const Mesh& mesh, const std::vector<Vec3>& rounded) {
  const bool int_source = sources_fit_int(mesh);
  f.append("ply\nformat binary_little_endian 1.0\n");
  f.append("comment source: the input triangle each face lies in; labels: its label set\n");
  f.append("element vertex ");
  append_integer(f, mesh.vertices.size());
  f.append("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  append_integer(f, mesh.triangles.size());
  f.append("\nproperty list uchar int vertex_indices\n");
  f.append(int_source ? "property int source\n" : "property double source\n");
  f.append("property list uint uint labels\nend_header\n");
  for (const Vec3& v : rounded)
    for (double c : v) append_le_double(f, c);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    f.append('\3');
    for (int i : mesh.triangles[t]) append_le_int32(f, i);
    if (int_source)
      append_le_int32(f, static_cast<std::int32_t>(mesh.source[t]));
    else
      append_le_double(f, static_cast<double>(mesh.source[t]));  // exact: |source| <= 2^53 was checked
    const LabelSet& labels = mesh.label_sets[mesh.label_set[t]];
    append_le(f, labels.size(), 4);
    for (std::uint32_t l : labels) append_le(f, l, 4);
  }
}


template <class Mesh>
void write_any_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  // Everything that can be refused is refused before a file is created.
  const MeshFormat format = detail::format_of_or_refuse(path, detail::kWriteFormats, "write_mesh writes");
  if (format == MeshFormat::ply && options.exact)
    detail::refuse(InputErrorKind::unsupported_variant, path,
                   "exact coordinates are written only to .obj and .off (PLY holds doubles)");
  check_mesh(path, mesh);
  if (format == MeshFormat::ply) check_ply_limits(path, mesh);
  const std::string side_path = path + ".provenance.csv";
  const bool has_side_file = format != MeshFormat::ply;
  refuse_folder(path);
  if (has_side_file) refuse_folder(side_path);
  const std::vector<Vec3> rounded = options.exact ? std::vector<Vec3>{} : rounded_vertices(path, mesh);

  AtomicFile file(path);
  switch (format) {
    case MeshFormat::obj:
      write_obj(file, mesh, rounded, options.exact);
      break;
    case MeshFormat::off:
      write_off(file, mesh, rounded, options.exact);
      break;
    case MeshFormat::ply:
      write_ply(file, mesh, rounded);
      break;
    case MeshFormat::stl:
      throw std::logic_error("write_mesh: .stl is not in kWriteFormats");
  }
  file.finish();
  std::optional<AtomicFile> side;
  if (has_side_file) {
    side.emplace(side_path);
    write_provenance(*side, mesh);
    side->finish();
    side->commit();
  }
  try {
    file.commit();
  } catch (...) {
    // The mesh file was not placed: its new side file must not stay alone.
    if (side) ::unlink(side_path.c_str());
    throw;
  }
}

}  // namespace

void write_mesh(const std::string& path, const OutputMesh& mesh, const WriteOptions& options) {
  write_any_mesh(path, mesh, options);
}

void write_mesh(const std::string& path, const ExactOutputMesh& mesh, const WriteOptions& options) {
  write_any_mesh(path, mesh, options);
}

void write_mesh(const std::string& path, const RoundedMesh& mesh, const WriteOptions& options) {
  write_any_mesh(path, mesh, options);
}

void write_off(const std::string& path, const std::vector<Vec3>& V, const std::vector<Tri>& F) {
  AtomicFile file(path);
  write_off_text(file, V.size(), F, [&](std::size_t i, Text& text) { append_coordinates(text, V[i]); });
  file.finish();
  file.commit();
}

}  // namespace arrangements
