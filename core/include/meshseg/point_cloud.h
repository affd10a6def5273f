// File: point_cloud.h
// -----------------------------------------------------------------------------
// Point clouds as scanners deliver them: XYZ (x y z [nx ny nz]), PLY vertices
// with optional normals, PWN (a point count, then points, then normals).
// Part of the `mesh` stage (same readers' conventions and errors).
#ifndef MESHSEG_POINT_CLOUD_H_
#define MESHSEG_POINT_CLOUD_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"

namespace meshseg {

struct PointCloud {
  std::vector<Eigen::Vector3d> points;
  // Empty, or one unit normal per point as given in the file.
  std::vector<Eigen::Vector3d> normals;
  std::string name;  // the file name, for messages

  bool has_normals() const { return !normals.empty(); }
};

// Returns the point cloud in `path` (XYZ, PWN, or PLY vertices).
// Errors (INVALID_ARGUMENT unless noted): missing file (NOT_FOUND), unknown
// format, a line with the wrong number of values, NaN/Inf, truncated binary
// PLY, declared counts over options.max_elements, no points.
absl::StatusOr<PointCloud> ReadPointCloud(const std::string& path,
                                          const ReadMeshOptions& options = {});

// Writes `cloud` as XYZ (with normals when it has them).
absl::Status WritePointCloud(const PointCloud& cloud, const std::string& path);

// Writes the points of `cloud` as a binary PLY with one colour per point:
// points with the same label share a colour (the colours of WriteColoredPly),
// label -1 (outliers, unlabelled) is grey. `point_labels` has one entry per
// point. Errors: INVALID_ARGUMENT if the sizes differ; INTERNAL on write failure.
absl::Status WriteColoredPointPly(const PointCloud& cloud, const std::vector<int>& point_labels,
                                  const std::string& path);

}  // namespace meshseg

#endif  // MESHSEG_POINT_CLOUD_H_
