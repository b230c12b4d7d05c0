// Validator for PLY files (see mesh_file_checks.h), mirroring CGAL::IO::read_PLY: a header
// of element / property lines, then the elements' items in order (ASCII tokens, or
// little / big endian binary values).
//
// CGAL's reader sizes each list from the count in the file, dereferences a null pointer
// when x, y, z (or a halfedge's source, target) have another type than it expects, loops
// over the declared items of a property-less element, and silently skips properties of
// unknown types (then misreads everything after). So the header is checked, and the body
// walked with every list count bounded by what is left of the file.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_file_checks.h"

namespace arrangements::detail {
namespace {

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<PlyType> ply_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::int8;
  if (name == "uchar" || name == "uint8") return PlyType::uint8;
  if (name == "short" || name == "int16") return PlyType::int16;
  if (name == "ushort" || name == "uint16") return PlyType::uint16;
  if (name == "int" || name == "int32") return PlyType::int32;
  if (name == "uint" || name == "uint32") return PlyType::uint32;
  if (name == "float" || name == "float32") return PlyType::float32;
  if (name == "double" || name == "float64") return PlyType::float64;
  return std::nullopt;
}

std::size_t size_of(PlyType t) {
  switch (t) {
    case PlyType::int8: case PlyType::uint8: return 1;
    case PlyType::int16: case PlyType::uint16: return 2;
    case PlyType::int32: case PlyType::uint32: case PlyType::float32: return 4;
    case PlyType::float64: return 8;
  }
  return 0;
}

const char* type_name(PlyType t) {
  switch (t) {
    case PlyType::int8: return "char";
    case PlyType::uint8: return "uchar";
    case PlyType::int16: return "short";
    case PlyType::uint16: return "ushort";
    case PlyType::int32: return "int";
    case PlyType::uint32: return "uint";
    case PlyType::float32: return "float";
    case PlyType::float64: return "double";
  }
  return "?";
}

bool is_real(PlyType t) { return t == PlyType::float32 || t == PlyType::float64; }

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::uint8;  // lists only
  PlyType type = PlyType::float32;      // the value / list entry type
};

// The role a property plays for CGAL's reader.
enum class Role { other, coordinate, face_indices };

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
  std::vector<Role> roles;
  bool is_vertex() const { return name == "vertex" || name == "vertices"; }
  bool is_face() const { return name == "face" || name == "faces"; }
};

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t body_start = 0;
};

const PlyProperty* find_property(const PlyElement& e, std::string_view name) {
  for (const PlyProperty& p : e.properties)
    if (p.name == name) return &p;
  return nullptr;
}

PlyHeader read_header(const std::string& path, const std::string& bytes) {
  PlyHeader h;
  TextCursor cursor(bytes);
  if (LineTokens(cursor.rest_of_line()).next() != "ply")
    refuse_at_line(InputErrorKind::malformed, path, 1, "not a PLY file (no 'ply')");
  {
    LineTokens tokens(cursor.rest_of_line());
    tokens.next();
    const std::string_view format = tokens.next();
    if (tokens.next().empty())
      refuse_at_line(InputErrorKind::malformed, path, 2, "expected 'format <encoding> <version>'");
    if (format == "ascii") h.format = PlyFormat::ascii;
    else if (format == "binary_little_endian") h.format = PlyFormat::binary_little_endian;
    else if (format == "binary_big_endian") h.format = PlyFormat::binary_big_endian;
    else refuse_at_line(InputErrorKind::malformed, path, 2, "unknown PLY encoding " + quoted(format));
  }
  for (;;) {
    if (cursor.at_end()) refuse(InputErrorKind::malformed, path, "the PLY header has no 'end_header'");
    const long line = cursor.line();
    LineTokens tokens(cursor.rest_of_line());
    const std::string_view keyword = tokens.next();
    if (keyword.empty()) refuse_at_line(InputErrorKind::malformed, path, line, "empty line in the PLY header");
    if (keyword == "end_header") break;
    if (keyword == "element") {
      PlyElement e;
      e.name = std::string(tokens.next());
      if (e.name.empty() || !parse_integer(tokens.next(), e.count))
        refuse_at_line(InputErrorKind::malformed, path, line, "expected 'element <name> <count>'");
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) refuse_at_line(InputErrorKind::malformed, path, line, "property before any element");
      PlyProperty p;
      const std::string_view type = tokens.next();
      std::optional<PlyType> value_type;
      if (type == "list") {
        const std::optional<PlyType> count_type = ply_type(tokens.next());
        value_type = ply_type(tokens.next());
        if (!count_type || is_real(*count_type) || !value_type)
          refuse_at_line(InputErrorKind::malformed, path, line,
                         "expected 'property list <integer type> <type> <name>'");
        p.list = true;
        p.count_type = *count_type;
      } else {
        value_type = ply_type(type);
        if (!value_type) refuse_at_line(InputErrorKind::malformed, path, line, "unknown property type " + quoted(type));
      }
      p.type = *value_type;
      p.name = std::string(tokens.next());
      if (p.name.empty()) refuse_at_line(InputErrorKind::malformed, path, line, "property without a name");
      h.elements.back().properties.push_back(std::move(p));
    }
    // "comment", "obj_info" and unknown keywords: CGAL ignores them.
  }
  h.body_start = cursor.position();
  return h;
}

