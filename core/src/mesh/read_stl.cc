// STL, binary and ASCII. A binary file may begin with "solid" too, so the
// size rule 84 + 50 n decides first; text starting with "solid" is ASCII.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/raw_mesh.h"
#include "mesh/text_cursor.h"
#include "mesh/weld.h"

namespace meshseg::mesh_internal {
namespace {

constexpr int64_t kHeaderBytes = 84;
constexpr int64_t kTriangleBytes = 50;

// The bits of a coordinate, with -0.0 mapped to 0.0 so that they weld.
template <typename Bits, typename Real>
Bits BitsOf(Real value) {
  value += Real(0);
  Bits bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

// Returns the triangles of `welder`'s corners, 3 per triangle in order.
template <typename Bits>
RawMesh FromWelded(const Welder<Bits>& welder, LargeVector<int> corners) {
  using Real = std::conditional_t<sizeof(Bits) == 4, float, double>;
  RawMesh raw;
  raw.vertices.resize(welder.keys().size());
  for (size_t i = 0; i < raw.vertices.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      Real value;
      std::memcpy(&value, &welder.keys()[i][c], sizeof(value));
      raw.vertices[i][c] = value;
    }
  }
  const int64_t n = static_cast<int64_t>(corners.size()) / 3;
  raw.input_vertex_count = static_cast<int64_t>(corners.size());
  raw.corners = std::move(corners);
  raw.face_start.resize(n + 1);
  for (int64_t t = 0; t <= n; ++t) raw.face_start[t] = 3 * t;
  return raw;
}

absl::StatusOr<RawMesh> ReadBinaryStl(std::string_view bytes, const Source& src,
                                      int64_t max_elements) {
  const int64_t size = static_cast<int64_t>(bytes.size());
  if (size < kHeaderBytes) {
    return BadInput(src, absl::StrCat("file is ", size, " bytes, shorter than the ", kHeaderBytes,
                                      "-byte binary stl header"));
  }
  uint32_t declared;
  std::memcpy(&declared, bytes.data() + 80, sizeof(declared));
  const int64_t n = declared;
  if (n > max_elements) {
    return BadInput(src, absl::StrCat("header declares ", n, " triangles, over the limit of ",
                                      max_elements));
  }
  const int64_t held = (size - kHeaderBytes) / kTriangleBytes;
  if (kHeaderBytes + kTriangleBytes * n != size) {
    return BadInput(src, absl::StrCat("header declares ", n, " triangles, file holds ", held,
                                      " (", size, " bytes, expected ",
                                      kHeaderBytes + kTriangleBytes * n, ")"));
  }
  if (n == 0) return BadInput(src, "header declares 0 triangles");
  // A closed mesh has about n / 2 vertices.
  Welder<uint32_t> welder(static_cast<size_t>(n / 2 + 16));
  LargeVector<int> corners(3 * n);
  const char* p = bytes.data() + kHeaderBytes;
  for (int64_t t = 0; t < n; ++t, p += kTriangleBytes) {
    for (int c = 0; c < 3; ++c) {
      const char* q = p + 12 + 12 * c;  // after the 12-byte facet normal
      float xyz[3];
      std::memcpy(xyz, q, sizeof(xyz));
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        return BadInput(src, absl::StrCat("non-finite coordinate in triangle ", t,
                                          " at byte offset ", q - bytes.data()));
      }
      corners[3 * t + c] = welder.Insert({BitsOf<uint32_t>(xyz[0]), BitsOf<uint32_t>(xyz[1]),
                                          BitsOf<uint32_t>(xyz[2])});
    }
  }
  return FromWelded(welder, std::move(corners));
}

absl::StatusOr<RawMesh> ReadAsciiStl(std::string_view bytes, const Source& src,
                                     int64_t max_elements) {
  TextCursor cursor(bytes);
  cursor.set_comments(false);
  Welder<uint64_t> welder(1024);
  LargeVector<int> corners;
  int corners_in_loop = 0;
  bool in_loop = false;
  while (cursor.SkipEmptyLines()) {
    const std::string_view word = cursor.Token();
    if (word == "vertex") {
      if (!in_loop) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": vertex outside a loop"));
      }
      std::array<uint64_t, 3> v;
      for (int i = 0; i < 3; ++i) {
        MESHSEG_ASSIGN_OR_RETURN(const double value, NextFinite(src, cursor, "coordinate"));
        v[i] = BitsOf<uint64_t>(value);
      }
      if (static_cast<int64_t>(corners.size()) / 3 >= max_elements) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": more than ", max_elements,
                                          " triangles"));
      }
      corners.push_back(welder.Insert(v));
      ++corners_in_loop;
    } else if (word == "outer") {
      in_loop = true;
      corners_in_loop = 0;
    } else if (word == "endloop") {
      if (corners_in_loop != 3) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": facet has ", corners_in_loop,
                                          " vertices, expected 3"));
      }
      in_loop = false;
    } else if (word != "solid" && word != "facet" && word != "endfacet" && word != "endsolid") {
      return BadInput(src, absl::StrCat("line ", cursor.line(), ": unexpected \"", Shorten(word),
                                        "\" in ascii stl"));
    }
    cursor.NextLine();
  }
  if (in_loop) return BadInput(src, absl::StrCat("line ", cursor.line(), ": unterminated facet"));
  if (corners.empty()) return BadInput(src, "no triangles");
  return FromWelded(welder, std::move(corners));
}

}  // namespace

absl::StatusOr<RawMesh> ReadStl(std::string_view bytes, const Source& src, int64_t max_elements) {
  const int64_t size = static_cast<int64_t>(bytes.size());
  if (size >= kHeaderBytes) {
    uint32_t declared;
    std::memcpy(&declared, bytes.data() + 80, sizeof(declared));
    if (kHeaderBytes + kTriangleBytes * static_cast<int64_t>(declared) == size) {
      return ReadBinaryStl(bytes, src, max_elements);
    }
  }
  const std::string_view start = StripLeadingSpace(bytes.substr(0, 256));
  if (start.starts_with("solid") && bytes.find('\0') == std::string_view::npos) {
    return ReadAsciiStl(bytes, src, max_elements);
  }
  return ReadBinaryStl(bytes, src, max_elements);
}

}  // namespace meshseg::mesh_internal
