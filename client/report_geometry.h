// File: report_geometry.h
// -----------------------------------------------------------------------------
// The geometry the HTML report draws: the input mesh (or point cloud) of a
// result as compact binary buffers, each face (or point) labelled with its
// region's index in result.regions, and the boundary curves as line segments.
#ifndef MESHSEG_CLIENT_REPORT_GEOMETRY_H_
#define MESHSEG_CLIENT_REPORT_GEOMETRY_H_

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg::cli {

struct ReportGeometry {
  enum class Kind { kNone, kTriangles, kPoints };
  Kind kind = Kind::kNone;
  // xyz per vertex (or point), minus `offset` (the bounding box centre), so
  // float precision holds on parts far from the origin.
  std::vector<float> positions;
  std::array<double, 3> offset = {0.0, 0.0, 0.0};
  std::vector<uint32_t> triangles;  // 3 vertex ids per face; empty for points
  // Index into result.regions per face (or point); -1 = no region.
  std::vector<int32_t> labels;
  // Vertex id pairs, one per curve edge, of sharp and of smooth curves.
  std::vector<uint32_t> sharp_segments;
  std::vector<uint32_t> smooth_segments;
  // Why there is no 3D view, or why it shows no curves; empty otherwise.
  std::string note;
};

// Returns the geometry of `result` on the file at `path` (the file that was
// segmented): a mesh with one label per face of the file, or a point cloud
// with one label per point. `format` overrides detection.
// Errors: those of ReadMesh / ReadPointCloud; INVALID_ARGUMENT naming the
// file when its face, point or vertex count is not the result's.
absl::StatusOr<ReportGeometry> GeometryForReport(const std::string& path,
                                                 const v1::SegmentationResult& result,
                                                 const std::optional<FileFormat>& format);

}  // namespace meshseg::cli

#endif  // MESHSEG_CLIENT_REPORT_GEOMETRY_H_
