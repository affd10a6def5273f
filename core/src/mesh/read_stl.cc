// STL, binary and ASCII. A binary file may begin with "solid" too, so the
// size rule 84 + 50 n decides first; text starting with "solid" is ASCII.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/raw_mesh.h"
#include "mesh/text_cursor.h"
#include "mesh/weld.h"

namespace meshseg::mesh_internal {
namespace {

constexpr int64_t kHeaderBytes = 84;
constexpr int64_t kTriangleBytes = 50;

float FloatAt(const char* p) {
  float v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}

RawMesh FromCorners(const std::vector<Eigen::Vector3d>& corners) {
  RawMesh raw;
  raw.corners = WeldIdentical(corners, &raw.vertices);
  const int64_t n = static_cast<int64_t>(corners.size()) / 3;
  raw.face_start.resize(n + 1);
  for (int64_t t = 0; t <= n; ++t) raw.face_start[t] = 3 * t;
  raw.input_vertex_count = static_cast<int64_t>(corners.size());
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
  std::vector<Eigen::Vector3d> corners(3 * n);
  const char* p = bytes.data() + kHeaderBytes;
  for (int64_t t = 0; t < n; ++t, p += kTriangleBytes) {
    for (int c = 0; c < 3; ++c) {
      const char* q = p + 12 + 12 * c;  // after the 12-byte facet normal
      Eigen::Vector3d& v = corners[3 * t + c];
      v = {FloatAt(q), FloatAt(q + 4), FloatAt(q + 8)};
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) {
        return BadInput(src, absl::StrCat("non-finite coordinate in triangle ", t,
                                          " at byte offset ", q - bytes.data()));
      }
    }
  }
  return FromCorners(corners);
}

absl::StatusOr<RawMesh> ReadAsciiStl(std::string_view bytes, const Source& src,
                                     int64_t max_elements) {
  TextCursor cursor(bytes);
  cursor.set_comments(false);
  std::vector<Eigen::Vector3d> corners;
  int corners_in_loop = 0;
  bool in_loop = false;
  while (cursor.SkipEmptyLines()) {
    const std::string_view word = cursor.Token();
    if (word == "vertex") {
      if (!in_loop) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": vertex outside a loop"));
      }
      Eigen::Vector3d v;
      for (int i = 0; i < 3; ++i) {
        const std::string_view token = cursor.Token();
        const std::optional<double> value = ParseDouble(token);
        if (!value) {
          return BadInput(src, absl::StrCat("line ", cursor.line(), ": expected a number, got \"",
                                            Shorten(token), "\""));
        }
        if (!std::isfinite(*value)) {
          return BadInput(src, absl::StrCat("line ", cursor.line(), ": non-finite coordinate \"",
                                            Shorten(token), "\""));
        }
        v[i] = *value;
      }
      if (static_cast<int64_t>(corners.size()) / 3 >= max_elements) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": more than ", max_elements,
                                          " triangles"));
      }
      corners.push_back(v);
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
  return FromCorners(corners);
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
