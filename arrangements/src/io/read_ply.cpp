// PLY reader (see mesh_reader.h; what it accepts: load_triangle_soup.h): a text header of
// element / property lines, then the elements' items in order (ASCII tokens, or little /
// big endian binary values). Vertices come from the elements "vertex" / "vertices"
// (float or double x, y, z), faces from "face" / "faces" (a list "vertex_indices", else
// "vertex_index", of an integer type); every other element and property is skipped. List
// lengths are bounded by what is left of the file, so a bad count cannot allocate.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_reader.h"

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
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 0;
}

const char* type_name(PlyType t) {
  switch (t) {
    case PlyType::int8:
      return "char";
    case PlyType::uint8:
      return "uchar";
    case PlyType::int16:
      return "short";
    case PlyType::uint16:
      return "ushort";
    case PlyType::int32:
      return "int";
    case PlyType::uint32:
      return "uint";
    case PlyType::float32:
      return "float";
    case PlyType::float64:
      return "double";
  }
  return "?";
}

bool is_real(PlyType t) { return t == PlyType::float32 || t == PlyType::float64; }

// The part a property plays for the loader.
enum class Role { other, x, y, z, face_indices };

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::uint8;  // lists only
  PlyType type = PlyType::float32;      // the value / list entry type
  Role role = Role::other;
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
  bool vertex = false, face = false;  // the name is vertex / vertices, face / faces
  bool is_vertex() const { return vertex; }
  bool is_face() const { return face; }
};

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  unsigned long long vertices = 0;  // over all vertex elements
};

PlyProperty* find_property(PlyElement& e, std::string_view name) {
  for (PlyProperty& p : e.properties)
    if (p.name == name) return &p;
  return nullptr;
}

PlyHeader read_header(const std::string& path, LineReader& lines) {
  PlyHeader h;
  std::string_view line;
  if (!lines.next(line) || LineTokens(line).next() != "ply")
    refuse_at_line(InputErrorKind::malformed, path, 1, "not a PLY file (no 'ply')");
  bool format_seen = false;
  for (;;) {
    if (!lines.next(line)) refuse(InputErrorKind::malformed, path, "the PLY header has no 'end_header'");
    const long number = lines.line_number();
    LineTokens tokens(line);
    const std::string_view keyword = tokens.next();
    if (keyword.empty()) refuse_at_line(InputErrorKind::malformed, path, number, "empty line in the PLY header");
    if (keyword == "end_header") break;
    if (keyword == "format") {
      const std::string_view format = tokens.next();
      if (tokens.next().empty())
        refuse_at_line(InputErrorKind::malformed, path, number, "expected 'format <encoding> <version>'");
      if (format == "ascii")
        h.format = PlyFormat::ascii;
      else if (format == "binary_little_endian")
        h.format = PlyFormat::binary_little_endian;
      else if (format == "binary_big_endian")
        h.format = PlyFormat::binary_big_endian;
      else
        refuse_at_line(InputErrorKind::malformed, path, number, "unknown PLY encoding " + quoted(format));
      format_seen = true;
    } else if (keyword == "element") {
      PlyElement e;
      e.name = std::string(tokens.next());
      if (e.name.empty() || !parse_integer(tokens.next(), e.count))
        refuse_at_line(InputErrorKind::malformed, path, number, "expected 'element <name> <count>'");
      e.vertex = e.name == "vertex" || e.name == "vertices";
      e.face = e.name == "face" || e.name == "faces";
      h.elements.push_back(std::move(e));
    } else if (keyword == "property") {
      if (h.elements.empty()) refuse_at_line(InputErrorKind::malformed, path, number, "property before any element");
      PlyProperty p;
      const std::string_view type = tokens.next();
      std::optional<PlyType> value_type;
      if (type == "list") {
        const std::optional<PlyType> count_type = ply_type(tokens.next());
        value_type = ply_type(tokens.next());
        if (!count_type || is_real(*count_type) || !value_type)
          refuse_at_line(InputErrorKind::malformed, path, number,
                         "expected 'property list <integer type> <type> <name>'");
        p.list = true;
        p.count_type = *count_type;
      } else {
        value_type = ply_type(type);
        if (!value_type)
          refuse_at_line(InputErrorKind::malformed, path, number, "unknown property type " + quoted(type));
      }
      p.type = *value_type;
      p.name = std::string(tokens.next());
      if (p.name.empty()) refuse_at_line(InputErrorKind::malformed, path, number, "property without a name");
      h.elements.back().properties.push_back(std::move(p));
    }
    // "comment", "obj_info" and unknown keywords are ignored.
  }
  if (!format_seen) refuse(InputErrorKind::malformed, path, "the PLY header has no 'format' line");
  return h;
}

