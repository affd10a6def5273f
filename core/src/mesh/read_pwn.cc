#include <cmath>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/point_cloud_readers.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {
namespace {

// Reads `out->size()` lines of three finite values; `what` names them.
absl::Status ReadTriples(const Source& src, TextCursor& cursor, const std::string& what,
                         std::vector<Eigen::Vector3d>* out) {
  for (size_t i = 0; i < out->size(); ++i) {
    if (!cursor.SkipEmptyLines()) {
      return BadInput(src, absl::StrCat("count declares ", out->size(), " ", what,
                                        ", file holds ", i));
    }
    for (int c = 0; c < 3; ++c) {
      MESHSEG_ASSIGN_OR_RETURN((*out)[i][c], NextFinite(src, cursor, "number"));
    }
    if (!cursor.AtLineEnd()) {
      return BadInput(src, absl::StrCat("line ", cursor.line(), ": more than 3 values"));
    }
    cursor.NextLine();
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<PointCloud> ReadPwn(std::string_view bytes, const Source& src,
                                   int64_t max_elements) {
  TextCursor cursor(bytes);
  if (!cursor.SkipEmptyLines()) return BadInput(src, "empty file");
  const std::string_view token = cursor.Token();
  const std::optional<int64_t> n = ParseInt(token);
  if (!n || !cursor.AtLineEnd()) {
    return BadInput(src, absl::StrCat("line ", cursor.line(), ": expected the point count, got \"",
                                      Shorten(token), "\""));
  }
  cursor.NextLine();
  // Each point and each normal takes at least "0 0 0\n".
  MESHSEG_RETURN_IF_ERROR(CheckDeclaredCount(src, "points", *n, 12,
                                             static_cast<int64_t>(bytes.size() - cursor.offset()),
                                             max_elements));
  if (*n == 0) return BadInput(src, "count declares 0 points");
  PointCloud cloud;
  cloud.points.resize(*n);
  cloud.normals.resize(*n);
  MESHSEG_RETURN_IF_ERROR(ReadTriples(src, cursor, "points", &cloud.points));
  MESHSEG_RETURN_IF_ERROR(ReadTriples(src, cursor, "normals", &cloud.normals));
  if (cursor.SkipEmptyLines()) {
    return BadInput(src, absl::StrCat("line ", cursor.line(), ": data after the ", *n,
                                      " declared points and normals"));
  }
  return cloud;
}

}  // namespace meshseg::mesh_internal
