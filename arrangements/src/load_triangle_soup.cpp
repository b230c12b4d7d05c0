// Stage 1: mesh file -> TriangleSoup (see load_triangle_soup.h).
#include "arrangements/load_triangle_soup.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "mesh_file_checks.h"

namespace arrangements {

const char* to_string(InputErrorKind kind) noexcept {
  switch (kind) {
    case InputErrorKind::unreadable_file: return "unreadable_file";
    case InputErrorKind::unknown_format: return "unknown_format";
    case InputErrorKind::unsupported_variant: return "unsupported_variant";
    case InputErrorKind::malformed: return "malformed";
    case InputErrorKind::non_finite_coordinate: return "non_finite_coordinate";
    case InputErrorKind::index_out_of_range: return "index_out_of_range";
    case InputErrorKind::too_few_corners: return "too_few_corners";
    case InputErrorKind::empty_mesh: return "empty_mesh";
    case InputErrorKind::too_large: return "too_large";
    case InputErrorKind::unscalable: return "unscalable";
  }
  return "unknown";
}

namespace {

using detail::lowercase_extension;
using detail::read_whole_file;
using detail::refuse;
using CgalPoint = CGAL::Simple_cartesian<double>::Point_3;  // what CGAL's readers fill
using Polygon = std::vector<std::size_t>;

enum class Format { obj, off, stl, ply };

Format format_of(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext == ".obj") return Format::obj;
  if (ext == ".off") return Format::off;
  if (ext == ".stl") return Format::stl;
  if (ext == ".ply") return Format::ply;
  refuse(InputErrorKind::unknown_format, path,
         (ext.empty() ? std::string("no file extension") : "unknown file extension '" + ext + "'") +
             " (supported: .obj .off .stl .ply, any case)");
}

void refuse_if_no_faces(const std::string& path, const detail::FileCounts& expected) {
  if (expected.faces == 0) refuse(InputErrorKind::empty_mesh, path, "the mesh has no faces");
}

// Calls one of CGAL's readers; its failure after our validation is still refused cleanly.
template <class Read>
void run_cgal_reader(const std::string& path, const char* format_name, Read read) {
  bool ok = false;
  try {
    ok = read();
  } catch (const CGAL::Failure_exception& e) {
    refuse(InputErrorKind::malformed, path, std::string("CGAL's ") + format_name + " reader failed: " + e.what());
  }
  if (!ok) refuse(InputErrorKind::malformed, path, std::string("CGAL's ") + format_name + " reader refused the file");
}

void read_with_cgal(const std::string& path, Format format, std::string bytes, std::vector<CgalPoint>& points,
                    std::vector<Polygon>& polygons, detail::FileCounts& expected) {
  switch (format) {
    case Format::obj: {
      expected = detail::check_obj_file(path, bytes);
      refuse_if_no_faces(path, expected);
      // CGAL skips from one face corner to the next at a ' ', not at a tab.
      std::replace(bytes.begin(), bytes.end(), '\t', ' ');
      std::istringstream in(std::move(bytes));
      run_cgal_reader(path, "OBJ", [&] { return CGAL::IO::read_OBJ(in, points, polygons); });
      break;
    }
    case Format::off: {
      expected = detail::check_off_file(path, bytes);
      refuse_if_no_faces(path, expected);
      std::istringstream in(std::move(bytes));
      run_cgal_reader(path, "OFF", [&] { return CGAL::IO::read_OFF(in, points, polygons); });
      break;
    }
    case Format::ply: {
      expected = detail::check_ply_file(path, bytes);
      refuse_if_no_faces(path, expected);
      std::istringstream in(std::move(bytes), std::ios::in | std::ios::binary);
      CGAL::IO::set_mode(in, CGAL::IO::BINARY);
      run_cgal_reader(path, "PLY", [&] { return CGAL::IO::read_PLY(in, points, polygons); });
      break;
    }
    case Format::stl: {
      const detail::StlEncoding encoding = detail::stl_encoding(path, bytes);
      expected = detail::check_stl_file(path, bytes, encoding);
      refuse_if_no_faces(path, expected);
      std::istringstream in(std::move(bytes), std::ios::in | std::ios::binary);
      // The two halves of CGAL::IO::read_STL, called directly: see check_stl_file.cpp.
      if (encoding == detail::StlEncoding::binary) {
        CGAL::IO::set_mode(in, CGAL::IO::BINARY);
        run_cgal_reader(path, "binary STL",
                        [&] { return CGAL::IO::internal::parse_binary_STL(in, points, polygons); });
      } else {
        run_cgal_reader(path, "ASCII STL", [&] { return CGAL::IO::internal::parse_ASCII_STL(in, points, polygons); });
      }
      expected.vertices = points.size();  // CGAL merges equal STL corners: no count to compare
      break;
    }
  }
}

// The checks that do not trust the validators: what goes into the soup is valid.
void check_soup(const std::string& path, const std::vector<CgalPoint>& points, const std::vector<Polygon>& polygons,
                const detail::FileCounts& expected) {
  std::size_t corners = 0;
  for (const Polygon& p : polygons) corners += p.size();
  if (points.size() != expected.vertices || polygons.size() != expected.faces || corners != expected.corners)
    refuse(InputErrorKind::malformed, path,
           "CGAL's reader read " + std::to_string(points.size()) + " vertices, " + std::to_string(polygons.size()) +
               " faces, " + std::to_string(corners) + " face corners; the file has " +
               std::to_string(expected.vertices) + ", " + std::to_string(expected.faces) + ", " +
               std::to_string(expected.corners));
  if (polygons.empty()) refuse(InputErrorKind::empty_mesh, path, "the mesh has no faces");
  if (points.size() > detail::kMaxIndexCount)
    refuse(InputErrorKind::too_large, path, std::to_string(points.size()) + " vertices (at most " +
                                                std::to_string(detail::kMaxIndexCount) + " are supported)");
  for (std::size_t v = 0; v < points.size(); ++v)
    if (!std::isfinite(points[v].x()) || !std::isfinite(points[v].y()) || !std::isfinite(points[v].z()))
      refuse(InputErrorKind::non_finite_coordinate, path, "vertex " + std::to_string(v + 1) + " is not finite");
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() < 3)
      refuse(InputErrorKind::too_few_corners, path, "face " + std::to_string(f + 1) + " has " +
                                                        std::to_string(polygons[f].size()) + " corners");
    for (std::size_t v : polygons[f])
      if (v >= points.size())
        refuse(InputErrorKind::index_out_of_range, path,
               "face " + std::to_string(f + 1) + ": vertex index " + std::to_string(v) +
                   " out of range (the file has " + std::to_string(points.size()) + " vertices)");
    triangles += polygons[f].size() - 2;
  }
  if (triangles > detail::kMaxIndexCount)
    refuse(InputErrorKind::too_large, path, std::to_string(triangles) + " triangles (at most " +
                                                std::to_string(detail::kMaxIndexCount) + " are supported)");
}

}  // namespace