// Finds the properties the loader reads and checks their types.
void assign_roles(const std::string& path, PlyHeader& h) {
  unsigned long long faces = 0;
  for (PlyElement& e : h.elements) {
    if (e.count > 0 && e.properties.empty())
      refuse(InputErrorKind::malformed, path, "element '" + e.name + "' has items but no properties");
    if (e.is_vertex()) {
      const Role roles[3] = {Role::x, Role::y, Role::z};
      for (int axis = 0; axis < 3; ++axis) {
        const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
        PlyProperty* p = find_property(e, name);
        if (!p || p->list || !is_real(p->type))
          refuse(InputErrorKind::unsupported_variant, path,
                 "element '" + e.name + "' needs a float or double property '" + name + "'");
        p->role = roles[axis];
      }
      h.vertices += e.count;
      if (e.count > kMaxIndexCount || h.vertices > kMaxIndexCount)
        refuse(InputErrorKind::too_large, path, "more than " + std::to_string(kMaxIndexCount) + " vertices");
    } else if (e.is_face()) {
      PlyProperty* chosen = nullptr;
      for (const char* name : {"vertex_indices", "vertex_index"}) {
        PlyProperty* p = find_property(e, name);
        if (!chosen && p && p->list && !is_real(p->type)) chosen = p;
      }
      if (!chosen)
        refuse(InputErrorKind::unsupported_variant, path,
               "element '" + e.name + "' needs a list property 'vertex_indices' or 'vertex_index' of an integer type");
      chosen->role = Role::face_indices;
      faces += e.count;
      if (e.count > kMaxIndexCount || faces > kMaxIndexCount)
        refuse(InputErrorKind::too_large, path, "more than " + std::to_string(kMaxIndexCount) + " faces");
    }
  }
}

// Names an item of the body in messages ("vertex 12", "face 3", "element 'x' item 5").
struct ItemName {
  const PlyElement* element = nullptr;
  unsigned long long number = 0;  // 1-based, over all vertex (face) elements for those
  std::string str() const {
    if (element->is_vertex()) return "vertex " + std::to_string(number);
    if (element->is_face()) return "face " + std::to_string(number);
    return "element '" + element->name + "' item " + std::to_string(number);
  }
};

// One value of the body, as integer or real.
struct Value {
  long long integer = 0;
  double real = 0;
};

class BodyReader {
 public:
  BodyReader(FileBytes& in, LineReader& lines, PlyFormat format)
      : in_(in), path_(in.path()), format_(format), tokens_(lines) {}

  // Reads one value of type t of property p; `what` names the item for messages.
  Value read(PlyType t, const ItemName& what, const PlyProperty& p) {
    return format_ == PlyFormat::ascii ? read_ascii(t, what, p) : read_binary(t, what, p);
  }
  // Bytes left (a bound for list lengths).
  std::uint64_t remaining_bytes() const {
    return in_.remaining() + (format_ == PlyFormat::ascii ? tokens_.pending() : 0);
  }
  std::string location(const std::string& what) const {
    return format_ == PlyFormat::ascii ? "line " + std::to_string(tokens_.line()) + ": " + what : what;
  }

 private:
  Value read_binary(PlyType t, const ItemName& what, const PlyProperty& p) {
    const std::size_t n = size_of(t);
    if (in_.fill(n) < n) refuse(InputErrorKind::malformed, path_, "the file ends inside " + what.str());
    const unsigned char* b = reinterpret_cast<const unsigned char*>(in_.unread());
    std::uint64_t bits = 0;
    if (format_ == PlyFormat::binary_big_endian)
      for (std::size_t i = 0; i < n; ++i) bits = (bits << 8) | b[i];
    else
      for (std::size_t i = n; i-- > 0;) bits = (bits << 8) | b[i];
    in_.consume(n);
    Value v;
    switch (t) {
      case PlyType::int8:
        v.integer = static_cast<std::int8_t>(bits);
        break;
      case PlyType::uint8:
        v.integer = static_cast<std::uint8_t>(bits);
        break;
      case PlyType::int16:
        v.integer = static_cast<std::int16_t>(bits);
        break;
      case PlyType::uint16:
        v.integer = static_cast<std::uint16_t>(bits);
        break;
      case PlyType::int32:
        v.integer = static_cast<std::int32_t>(bits);
        break;
      case PlyType::uint32:
        v.integer = static_cast<std::uint32_t>(bits);
        break;
      case PlyType::float32: {
        const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &b32, sizeof f);
        v.real = f;
        break;
      }
      case PlyType::float64:
        std::memcpy(&v.real, &bits, sizeof v.real);
        break;
    }
    if (p.role >= Role::x && p.role <= Role::z && !std::isfinite(v.real))
      refuse(InputErrorKind::non_finite_coordinate, path_,
             what.str() + ": coordinate '" + p.name + "' is not finite (" + std::to_string(v.real) + ")");
    return v;
  }

  template <class T>
  bool integer(std::string_view token, Value& v) {
    T x;
    if (!parse_integer(token, x)) return false;
    v.integer = x;
    return true;
  }

  Value read_ascii(PlyType t, const ItemName& what, const PlyProperty& p) {
    const std::string_view token = tokens_.next();
    if (token.empty()) refuse(InputErrorKind::malformed, path_, "the file ends inside " + what.str());
    Value v;
    bool ok = false;
    switch (t) {
      case PlyType::int8:
        ok = integer<std::int8_t>(token, v);
        break;
      case PlyType::uint8:
        ok = integer<std::uint8_t>(token, v);
        break;
      case PlyType::int16:
        ok = integer<std::int16_t>(token, v);
        break;
      case PlyType::uint16:
        ok = integer<std::uint16_t>(token, v);
        break;
      case PlyType::int32:
        ok = integer<std::int32_t>(token, v);
        break;
      case PlyType::uint32:
        ok = integer<std::uint32_t>(token, v);
        break;
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
        // Non-finite values are refused in coordinates only (other properties are skipped).
        if (r == RealParse::non_finite && p.role >= Role::x && p.role <= Role::z)
          refuse_at_line(
              InputErrorKind::non_finite_coordinate, path_, tokens_.line(),
              what.str() + ": property '" + p.name + "' value " + quoted(token) + " is not a finite " + type_name(t));
        ok = r != RealParse::not_a_number;
        break;
      }
    }
    if (!ok)
      refuse_at_line(
          InputErrorKind::malformed, path_, tokens_.line(),
          what.str() + ": property '" + p.name + "' value " + quoted(token) + " is not a valid " + type_name(t));
    return v;
  }

  FileBytes& in_;
  const std::string& path_;
  PlyFormat format_;
  TokenReader tokens_;
};

