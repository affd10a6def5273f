// meshseg info FILE [--json]: statistics of a mesh or a point cloud, or a
// volume's header.
#include <cstdio>
#include <filesystem>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "client/commands.h"
#include "client/volume_args.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/point_cloud.h"
#include "meshseg/proto/convert.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (static_cast<unsigned char>(c) < 0x20) {
      absl::StrAppendFormat(&out, "\\u%04x", c);
    } else {
      out.push_back(c);
    }
  }
  return out + "\"";
}

std::string JsonVec(const Eigen::Vector3d& v) {
  return absl::StrFormat("[%.17g, %.17g, %.17g]", v.x(), v.y(), v.z());
}

absl::Status MeshInfo(const std::string& path, FileFormat format, bool json) {
  MESHSEG_ASSIGN_OR_RETURN(const Mesh& mesh, ReadMesh(path));
  const MeshStats s = MeshStatistics(mesh);
  const std::string name = std::filesystem::path(path).filename().string();
  if (json) {
    std::printf(
        "{\"file\": %s, \"format\": \"%s\", \"vertex_count\": %lld, \"face_count\": %lld, "
        "\"mean_edge_length\": %.17g, \"boundary_edge_count\": %lld, \"component_count\": %lld, "
        "\"input_vertex_count\": %lld, \"mesh_face_count\": %lld, \"dropped_face_count\": %lld, "
        "\"degenerate_face_count\": %lld, \"non_manifold_edge_count\": %lld, "
        "\"non_manifold_vertex_count\": %lld, \"isolated_vertex_count\": %lld, "
        "\"bbox_min\": %s, \"bbox_max\": %s}\n",
        JsonString(name).c_str(), FileFormatName(format), (long long)s.vertex_count,
        (long long)s.input_face_count, s.mean_edge_length, (long long)s.boundary_edge_count,
        (long long)s.component_count, (long long)s.input_vertex_count, (long long)s.face_count,
        (long long)s.dropped_face_count, (long long)s.degenerate_face_count,
        (long long)s.non_manifold_edge_count, (long long)s.non_manifold_vertex_count,
        (long long)s.isolated_vertex_count, JsonVec(s.bbox_min).c_str(),
        JsonVec(s.bbox_max).c_str());
    return absl::OkStatus();
  }
  std::printf(
      "%s (%s mesh)\n  faces      %lld in the file, %lld in the mesh, %lld dropped "
      "(%lld degenerate)\n  vertices   %lld in the file, %lld in the mesh (%lld isolated)\n"
      "  edges      mean length %.6g, %lld boundary, %lld non-manifold\n"
      "  components %lld\n  non-manifold vertices %lld\n  bbox       (%.6g %.6g %.6g) - "
      "(%.6g %.6g %.6g)\n",
      name.c_str(), FileFormatName(format), (long long)s.input_face_count, (long long)s.face_count,
      (long long)s.dropped_face_count, (long long)s.degenerate_face_count,
      (long long)s.input_vertex_count, (long long)s.vertex_count,
      (long long)s.isolated_vertex_count, s.mean_edge_length, (long long)s.boundary_edge_count,
      (long long)s.non_manifold_edge_count, (long long)s.component_count,
      (long long)s.non_manifold_vertex_count, s.bbox_min.x(), s.bbox_min.y(), s.bbox_min.z(),
      s.bbox_max.x(), s.bbox_max.y(), s.bbox_max.z());
  return absl::OkStatus();
}

