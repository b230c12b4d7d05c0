// Load (before stage 1): mesh file -> TriangleSoup or ExactTriangleSoup (see
// load_triangle_soup.h): the file is read once, as a stream, by the reader of its format
// (read_obj.cpp, read_off.cpp, read_stl.cpp, read_ply.cpp), which validates it and fills a
// SoupBuilder (soup_builder.cpp) in the same pass. Here too: FileBytes and the slow paths
// of LineReader (mesh_reader.h).
#include "arrangements/load_triangle_soup.h"

#include "arrangements/as_input.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "io/load_mesh_file.h"
#include "io/mesh_format.h"
#include "io/mesh_reader.h"

namespace arrangements {

const char* to_string(InputErrorKind kind) noexcept {
  switch (kind) {
    case InputErrorKind::unreadable_file:
      return "unreadable_file";
    case InputErrorKind::unknown_format:
      return "unknown_format";
    case InputErrorKind::unsupported_variant:
      return "unsupported_variant";
    case InputErrorKind::malformed:
      return "malformed";
    case InputErrorKind::non_finite_coordinate:
      return "non_finite_coordinate";
    case InputErrorKind::index_out_of_range:
      return "index_out_of_range";
    case InputErrorKind::too_few_corners:
      return "too_few_corners";
    case InputErrorKind::empty_mesh:
      return "empty_mesh";
    case InputErrorKind::too_large:
      return "too_large";
  }
  return "unknown";
}

namespace detail {

FileBytes::FileBytes(const std::string& path) : path_(path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) refuse(InputErrorKind::unreadable_file, path, "no such file");
  if (!std::filesystem::is_regular_file(status)) refuse(InputErrorKind::unreadable_file, path, "not a regular file");
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_)
    refuse(InputErrorKind::unreadable_file, path, std::string("cannot open the file: ") + std::strerror(errno));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  size_ = ec ? 0 : static_cast<std::uint64_t>(size);
  // 1 MiB at a time, or the whole file when it is smaller (a small file need not touch
  // a MiB of zeroed pages: most of a tiny load's time, measured by the fuzzers).
  constexpr std::uint64_t kChunk = std::uint64_t{1} << 20;
  buffer_.resize(static_cast<std::size_t>(size_ > 0 && size_ < kChunk ? size_ + 1 : kChunk));
}

FileBytes::~FileBytes() {
  if (file_) std::fclose(file_);
}

std::size_t FileBytes::refill(std::size_t n) {
  if (pos_ > 0) {  // keep the unconsumed bytes, at the front
    std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
  }
  if (n > buffer_.size()) buffer_.resize(std::max(n, 2 * buffer_.size()));
  while (end_ < n && !eof_) {
    const std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_);
    end_ += got;
    if (got == 0) {
      if (std::ferror(file_)) refuse(InputErrorKind::unreadable_file, path_, "read error");
      eof_ = true;
    }
  }
  return end_;
}

// Past the first kMaxLineBytes of a line (i >= kMaxLineBytes): allowed by the reader's rule
// (asked once, at the first byte beyond them), then numbers and blanks only.
std::size_t LineReader::find_long_line_end(const char* p, std::size_t i, std::size_t n) const {
  for (; i < n; ++i) {
    const char c = p[i];
    if (is_line_end(c)) return i;
    if (i == kMaxLineBytes && !(long_lines_ && long_lines_(std::string_view(p, kMaxLineBytes))))
      refuse_not_text("longer than " + std::to_string(kMaxLineBytes) + " bytes (1 MiB)");
    if (!is_number_or_blank(c))
      refuse_not_text(c == '\0' ? std::string("a NUL byte")
                                : "longer than " + std::to_string(kMaxLineBytes) + " bytes (1 MiB) with " +
                                      quoted(std::string_view(&p[i], 1)) +
                                      " after them (only numbers and blanks may follow)");
  }
  return n;
}

void LineReader::refuse_not_text(const std::string& problem) const {
  refuse_at_line(InputErrorKind::malformed, in_.path(), line_ + 1, problem + ": " + not_text_);
}

}  // namespace detail

using detail::MeshFormat;
using detail::refuse;