// The fewest bytes an item of e takes (lists count as their length alone).
std::uint64_t least_item_bytes(const PlyElement& e, PlyFormat format) {
  std::uint64_t n = 0;
  for (const PlyProperty& p : e.properties)
    n += format == PlyFormat::ascii ? 2 : size_of(p.list ? p.count_type : p.type);
  return std::max<std::uint64_t>(n, 1);
}

void read_body(FileBytes& in, LineReader& lines, const PlyHeader& h, SoupBuilder& out) {
  const std::string& path = in.path();
  BodyReader body(in, lines, h.format);
  std::vector<int> corners;
  unsigned long long faces = 0;
  for (const PlyElement& e : h.elements) {
    const std::uint64_t fit = std::min<std::uint64_t>(e.count, in.remaining() / least_item_bytes(e, h.format));
    if (e.is_vertex()) out.vertices.reserve(out.vertices.size() + static_cast<std::size_t>(fit));
    if (e.is_face()) out.triangles.reserve(out.triangles.size() + static_cast<std::size_t>(fit));
    for (unsigned long long item = 0; item < e.count; ++item) {
      const ItemName what{&e, e.is_vertex() ? out.vertices.size() + 1 : e.is_face() ? faces + 1 : item + 1};
      Vec3 v{0, 0, 0};
      for (const PlyProperty& p : e.properties) {
        if (!p.list) {
          const Value value = body.read(p.type, what, p);
          if (p.role >= Role::x && p.role <= Role::z)
            v[static_cast<int>(p.role) - static_cast<int>(Role::x)] = value.real;
          continue;
        }
        const long long n = body.read(p.count_type, what, p).integer;
        // Each entry takes at least one byte: this bounds the list.
        if (n < 0 || static_cast<unsigned long long>(n) > body.remaining_bytes())
          refuse(InputErrorKind::malformed, path,
                 body.location(what.str() + ": list length " + std::to_string(n) +
                               " is negative or exceeds the rest of the file"));
        const bool indices = p.role == Role::face_indices;
        if (indices && n < 3)
          refuse(InputErrorKind::too_few_corners, path,
                 body.location(what.str() + " has " + std::to_string(n) + " corners (at least 3 are needed)"));
        if (indices) corners.clear();
        for (long long i = 0; i < n; ++i) {
          const long long index = body.read(p.type, what, p).integer;
          if (!indices) continue;
          if (index < 0 || static_cast<unsigned long long>(index) >= h.vertices)
            refuse(InputErrorKind::index_out_of_range, path,
                   body.location(what.str() + ": vertex index " + std::to_string(index) +
                                 " out of range (the file has " + std::to_string(h.vertices) + " vertices)"));
          corners.push_back(static_cast<int>(index));
        }
      }
      if (e.is_vertex()) out.add_vertex(v);
      if (e.is_face()) {
        out.add_face(corners);
        ++faces;
      }
    }
  }
}

}  // namespace

void read_ply(FileBytes& in, SoupBuilder& out) {
  LineReader lines(in, "not a PLY file (its header is text)");
  PlyHeader h = read_header(in.path(), lines);
  assign_roles(in.path(), h);
  // ASCII items (a list with many entries) may take more than 1 MiB; the header may not.
  lines.allow_long_lines([](std::string_view) { return true; });
  read_body(in, lines, h, out);
}

}  // namespace arrangements::detail
