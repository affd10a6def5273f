// ReadPointCloud (dispatch by format, normal normalisation) and
// WritePointCloud.
#include "meshseg/point_cloud.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/file_format.h"
#include "mesh/ply_body.h"
#include "mesh/point_cloud_readers.h"

namespace meshseg {
namespace mesh_internal {

absl::Status NormalizeNormals(const Source& src, PointCloud* cloud) {
  for (size_t i = 0; i < cloud->normals.size(); ++i) {
    Eigen::Vector3d& n = cloud->normals[i];
    const double length = n.norm();
    if (!(length > 0.0) || !std::isfinite(length)) {
      return BadInput(src, absl::StrCat("point ", i, " has a zero or non-finite normal (", n.x(),
                                        ", ", n.y(), ", ", n.z(), ")"));
    }
    n /= length;
  }
  return absl::OkStatus();
}

}  // namespace mesh_internal

using mesh_internal::BadInput;
using mesh_internal::FileName;
using mesh_internal::InputFile;
using mesh_internal::OpenInput;
using mesh_internal::PlyData;
using mesh_internal::ReadPlyData;
using mesh_internal::ReadPwn;
using mesh_internal::ReadXyz;
using mesh_internal::Source;

absl::StatusOr<PointCloud> ReadPointCloud(const std::string& path,
                                          const ReadMeshOptions& options) {
  const Source src{"read_point_cloud", FileName(path)};
  MESHSEG_ASSIGN_OR_RETURN(const InputFile input, OpenInput(path, options, src));
  const std::string_view bytes = input.bytes();
  const FileFormat format = input.format;
  PointCloud cloud;
  switch (format) {
    case FileFormat::kXyz: {
      MESHSEG_ASSIGN_OR_RETURN(cloud, ReadXyz(bytes, src, options.max_elements));
      break;
    }
    case FileFormat::kPwn: {
      MESHSEG_ASSIGN_OR_RETURN(cloud, ReadPwn(bytes, src, options.max_elements));
      break;
    }
    case FileFormat::kPly: {
      MESHSEG_ASSIGN_OR_RETURN(PlyData data, ReadPlyData(bytes, src, options.max_elements));
      if (data.vertices.empty()) return BadInput(src, "no points");
      cloud.points.assign(data.vertices.begin(), data.vertices.end());
      cloud.normals = std::move(data.normals);
      break;
    }
    default:
      return BadInput(src, absl::StrCat("unknown point-cloud format \"", FileFormatName(format),
                                        "\" (xyz, pwn, ply)"));
  }
  cloud.name = src.name;
  MESHSEG_RETURN_IF_ERROR(NormalizeNormals(src, &cloud));
  return cloud;
}

absl::Status WritePointCloud(const PointCloud& cloud, const std::string& path) {
  const std::string name = mesh_internal::FileName(path);
  if (cloud.has_normals() && cloud.normals.size() != cloud.points.size()) {
    return absl::InvalidArgumentError(absl::StrCat("write_point_cloud: \"", name, "\": ",
                                                   cloud.normals.size(), " normals for ",
                                                   cloud.points.size(), " points"));
  }
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (file == nullptr) {
    return absl::InternalError(absl::StrCat("write_point_cloud: \"", name, "\": cannot open"));
  }
  bool ok = true;
  for (size_t i = 0; i < cloud.points.size() && ok; ++i) {
    const Eigen::Vector3d& p = cloud.points[i];
    // %.17g keeps every double exactly.
    ok = std::fprintf(file.get(), "%.17g %.17g %.17g", p.x(), p.y(), p.z()) > 0;
    if (cloud.has_normals()) {
      const Eigen::Vector3d& n = cloud.normals[i];
      ok = ok && std::fprintf(file.get(), " %.17g %.17g %.17g", n.x(), n.y(), n.z()) > 0;
    }
    ok = ok && std::fputc('\n', file.get()) != EOF;
  }
  if (!ok || std::fflush(file.get()) != 0) {
    return absl::InternalError(absl::StrCat("write_point_cloud: \"", name, "\": cannot write"));
  }
  return absl::OkStatus();
}

}  // namespace meshseg