TriangleSoup load_triangle_soup(const std::string& path, std::uint32_t label) {
  const Format format = format_of(path);
  std::string bytes = read_whole_file(path);
  if (bytes.empty()) refuse(InputErrorKind::empty_mesh, path, "the file is empty");

  std::vector<CgalPoint> points;
  std::vector<Polygon> polygons;
  detail::FileCounts expected;
  read_with_cgal(path, format, std::move(bytes), points, polygons, expected);
  check_soup(path, points, polygons, expected);

  TriangleSoup soup;
  soup.vertices.reserve(points.size());
  for (const CgalPoint& p : points) soup.vertices.push_back({p.x(), p.y(), p.z()});
  for (const Polygon& p : polygons)
    for (std::size_t i = 1; i + 1 < p.size(); ++i)  // fan from the first corner
      soup.triangles.push_back({static_cast<int>(p[0]), static_cast<int>(p[i]), static_cast<int>(p[i + 1])});
  soup.labels.assign(soup.triangles.size(), 0);
  soup.label_sets = {LabelSet{label}};
  soup.source.resize(soup.triangles.size());
  for (std::size_t t = 0; t < soup.source.size(); ++t) soup.source[t] = static_cast<std::int64_t>(t);
  return soup;
}

TriangleSoup load_triangle_soups(const std::vector<std::string>& paths) {
  TriangleSoup all;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const TriangleSoup one = load_triangle_soup(paths[i], static_cast<std::uint32_t>(i));
    if (all.vertices.size() + one.vertices.size() > detail::kMaxIndexCount ||
        all.triangles.size() + one.triangles.size() > detail::kMaxIndexCount)
      refuse(InputErrorKind::too_large, paths[i], "the input files together have more than " +
                                                      std::to_string(detail::kMaxIndexCount) +
                                                      " vertices or triangles");
    const int offset = static_cast<int>(all.vertices.size());
    const std::int64_t source_offset = static_cast<std::int64_t>(all.triangles.size());
    all.vertices.insert(all.vertices.end(), one.vertices.begin(), one.vertices.end());
    for (std::size_t t = 0; t < one.triangles.size(); ++t) {
      const Tri& tri = one.triangles[t];
      all.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
      all.labels.push_back(static_cast<int>(i));
      all.source.push_back(source_offset + one.source[t]);
    }
    all.label_sets.push_back(LabelSet{static_cast<std::uint32_t>(i)});
  }
  return all;
}

}  // namespace arrangements
