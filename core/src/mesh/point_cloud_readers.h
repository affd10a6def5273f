// Readers of point-cloud files (XYZ, PWN; PLY goes through ReadPlyData).
#ifndef MESHSEG_MESH_POINT_CLOUD_READERS_H_
#define MESHSEG_MESH_POINT_CLOUD_READERS_H_

#include <cstdint>
#include <string_view>

#include "absl/status/statusor.h"
#include "meshseg/point_cloud.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

// Returns the points (and normals, as given) of an XYZ file: one point per
// line, "x y z" or "x y z nx ny nz", blank- or comma-separated, '#' comments.
// Every line must have as many values as the first.
absl::StatusOr<PointCloud> ReadXyz(std::string_view bytes, const Source& src,
                                   int64_t max_elements);

// Returns the points and normals of a PWN file: a count N, N lines "x y z",
// then N lines "nx ny nz".
absl::StatusOr<PointCloud> ReadPwn(std::string_view bytes, const Source& src,
                                   int64_t max_elements);

// Scales every normal of `cloud` to unit length. Errors name the first point
// whose normal is zero or not finite.
absl::Status NormalizeNormals(const Source& src, PointCloud* cloud);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_POINT_CLOUD_READERS_H_