// Checks what CGAL's reader assumes of the elements it interprets; sets the roles.
void check_elements(const std::string& path, PlyHeader& h) {
  for (PlyElement& e : h.elements) {
    if (e.count > 0 && e.properties.empty())
      refuse(InputErrorKind::malformed, path, "element '" + e.name + "' has items but no properties");
    e.roles.assign(e.properties.size(), Role::other);
    if (e.is_vertex()) {
      for (const char* axis : {"x", "y", "z"}) {
        const PlyProperty* p = find_property(e, axis);
        if (!p || p->list || !is_real(p->type))
          refuse(InputErrorKind::unsupported_variant, path,
                 std::string("element '") + e.name + "' needs a float or double property '" + axis + "'");
        e.roles[p - e.properties.data()] = Role::coordinate;
      }
    } else if (e.is_face()) {
      // CGAL's order of preference; it reads the first match.
      const PlyProperty* chosen = nullptr;
      for (const char* name : {"vertex_indices", "vertex_index"}) {
        const PlyProperty* p = find_property(e, name);
        if (!chosen && p && p->list && (p->type == PlyType::int32 || p->type == PlyType::uint32)) chosen = p;
      }
      if (!chosen)
        refuse(InputErrorKind::unsupported_variant, path,
               "element '" + e.name + "' needs a list property 'vertex_indices' or 'vertex_index' of int or uint");
      e.roles[chosen - e.properties.data()] = Role::face_indices;
    } else if (e.name == "halfedge") {
      for (const char* name : {"source", "target"}) {
        const PlyProperty* p = find_property(e, name);
        if (p && (p->list || p->type != PlyType::uint32))
          refuse(InputErrorKind::unsupported_variant, path, std::string("element 'halfedge': property '") + name +
                                                                "' must be uint (CGAL's reader assumes it)");
      }
    }
  }
}

// Names an item of the body in messages ("vertex 12", "face 3", "element 'x' item 5"),
// built only when a message needs it.
struct ItemName {
  const PlyElement* element = nullptr;
  unsigned long long number = 0;  // 1-based, over all vertex (face) elements for those
  std::string str() const {
    if (element->is_vertex()) return "vertex " + std::to_string(number);
    if (element->is_face()) return "face " + std::to_string(number);
    return "element '" + element->name + "' item " + std::to_string(number);
  }
};

// One value of the body, read as integer or real.
struct Value {
  long long integer = 0;
  double real = 0;
};

class BodyReader {
 public:
  BodyReader(const std::string& path, const std::string& bytes, const PlyHeader& h)
      : path_(path), bytes_(bytes), format_(h.format), pos_(h.body_start), cursor_(bytes, h.body_start) {}

  // Reads one value of type t; `what` names the item for messages.
  Value read(PlyType t, const ItemName& what, const PlyProperty& p, bool is_coordinate) {
    return format_ == PlyFormat::ascii ? read_ascii(t, what, p, is_coordinate) : read_binary(t, what, p, is_coordinate);
  }
  // Bytes left (a bound for list lengths).
  std::size_t remaining_bytes() const {
    return format_ == PlyFormat::ascii ? bytes_.size() - cursor_.position() : bytes_.size() - pos_;
  }
  std::string location(const std::string& what) const {
    return format_ == PlyFormat::ascii ? "line " + std::to_string(cursor_.line()) + ": " + what : what;
  }

