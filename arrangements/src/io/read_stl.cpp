// STL reader (see mesh_reader.h; what it accepts: load_triangle_soup.h). Binary when the
// size is exactly 84 + 50 x (the header's triangle count; nothing is reserved before that
// holds), else ASCII when the first token begins with "solid" (any case), no byte is NUL and
// no line is longer than 1 MiB (so a file of NULs or of binary data is refused at its first
// bytes). Equal corner positions (==, so -0.0 and 0.0 are one) become one vertex, in the
// order of their first appearance.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_reader.h"

namespace arrangements::detail {
namespace {

constexpr std::size_t kBinaryHeaderBytes = 84;    // 80-byte comment + uint32 triangle count
constexpr std::size_t kBinaryTriangleBytes = 50;  // normal, 3 corners (12 floats), uint16

std::uint32_t read_le_uint32(const char* at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(at[i]);
  return v;
}

float read_le_float(const char* at) {
  const std::uint32_t bits = read_le_uint32(at);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Vertex index by exact position: open addressing over indices into the vertices.
class PositionIndex {
 public:
  int find_or_add(const Vec3& p, SoupBuilder& out) {
    if (2 * (out.vertices.size() + 1) > slots_.size()) grow(out.vertices);
    for (std::size_t s = hash(p) & mask_;; s = (s + 1) & mask_) {
      const int v = slots_[s];
      if (v < 0) {
        out.add_vertex(p);
        slots_[s] = static_cast<int>(out.vertices.size() - 1);
        return slots_[s];
      }
      if (out.vertices[v] == p) return v;
    }
  }

 private:
  static std::size_t hash(const Vec3& p) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (double c : p) {
      const double d = c + 0.0;  // -0.0 and 0.0 hash alike
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h);
  }
  void grow(const std::vector<Vec3>& vertices) {
    slots_.assign(slots_.empty() ? 1024 : 2 * slots_.size(), -1);
    mask_ = slots_.size() - 1;
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      std::size_t s = hash(vertices[v]) & mask_;
      while (slots_[s] >= 0) s = (s + 1) & mask_;
      slots_[s] = static_cast<int>(v);
    }
  }
  std::vector<int> slots_;
  std::size_t mask_ = 0;
};

// Why the file is not an STL: not ASCII (no 'solid', or bytes that are not text), and its
// size does not match the triangle count of a binary header.
std::string not_stl(const FileBytes& in, std::uint32_t declared) {
  if (in.size() >= kBinaryHeaderBytes) {
    const std::uint64_t expected = kBinaryHeaderBytes + std::uint64_t{declared} * kBinaryTriangleBytes;
    return "neither an ASCII STL (which begins with 'solid') nor a binary STL of the right size: the binary STL "
           "size does not match its triangle count (a header declaring " +
           std::to_string(declared) + " triangles needs " + std::to_string(expected) + " bytes, the file has " +
           std::to_string(in.size()) + ")";
  }
  return "not an ASCII STL (which begins with 'solid') and too short for a binary STL (" + std::to_string(in.size()) +
         " bytes, the binary header alone has 84)";
}

[[noreturn]] void refuse_not_stl(const FileBytes& in, std::uint32_t declared) {
  refuse(InputErrorKind::malformed, in.path(), not_stl(in, declared));
}

void read_binary(FileBytes& in, SoupBuilder& out, std::uint32_t n) {
  if (n > kMaxIndexCount)
    refuse(InputErrorKind::too_large, in.path(),
           std::to_string(n) + " triangles (at most " + std::to_string(kMaxIndexCount) + " are supported)");
  in.consume(kBinaryHeaderBytes);
  out.triangles.reserve(n);
  PositionIndex positions;
  for (std::uint32_t t = 0; t < n; ++t) {
    if (in.fill(kBinaryTriangleBytes) < kBinaryTriangleBytes)
      refuse(InputErrorKind::malformed, in.path(), "the file ends inside triangle " + std::to_string(t + 1));
    const char* corners = in.unread() + 12;
    int ijk[3];
    for (int k = 0; k < 3; ++k) {
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        const float c = read_le_float(corners + 12 * k + 4 * axis);
        if (!std::isfinite(c))
          refuse(InputErrorKind::non_finite_coordinate, in.path(),
                 "triangle " + std::to_string(t + 1) + ", corner " + std::to_string(k + 1) +
                     ": a coordinate is not finite (" + std::to_string(c) + ")");
        p[axis] = c;
      }
      ijk[k] = positions.find_or_add(p, out);
    }
    out.add_face(ijk);
    in.consume(kBinaryTriangleBytes);
  }
}

