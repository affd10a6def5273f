// Wavefront OBJ: "v x y z [w]" and "f" lines whose corners are i, i/t, i//n
// or i/t/n, 1-based or negative (relative to the vertices so far). Other
// statements (vt, vn, g, o, s, usemtl, mtllib, l, p) are skipped.
#include <cmath>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/raw_mesh.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {

absl::StatusOr<RawMesh> ReadObj(std::string_view bytes, const Source& src, int64_t max_elements) {
  TextCursor cursor(bytes);
  RawMesh raw;
  raw.face_start.clear();
  raw.face_start.push_back(0);
  while (cursor.SkipEmptyLines()) {
    const std::string_view word = cursor.Token();
    if (word == "v") {
      Eigen::Vector3d v;
      for (int i = 0; i < 3; ++i) {
        MESHSEG_ASSIGN_OR_RETURN(v[i], NextFinite(src, cursor, "coordinate"));
      }
      if (static_cast<int64_t>(raw.vertices.size()) >= max_elements) {
        return AtLine(src, cursor, absl::StrCat("more than ", max_elements, " vertices"));
      }
      raw.vertices.push_back(v);
    } else if (word == "f") {
      const int64_t n = static_cast<int64_t>(raw.vertices.size());
      int corners = 0;
      for (std::string_view token = cursor.Token(); !token.empty(); token = cursor.Token()) {
        const std::string_view index_text = token.substr(0, token.find('/'));
        const std::optional<int64_t> index = ParseInt(index_text);
        if (!index) {
          return AtLine(src, cursor,
                        absl::StrCat("expected a vertex index, got \"", Shorten(token), "\""));
        }
        const int64_t i = *index < 0 ? n + *index : *index - 1;
        if (*index == 0 || i < 0 || i >= n) {
          return AtLine(src, cursor, absl::StrCat("vertex index ", *index, " out of range (", n,
                                                  " vertices defined so far)"));
        }
        raw.corners.push_back(static_cast<int>(i));
        ++corners;
      }
      if (corners < 3) {
        return AtLine(src, cursor, absl::StrCat("face has ", corners, " corners, expected >= 3"));
      }
      if (raw.face_count() >= max_elements) {
        return AtLine(src, cursor, absl::StrCat("more than ", max_elements, " faces"));
      }
      raw.face_start.push_back(static_cast<int64_t>(raw.corners.size()));
    }
    cursor.NextLine();
  }
  raw.input_vertex_count = static_cast<int64_t>(raw.vertices.size());
  if (raw.vertices.empty()) return BadInput(src, "no vertices");
  if (raw.face_count() == 0) return BadInput(src, "no faces");
  return raw;
}

}  // namespace meshseg::mesh_internal