namespace {

template <class Coordinates>
BasicTriangleSoup<Coordinates> soup_of(std::vector<Coordinates>&& vertices, detail::SoupBuilder& builder,
                                       std::uint32_t label) {
  BasicTriangleSoup<Coordinates> soup;
  soup.vertices = std::move(vertices);
  soup.triangles = std::move(builder.triangles);
  soup.label_set.assign(soup.triangles.size(), 0);
  soup.label_sets = {LabelSet{label}};
  soup.source.resize(soup.triangles.size());
  for (std::size_t t = 0; t < soup.source.size(); ++t) soup.source[t] = static_cast<std::int64_t>(t);
  soup.polygon = std::move(builder.polygon);
  return soup;
}

// One file; exact: whether rationals that are not doubles are kept (else refused).
AnyTriangleSoup load_file(const std::string& path, std::uint32_t label, bool exact) {
  const MeshFormat format = detail::format_of_or_refuse(path, detail::kLoadFormats, "supported:");
  detail::FileBytes in(path);
  // An empty file is an empty OBJ (what write_mesh writes for an empty mesh); the other
  // formats begin with a header.
  if (format != MeshFormat::obj && in.size() == 0 && in.fill(1) == 0)
    refuse(InputErrorKind::empty_mesh, path, "the file is empty");
  detail::SoupBuilder builder(path, exact);
  switch (format) {
    case MeshFormat::obj:
      detail::read_obj(in, builder);
      break;
    case MeshFormat::off:
      detail::read_off(in, builder);
      break;
    case MeshFormat::stl:
      detail::read_stl(in, builder);
      break;
    case MeshFormat::ply:
      detail::read_ply(in, builder);
      break;
  }
  // Neither vertices nor faces: a valid empty mesh (as write_mesh writes an empty
  // arrangement). Vertices without faces: not a mesh (a point cloud, or lost faces).
  if (builder.triangles.empty() && !builder.vertices.empty())
    refuse(InputErrorKind::empty_mesh, path,
           "the mesh has no faces (" + std::to_string(builder.vertices.size()) + " vertices)");
  builder.finish();
  if (!builder.exact_vertices.empty()) return soup_of(std::move(builder.exact_vertices), builder, label);
  return soup_of(std::move(builder.vertices), builder, label);
}

// Appends file i (`one`, loaded with label i) to `all`: vertex indices, `source` and
// `polygon` offset; one's coordinates converted exactly when all's are rationals.
template <class Coordinates, class OneCoordinates>
void append(BasicTriangleSoup<Coordinates>& all, BasicTriangleSoup<OneCoordinates>&& one, std::size_t i,
            const std::string& path) {
  if (all.vertices.size() + one.vertices.size() > detail::kMaxIndexCount ||
      all.triangles.size() + one.triangles.size() > detail::kMaxIndexCount)
    refuse(
        InputErrorKind::too_large, path,
        "the input files together have more than " + std::to_string(detail::kMaxIndexCount) + " vertices or triangles");
  const int offset = static_cast<int>(all.vertices.size());
  const std::int64_t source_offset = static_cast<std::int64_t>(all.triangles.size());
  if constexpr (std::is_same_v<Coordinates, OneCoordinates>) {
    all.vertices.insert(all.vertices.end(), std::make_move_iterator(one.vertices.begin()),
                        std::make_move_iterator(one.vertices.end()));
  } else {
    for (const Vec3& v : one.vertices) all.vertices.push_back(to_exact(v));
  }
  if (!one.polygon.empty() || !all.polygon.empty()) {  // ids are source indices: offset them too
    all.polygon.resize(all.triangles.size(), -1);
    for (std::size_t t = 0; t < one.triangles.size(); ++t)
      all.polygon.push_back(one.polygon.empty() || one.polygon[t] < 0 ? -1 : source_offset + one.polygon[t]);
  }
  for (std::size_t t = 0; t < one.triangles.size(); ++t) {
    const Tri& tri = one.triangles[t];
    all.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
    all.label_set.push_back(static_cast<int>(i));
    all.source.push_back(source_offset + one.source[t]);
  }
  all.label_sets.push_back(LabelSet{static_cast<std::uint32_t>(i)});
}

}  // namespace

namespace detail {

AnyTriangleSoup load_mesh_file(const std::string& path, std::uint32_t label) { return load_file(path, label, true); }

// Doubles until a file has a coordinate that is not a double, then every coordinate exactly.
void append_mesh_file(AnyTriangleSoup& all, AnyTriangleSoup&& one, std::size_t i, const std::string& path) {
  if (i == 0) {  // labels 0, label_sets {{0}}, source 0..: as they are (no copy)
    all = std::move(one);
    return;
  }
  if (std::holds_alternative<ExactTriangleSoup>(one) && std::holds_alternative<TriangleSoup>(all))
    all = to_exact(std::move(std::get<TriangleSoup>(all)));
  if (ExactTriangleSoup* exact_all = std::get_if<ExactTriangleSoup>(&all))
    std::visit([&](auto& o) { append(*exact_all, std::move(o), i, path); }, one);
  else  // both doubles
    append(std::get<TriangleSoup>(all), std::move(std::get<TriangleSoup>(one)), i, path);
}

}  // namespace detail

namespace {

// The files concatenated (load_triangle_soup.h); exact as for load_file.
AnyTriangleSoup load_files(const std::vector<std::string>& paths, bool exact) {
  AnyTriangleSoup all;
  for (std::size_t i = 0; i < paths.size(); ++i)
    detail::append_mesh_file(all, load_file(paths[i], static_cast<std::uint32_t>(i), exact), i, paths[i]);
  return all;
}

}  // namespace

TriangleSoup load_triangle_soup(const std::string& path, std::uint32_t label) {
  return std::get<TriangleSoup>(load_file(path, label, false));
}

TriangleSoup load_triangle_soups(const std::vector<std::string>& paths) {
  return std::get<TriangleSoup>(load_files(paths, false));
}

AnyTriangleSoup load_mesh_files(const std::vector<std::string>& paths) { return load_files(paths, true); }

}  // namespace arrangements