bool begins_with_solid(std::string_view token) {
  return token.size() >= 5 && equals_ignoring_case(token.substr(0, 5), "solid");
}

// Outside a facet only "solid", "facet" and "endsolid" matter (any case); inside, "vertex"
// is followed by three numbers and "endfacet" ends it. The rest of a "solid" or "endsolid"
// line is the solid's name, free text ("solid facet" names a solid "facet").
void read_ascii(FileBytes& in, SoupBuilder& out, std::uint32_t declared) {
  const std::string& path = in.path();
  LineReader lines(in, not_stl(in, declared));  // refuses NUL bytes and lines beyond 1 MiB
  TokenReader tokens(lines);
  std::string_view token = tokens.next();
  if (!begins_with_solid(token)) refuse_not_stl(in, declared);
  PositionIndex positions;
  std::size_t facets = 0;
  bool in_solid = false, solid_seen = false;
  for (; !token.empty(); token = tokens.next()) {
    if (equals_ignoring_case(token, "solid")) {
      if (in_solid)
        refuse_at_line(InputErrorKind::malformed, path, tokens.line(), "'solid' before the previous 'endsolid'");
      in_solid = true;
      tokens.skip_rest_of_line();
    } else if (equals_ignoring_case(token, "endsolid")) {
      in_solid = false;
      solid_seen = true;
      tokens.skip_rest_of_line();
    } else if (equals_ignoring_case(token, "facet")) {
      const long facet_line = tokens.line();
      const auto what = [&facets] { return "facet " + std::to_string(facets + 1); };
      int corners = 0;
      int ijk[3];
      for (token = tokens.next(); !equals_ignoring_case(token, "endfacet"); token = tokens.next()) {
        if (token.empty()) refuse_at_line(InputErrorKind::malformed, path, facet_line, what() + " has no 'endfacet'");
        if (!equals_ignoring_case(token, "vertex")) continue;
        if (corners == 3)
          refuse_at_line(InputErrorKind::malformed, path, tokens.line(), what() + " has more than 3 vertices");
        Vec3 p;
        for (int axis = 0; axis < 3; ++axis) {
          const std::string_view number = tokens.next();
          const RealParse r = parse_real(number, p[axis]);
          if (r != RealParse::ok) refuse_coordinate(path, tokens.line(), r, what() + ": coordinate ", number);
        }
        ijk[corners++] = positions.find_or_add(p, out);
      }
      if (corners != 3)
        refuse_at_line(InputErrorKind::too_few_corners, path, tokens.line(),
                       what() + " has " + std::to_string(corners) + " vertices (3 are needed)");
      out.add_face(ijk);
      ++facets;
    }
  }
  if (in_solid) refuse(InputErrorKind::malformed, path, "the file ends without 'endsolid'");
  if (!solid_seen) refuse(InputErrorKind::malformed, path, "no 'solid' ... 'endsolid' block");
}

}  // namespace

void read_stl(FileBytes& in, SoupBuilder& out) {
  std::uint32_t declared = 0;
  if (in.size() >= kBinaryHeaderBytes && in.fill(kBinaryHeaderBytes) >= kBinaryHeaderBytes) {
    declared = read_le_uint32(in.unread() + 80);
    if (kBinaryHeaderBytes + std::uint64_t{declared} * kBinaryTriangleBytes == in.size())
      return read_binary(in, out, declared);
  }
  read_ascii(in, out, declared);
}

}  // namespace arrangements::detail
