// arrangements/src/io/mesh_format.h (internal to the mesh readers, writers and tools)
//
// The mesh file formats, and the one place where a path's extension picks one of them.
//   MeshFormat        obj, off, stl, ply
//   extension(f)      ".obj", ".off", ".stl", ".ply"
//   kLoadFormats      what load_triangle_soup reads (all four)
//   kWriteFormats     what write_mesh writes (.obj .off .ply)
//   kExactFormats     what read_exact_mesh reads (.obj .off)
//   format_of(path, formats)              the format among `formats` that the extension of
//                                         path names, in any case; nullopt if none
//   format_of_or_refuse(path, formats, lead)
//                                         the same, or InputError (unknown_format):
//       "PATH: unknown file extension '.EXT' (LEAD .A .B, any case)" (EXT in lower case),
//       "PATH: no file extension (LEAD .A .B, any case)"
//   where .A .B are the extensions of `formats`, in their order (extension_list).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace arrangements::detail {

enum class MeshFormat { obj, off, stl, ply };

inline constexpr std::array kLoadFormats = {MeshFormat::obj, MeshFormat::off, MeshFormat::stl, MeshFormat::ply};
inline constexpr std::array kWriteFormats = {MeshFormat::obj, MeshFormat::off, MeshFormat::ply};
inline constexpr std::array kExactFormats = {MeshFormat::obj, MeshFormat::off};

// The format's file extension: lower case, with its dot.
const char* extension(MeshFormat format) noexcept;

// The extensions of `formats`, separated by one space (".obj .off .ply").
std::string extension_list(std::span<const MeshFormat> formats);

std::optional<MeshFormat> format_of(const std::string& path, std::span<const MeshFormat> formats);

MeshFormat format_of_or_refuse(const std::string& path, std::span<const MeshFormat> formats, std::string_view lead);

}  // namespace arrangements::detail
