#include "client/report_geometry.h"

#include <filesystem>
#include <limits>
#include <map>

#include "absl/strings/str_cat.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {
namespace {

// Region index per region id of `result`.
std::map<int, int> IndexOfRegionId(const v1::SegmentationResult& result) {
  std::map<int, int> index;
  for (int i = 0; i < result.regions_size(); ++i) index.emplace(result.regions(i).id(), i);
  return index;
}

int32_t IndexOf(const std::map<int, int>& index, int label) {
  const auto it = index.find(label);
  return it == index.end() ? -1 : it->second;
}

// Fills positions and offset from `points`, centred on their bounding box.
void SetPositions(const std::vector<Eigen::Vector3d>& points, ReportGeometry* g) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d centre =
      points.empty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(0.5 * (lo + hi));
  g->offset = {centre.x(), centre.y(), centre.z()};
  g->positions.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points) {
    for (int c = 0; c < 3; ++c) g->positions.push_back(static_cast<float>(p[c] - centre[c]));
  }
}

absl::Status CountMismatch(const std::string& name, int64_t file_count, const char* what,
                           int64_t result_count, const char* result_what) {
  return absl::InvalidArgumentError(
      absl::StrCat("report: \"", name, "\" has ", file_count, " ", what, ", the result ",
                   result_count, " ", result_what, " (give the file that was segmented)"));
}

absl::StatusOr<ReportGeometry> CloudGeometry(const std::string& path,
                                             const v1::SegmentationResult& result,
                                             const std::optional<FileFormat>& format) {
  MESHSEG_ASSIGN_OR_RETURN(const PointCloud cloud, ReadPointCloud(path, {.format = format}));
  const int64_t n = static_cast<int64_t>(cloud.points.size());
  if (result.point_labels_size() != n) {
    return CountMismatch(cloud.name, n, "points", result.point_labels_size(), "point labels");
  }
  ReportGeometry g;
  g.kind = ReportGeometry::Kind::kPoints;
  SetPositions(cloud.points, &g);
  const std::map<int, int> index = IndexOfRegionId(result);
  g.labels.reserve(cloud.points.size());
  for (const int label : result.point_labels()) g.labels.push_back(IndexOf(index, label));
  g.note =
      "the points of the input, coloured by region; the boundary curves lie on the "
      "reconstructed mesh, which the result does not hold";
  return g;
}

// Appends the edges of every curve to the sharp or smooth segments.
absl::Status AddCurves(const v1::SegmentationResult& result, const std::string& name,
                       int64_t vertex_count, ReportGeometry* g) {
  for (const v1::BoundaryCurve& curve : result.curves()) {
    std::vector<uint32_t>& out = curve.sharp() ? g->sharp_segments : g->smooth_segments;
    for (int k = 0; k < curve.vertices_size(); ++k) {
      if (curve.vertices(k) < 0 || curve.vertices(k) >= vertex_count) {
        return absl::InvalidArgumentError(absl::StrCat(
            "report: curve ", curve.id(), " has vertex ", curve.vertices(k), ", \"", name,
            "\" has ", vertex_count, " vertices (give the file that was segmented)"));
      }
      if (k == 0) continue;
      out.push_back(static_cast<uint32_t>(curve.vertices(k - 1)));
      out.push_back(static_cast<uint32_t>(curve.vertices(k)));
    }
  }
  return absl::OkStatus();
}

absl::StatusOr<ReportGeometry> MeshGeometry(const std::string& path,
                                            const v1::SegmentationResult& result,
                                            const std::optional<FileFormat>& format) {
  MESHSEG_ASSIGN_OR_RETURN(const Mesh& mesh, ReadMesh(path, {.format = format}));
  const int64_t input_faces = static_cast<int64_t>(mesh.face_of_input.size());
  if (result.face_labels_size() != input_faces) {
    return CountMismatch(mesh.name, input_faces, "faces", result.face_labels_size(), "face labels");
  }
  ReportGeometry g;
  g.kind = ReportGeometry::Kind::kTriangles;
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh.tri.n_vertices());
  for (const auto v : mesh.tri.vertices()) vertices.push_back(ToEigen(mesh.tri.point(v)));
  SetPositions(vertices, &g);
  g.triangles.reserve(3 * mesh.tri.n_faces());
  for (const auto f : mesh.tri.faces()) {
    for (const auto v : mesh.tri.fv_range(f)) g.triangles.push_back(v.idx());
  }
  const std::map<int, int> index = IndexOfRegionId(result);
  g.labels.assign(mesh.tri.n_faces(), -1);
  for (int64_t i = 0; i < input_faces; ++i) {
    if (mesh.face_of_input[i] >= 0)
      g.labels[mesh.face_of_input[i]] = IndexOf(index, result.face_labels(i));
  }
  MESHSEG_RETURN_IF_ERROR(
      AddCurves(result, mesh.name, static_cast<int64_t>(mesh.tri.n_vertices()), &g));
  return g;
}

}  // namespace

absl::StatusOr<ReportGeometry> GeometryForReport(const std::string& path,
                                                 const v1::SegmentationResult& result,
                                                 const std::optional<FileFormat>& format) {
  bool cloud = format && (*format == FileFormat::kXyz || *format == FileFormat::kPwn);
  if (!format || *format == FileFormat::kPly) {
    MESHSEG_ASSIGN_OR_RETURN(cloud, IsPointCloudFile(path));
  }
  return cloud ? CloudGeometry(path, result, format) : MeshGeometry(path, result, format);
}

}  // namespace meshseg::cli
