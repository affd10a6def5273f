#include <cmath>

#include "absl/strings/str_cat.h"
#include "mesh/point_cloud_readers.h"
#include "mesh/text_cursor.h"

namespace meshseg::mesh_internal {

absl::StatusOr<PointCloud> ReadXyz(std::string_view bytes, const Source& src,
                                   int64_t max_elements) {
  TextCursor cursor(bytes, /*comma_is_space=*/true);
  PointCloud cloud;
  int columns = 0;  // of the first line: 3 or 6
  while (cursor.SkipEmptyLines()) {
    double values[6];
    int count = 0;
    for (std::string_view token = cursor.Token(); !token.empty(); token = cursor.Token()) {
      const std::optional<double> value = ParseDouble(token);
      if (!value) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": expected a number, got \"",
                                          Shorten(token), "\""));
      }
      if (!std::isfinite(*value)) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": non-finite value \"",
                                          Shorten(token), "\""));
      }
      if (count == 6) {
        return BadInput(src, absl::StrCat("line ", cursor.line(),
                                          ": more than 6 values, expected 3 or 6"));
      }
      values[count++] = *value;
    }
    if (columns == 0) {
      if (count != 3 && count != 6) {
        return BadInput(src, absl::StrCat("line ", cursor.line(), ": ", count,
                                          " values, expected 3 (x y z) or 6 (x y z nx ny nz)"));
      }
      columns = count;
    } else if (count != columns) {
      return BadInput(src, absl::StrCat("line ", cursor.line(), ": ", count, " values, expected ",
                                        columns, " as on the first line"));
    }
    if (static_cast<int64_t>(cloud.points.size()) >= max_elements) {
      return BadInput(src, absl::StrCat("line ", cursor.line(), ": more than ", max_elements,
                                        " points"));
    }
    cloud.points.emplace_back(values[0], values[1], values[2]);
    if (columns == 6) cloud.normals.emplace_back(values[3], values[4], values[5]);
    cursor.NextLine();
  }
  if (cloud.points.empty()) return BadInput(src, "no points");
  return cloud;
}

}  // namespace meshseg::mesh_internal
