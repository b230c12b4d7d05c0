// The one extension -> format dispatch (see mesh_format.h).
#include "io/mesh_format.h"

#include <cctype>
#include <filesystem>

#include "io/mesh_file_checks.h"

namespace arrangements::detail {
namespace {

// The extension of path in lower case, with its dot ("" if none).
std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

const char* extension(MeshFormat format) noexcept {
  switch (format) {
    case MeshFormat::obj:
      return ".obj";
    case MeshFormat::off:
      return ".off";
    case MeshFormat::stl:
      return ".stl";
    case MeshFormat::ply:
      return ".ply";
  }
  return "";
}

std::string extension_list(std::span<const MeshFormat> formats) {
  std::string list;
  for (MeshFormat f : formats) {
    if (!list.empty()) list += ' ';
    list += extension(f);
  }
  return list;
}

std::optional<MeshFormat> format_of(const std::string& path, std::span<const MeshFormat> formats) {
  const std::string ext = lowercase_extension(path);
  for (MeshFormat f : formats)
    if (ext == extension(f)) return f;
  return std::nullopt;
}

MeshFormat format_of_or_refuse(const std::string& path, std::span<const MeshFormat> formats, std::string_view lead) {
  if (const std::optional<MeshFormat> f = format_of(path, formats)) return *f;
  const std::string ext = lowercase_extension(path);
  refuse(InputErrorKind::unknown_format, path,
         (ext.empty() ? std::string("no file extension") : "unknown file extension '" + ext + "'") + " (" +
             std::string(lead) + " " + extension_list(formats) + ", any case)");
}

}  // namespace arrangements::detail