absl::Status CloudInfo(const std::string& path, FileFormat format, bool json) {
  MESHSEG_ASSIGN_OR_RETURN(const PointCloud cloud, ReadPointCloud(path));
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  if (!cloud.points.empty()) lo = hi = cloud.points.front();
  for (const Eigen::Vector3d& p : cloud.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const std::string name = std::filesystem::path(path).filename().string();
  if (json) {
    std::printf(
        "{\"file\": %s, \"format\": \"%s\", \"point_count\": %zu, \"has_normals\": %s, "
        "\"bbox_min\": %s, \"bbox_max\": %s}\n",
        JsonString(name).c_str(), FileFormatName(format), cloud.points.size(),
        cloud.has_normals() ? "true" : "false", JsonVec(lo).c_str(), JsonVec(hi).c_str());
    return absl::OkStatus();
  }
  std::printf("%s (%s point cloud)\n  points     %zu (%s normals)\n  bbox       (%.6g %.6g %.6g) - "
              "(%.6g %.6g %.6g)\n",
              name.c_str(), FileFormatName(format), cloud.points.size(),
              cloud.has_normals() ? "with" : "without", lo.x(), lo.y(), lo.z(), hi.x(), hi.y(),
              hi.z());
  return absl::OkStatus();
}

absl::Status VolumeInfoOf(const std::string& path, const Args& args, bool json) {
  UploadOptions options;
  options.format_hint = args.Value("--format").value_or("");
  MESHSEG_RETURN_IF_ERROR(VolumeOptionsFromArgs(args, &options));
  PipelineParams params;
  MESHSEG_ASSIGN_OR_RETURN(params.format, FormatFromHint(options.format_hint));
  MESHSEG_RETURN_IF_ERROR(RawLayoutFromProto(options.raw, &params));
  params.volume.read.format = params.format;
  MESHSEG_ASSIGN_OR_RETURN(const VolumeInfo info, ReadVolumeInfo(path, params.volume.read));
  const VolumeGeometry& g = info.geometry;
  if (json) {
    std::printf(
        "{\"file\": %s, \"format\": \"%s\", \"dims\": [%lld, %lld, %lld], \"voxel_count\": %lld, "
        "\"spacing\": %s, \"origin\": %s, \"voxel_type\": \"%s\", \"encoding\": \"%s\", "
        "\"big_endian\": %s}\n",
        JsonString(info.name).c_str(), FileFormatName(info.format), (long long)g.dims[0],
        (long long)g.dims[1], (long long)g.dims[2], (long long)g.VoxelCount(),
        JsonVec(g.Spacing()).c_str(), JsonVec(g.origin).c_str(), VoxelTypeName(info.type),
        info.gzip ? "gzip" : "raw", info.big_endian ? "true" : "false");
    return absl::OkStatus();
  }
  std::printf("%s (%s volume)\n  samples    %lld x %lld x %lld %s (%s%s)\n  spacing    %.6g %.6g %.6g\n"
              "  origin     (%.6g %.6g %.6g)\n",
              info.name.c_str(), FileFormatName(info.format), (long long)g.dims[0], (long long)g.dims[1],
              (long long)g.dims[2], VoxelTypeName(info.type), info.gzip ? "gzip" : "raw",
              info.big_endian ? ", big endian" : "", g.Spacing().x(), g.Spacing().y(), g.Spacing().z(),
              g.origin.x(), g.origin.y(), g.origin.z());
  return absl::OkStatus();
}

}  // namespace

absl::Status RunInfo(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv,
                  {"--format", "--iso", "--volume-mode", "--dims", "--spacing", "--origin",
                   "--type"},
                  {"--json", "--memory-estimate", kBigEndianSwitch}, 1));
  const std::string& path = args.positional(0);
  if (args.Has("--memory-estimate")) {  // from the header alone, as admission sees it
    MESHSEG_ASSIGN_OR_RETURN(const MemoryEstimate e, EstimateJobMemory(path));
    std::printf(
        "{\"file\": %s, \"format\": \"%s\", \"point_cloud\": %s, "
        "\"declared_vertices\": %lld, \"declared_faces\": %lld, \"file_bytes\": %lld, "
        "\"peak_bytes\": %lld}\n",
        JsonString(std::filesystem::path(path).filename().string()).c_str(),
        FileFormatName(e.input.format), e.input.point_cloud ? "true" : "false",
        (long long)e.input.vertex_count, (long long)e.input.face_count,
        (long long)e.input.file_bytes, (long long)e.peak_bytes);
    return absl::OkStatus();
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<FileFormat> hinted,
                           FormatFromHint(args.Value("--format").value_or("")));
  FileFormat format;
  if (hinted) {
    format = *hinted;
  } else {
    MESHSEG_ASSIGN_OR_RETURN(format, DetectFileFormat(path));
  }
  if (IsVolumeFormat(format)) return VolumeInfoOf(path, args, args.Has("--json"));
  MESHSEG_ASSIGN_OR_RETURN(const bool cloud, IsPointCloudFile(path));
  return cloud ? CloudInfo(path, format, args.Has("--json"))
               : MeshInfo(path, format, args.Has("--json"));
}

}  // namespace meshseg::cli