 private:
  Value read_binary(PlyType t, const ItemName& what, const PlyProperty& p, bool is_coordinate) {
    const std::size_t n = size_of(t);
    if (bytes_.size() - pos_ < n) refuse(InputErrorKind::malformed, path_, "the file ends inside " + what.str());
    unsigned char b[8];
    for (std::size_t i = 0; i < n; ++i)
      b[i] = static_cast<unsigned char>(bytes_[pos_ + (format_ == PlyFormat::binary_big_endian ? n - 1 - i : i)]);
    pos_ += n;
    std::uint64_t bits = 0;
    for (std::size_t i = n; i-- > 0;) bits = (bits << 8) | b[i];
    Value v;
    switch (t) {
      case PlyType::int8: v.integer = static_cast<std::int8_t>(bits); break;
      case PlyType::uint8: v.integer = static_cast<std::uint8_t>(bits); break;
      case PlyType::int16: v.integer = static_cast<std::int16_t>(bits); break;
      case PlyType::uint16: v.integer = static_cast<std::uint16_t>(bits); break;
      case PlyType::int32: v.integer = static_cast<std::int32_t>(bits); break;
      case PlyType::uint32: v.integer = static_cast<std::uint32_t>(bits); break;
      case PlyType::float32: {
        const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &b32, sizeof f);
        v.real = f;
        break;
      }
      case PlyType::float64: std::memcpy(&v.real, &bits, sizeof v.real); break;
    }
    if (is_coordinate && !std::isfinite(v.real))
      refuse(InputErrorKind::non_finite_coordinate, path_,
             what.str() + ": coordinate '" + p.name + "' is not finite (" + std::to_string(v.real) + ")");
    return v;
  }

  Value read_ascii(PlyType t, const ItemName& what, const PlyProperty& p, bool is_coordinate) {
    const std::string_view token = cursor_.token();
    if (token.empty()) refuse(InputErrorKind::malformed, path_, "the file ends inside " + what.str());
    Value v;
    bool ok = false;
    switch (t) {
      case PlyType::int8: { std::int8_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::uint8: { std::uint8_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::int16: { std::int16_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::uint16: { std::uint16_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::int32: { std::int32_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::uint32: { std::uint32_t x; ok = parse_integer(token, x); v.integer = x; break; }
      case PlyType::float32:
      case PlyType::float64: {
        RealParse r;
        if (t == PlyType::float32) {
          float f = 0;
          r = parse_real(token, f);
          v.real = f;
        } else {
          r = parse_real(token, v.real);
        }
        if (r == RealParse::non_finite)
          refuse_at_line(is_coordinate ? InputErrorKind::non_finite_coordinate : InputErrorKind::malformed, path_,
                         cursor_.line(),
                         what.str() + ": property '" + p.name + "' value " + quoted(token) + " is not a finite " +
                             (t == PlyType::float32 ? "float" : "double"));
        ok = r == RealParse::ok;
        break;
      }
    }
    if (!ok)
      refuse_at_line(InputErrorKind::malformed, path_, cursor_.line(),
                     what.str() + ": property '" + p.name + "' value " + quoted(token) + " is not a valid " +
                         type_name(t));
    return v;
  }

  const std::string& path_;
  const std::string& bytes_;
  PlyFormat format_;
  std::size_t pos_;    // binary
  TextCursor cursor_;  // ascii
};

}  // namespace

FileCounts check_ply_file(const std::string& path, const std::string& bytes) {
  PlyHeader h = read_header(path, bytes);
  check_elements(path, h);
  FileCounts counts;
  // Declared counts may be absurd (the walk below stops at the end of the file): saturate.
  for (const PlyElement& e : h.elements)
    if (e.is_vertex()) counts.vertices = e.count > SIZE_MAX - counts.vertices ? SIZE_MAX : counts.vertices + e.count;
  BodyReader body(path, bytes, h);
  unsigned long long vertex_number = 0;
  for (const PlyElement& e : h.elements) {
    for (unsigned long long item = 0; item < e.count; ++item) {
      const ItemName what{&e, e.is_vertex() ? vertex_number + 1 : e.is_face() ? counts.faces + 1 : item + 1};
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        const Role role = e.roles[k];
        if (!p.list) {
          body.read(p.type, what, p, role == Role::coordinate);
          continue;
        }
        const long long n = body.read(p.count_type, what, p, false).integer;
        // Each entry takes at least one byte, so this bounds the list CGAL allocates.
        if (n < 0 || static_cast<unsigned long long>(n) > body.remaining_bytes())
          refuse(InputErrorKind::malformed, path, body.location(what.str() + ": list length " + std::to_string(n) +
                                                                " is negative or exceeds the rest of the file"));
        if (role == Role::face_indices && n < 3)
          refuse(InputErrorKind::too_few_corners, path,
                 body.location(what.str() + " has " + std::to_string(n) + " corners (at least 3 are needed)"));
        for (long long i = 0; i < n; ++i) {
          const long long index = body.read(p.type, what, p, false).integer;
          if (role == Role::face_indices && (index < 0 || static_cast<unsigned long long>(index) >= counts.vertices))
            refuse(InputErrorKind::index_out_of_range, path,
                   body.location(what.str() + ": vertex index " + std::to_string(index) +
                                 " out of range (the file has " + std::to_string(counts.vertices) + " vertices)"));
        }
        if (role == Role::face_indices) counts.corners += static_cast<std::size_t>(n);
      }
      if (e.is_vertex()) ++vertex_number;
      if (e.is_face()) ++counts.faces;
    }
  }
  if (counts.vertices > kMaxIndexCount || counts.faces > kMaxIndexCount)
    refuse(InputErrorKind::too_large, path, "more than " + std::to_string(kMaxIndexCount) + " vertices or faces");
  return counts;
}

}  // namespace arrangements::detail
