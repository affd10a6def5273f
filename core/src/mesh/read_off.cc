// OFF (and COFF/NOFF/CNOFF): a header line, "nv nf ne", nv vertex lines
// whose first three values are x y z, then nf lines "n i1 .. in [colour]".
#include <cmath>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/raw_mesh.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {
namespace {

// Reads the next integer token of the current line into *value.
absl::Status NextInt(const Source& src, TextCursor& cursor, const std::string& what,
                     int64_t* value) {
  const std::string_view token = cursor.Token();
  const std::optional<int64_t> parsed = ParseInt(token);
  if (!parsed) {
    return AtLine(src, cursor,
                  absl::StrCat("expected ", what, ", got \"", Shorten(token), "\""));
  }
  *value = *parsed;
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<RawMesh> ReadOff(std::string_view bytes, const Source& src, int64_t max_elements) {
  TextCursor cursor(bytes);
  if (!cursor.SkipEmptyLines()) return BadInput(src, "empty file");
  const std::string_view magic = cursor.Token();
  if (!magic.ends_with("OFF") || magic.size() > 5) {
    return AtLine(src, cursor, absl::StrCat("expected \"OFF\", got \"", Shorten(magic), "\""));
  }
  if (cursor.AtLineEnd()) {
    cursor.NextLine();
    if (!cursor.SkipEmptyLines()) return BadInput(src, "missing vertex and face counts");
  }
  int64_t nv = 0, nf = 0, ne = 0;
  MESHSEG_RETURN_IF_ERROR(NextInt(src, cursor, "the vertex count", &nv));
  MESHSEG_RETURN_IF_ERROR(NextInt(src, cursor, "the face count", &nf));
  if (!cursor.AtLineEnd()) MESHSEG_RETURN_IF_ERROR(NextInt(src, cursor, "the edge count", &ne));
  cursor.NextLine();
  const int64_t left = static_cast<int64_t>(bytes.size() - cursor.offset());
  // Shortest possible lines: "0 0 0\n" and "3 0 1 2\n".
  MESHSEG_RETURN_IF_ERROR(CheckDeclaredCount(src, "vertices", nv, 6, left, max_elements));
  MESHSEG_RETURN_IF_ERROR(CheckDeclaredCount(src, "faces", nf, 8, left - 6 * nv, max_elements));
  if (nv == 0) return BadInput(src, "header declares 0 vertices");
  if (nf == 0) return BadInput(src, "header declares 0 faces");

  RawMesh raw;
  raw.vertices.resize(nv);
  raw.input_vertex_count = nv;
  for (int64_t i = 0; i < nv; ++i) {
    if (!cursor.SkipEmptyLines()) {
      return BadInput(src, absl::StrCat("header declares ", nv, " vertices, file holds ", i));
    }
    for (int c = 0; c < 3; ++c) {
      MESHSEG_ASSIGN_OR_RETURN(raw.vertices[i][c], NextFinite(src, cursor, "coordinate"));
    }
    cursor.NextLine();
  }
  raw.face_start.resize(nf + 1);
  raw.corners.reserve(3 * nf);
  for (int64_t f = 0; f < nf; ++f) {
    if (!cursor.SkipEmptyLines()) {
      return BadInput(src, absl::StrCat("header declares ", nf, " faces, file holds ", f));
    }
    int64_t n = 0;
    MESHSEG_RETURN_IF_ERROR(NextInt(src, cursor, "a corner count", &n));
    if (n < 3 || n > 1'000'000) {
      return AtLine(src, cursor, absl::StrCat("face has ", n, " corners, expected 3 to 1000000"));
    }
    for (int64_t c = 0; c < n; ++c) {
      int64_t index = 0;
      MESHSEG_RETURN_IF_ERROR(NextInt(src, cursor, "a vertex index", &index));
      if (index < 0 || index >= nv) {
        return AtLine(src, cursor,
                      absl::StrCat("vertex index ", index, " out of range [0, ", nv, ")"));
      }
      raw.corners.push_back(static_cast<int>(index));
    }
    raw.face_start[f + 1] = static_cast<int64_t>(raw.corners.size());
    cursor.NextLine();
  }
  if (cursor.SkipEmptyLines()) {
    return AtLine(src, cursor, absl::StrCat("data after the ", nf, " declared faces"));
  }
  return raw;
}

}  // namespace meshseg::mesh_internal
