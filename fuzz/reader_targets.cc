// The reader targets: bytes in, a mesh or point cloud or a clean error out.
#include <cmath>
#include <string>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "fuzz/check.h"
#include "fuzz/reader_targets.h"
#include "fuzz/volume_targets.h"
#include "mesh/file_format.h"
#include "mesh/ply_body.h"
#include "mesh/point_cloud_readers.h"
#include "mesh/raw_mesh.h"

namespace meshseg::fuzz {
namespace {

using mesh_internal::RawMesh;
using mesh_internal::Source;

// The bound ReadMesh applies by default: the fuzzer exercises the limit the
// service runs with, not a smaller one of its own.
const int64_t kMaxElements = ReadMeshOptions().max_elements;

// A reader's error must be INVALID_ARGUMENT, start with `<op>: "<name>": `
// and stay short (a message quotes a token, never the input).
void CheckCleanError(const absl::Status& status, const Source& src) {
  const std::string message(status.message());
  Check(status.code() == absl::StatusCode::kInvalidArgument, "error code is INVALID_ARGUMENT",
        status.ToString());
  Check(absl::StartsWith(message, absl::StrCat(std::string(src.op), ": \"", src.name, "\": ")),
        "error names the operation and the file", message);
  Check(message.size() < 512, "error message is short", message);
}

bool Finite(const Eigen::Vector3d& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// Builds the mesh of `raw` as ReadMesh does and checks what it holds.
void CheckMesh(absl::StatusOr<RawMesh> raw, const Source& src) {
  if (!raw.ok()) return CheckCleanError(raw.status(), src);
  const int64_t input_faces = raw->face_count();
  const int64_t input_vertices = raw->input_vertex_count;
  const absl::StatusOr<Mesh> mesh = mesh_internal::BuildFromRaw(*std::move(raw), src);
  if (!mesh.ok()) return CheckCleanError(mesh.status(), src);
  const int64_t faces = static_cast<int64_t>(mesh->tri.n_faces());
  Check(faces > 0, "a mesh read without error has faces");
  Check(static_cast<int64_t>(mesh->face_of_input.size()) == input_faces,
        "one face_of_input entry per input face");
  for (const int f : mesh->face_of_input) {
    Check(f >= -1 && f < faces, "face_of_input entries are -1 or a mesh face",
          absl::StrCat(f, " of ", faces));
  }
  Check(mesh->input_vertex_count == input_vertices, "input vertex count kept");
  for (const auto v : mesh->tri.vertices()) {
    Check(Finite(ToEigen(mesh->tri.point(v))), "vertices are finite");
  }
  for (const auto f : mesh->tri.faces()) {
    Check(mesh->tri.valence(f) == 3, "faces are triangles");
  }
}

// Finishes a point cloud as ReadPointCloud does and checks what it holds.
void CheckCloud(absl::StatusOr<PointCloud> cloud, const Source& src) {
  if (cloud.ok()) {
    const absl::Status normalized = mesh_internal::NormalizeNormals(src, &*cloud);
    if (!normalized.ok()) cloud = normalized;
  }
  if (!cloud.ok()) return CheckCleanError(cloud.status(), src);
  Check(!cloud->points.empty(), "a cloud read without error has points");
  Check(cloud->normals.empty() || cloud->normals.size() == cloud->points.size(),
        "no normals or one per point");
  for (const Eigen::Vector3d& p : cloud->points) Check(Finite(p), "points are finite");
  for (const Eigen::Vector3d& n : cloud->normals) {
    Check(std::abs(n.norm() - 1.0) < 1e-9, "normals are unit length after normalisation");
  }
}

absl::StatusOr<PointCloud> PlyCloud(std::string_view bytes, const Source& src) {
  absl::StatusOr<mesh_internal::PlyData> data = mesh_internal::ReadPlyData(bytes, src, kMaxElements);
  if (!data.ok()) return data.status();
  if (data->vertices.empty()) return mesh_internal::BadInput(src, "no points");
  PointCloud cloud;
  cloud.points.assign(data->vertices.begin(), data->vertices.end());
  cloud.normals = std::move(data->normals);
  return cloud;
}

}  // namespace

void FuzzMeshReader(FileFormat format, std::string_view bytes) {
  if (bytes.empty()) return;  // refused by OpenInput before any reader runs
  const Source src{"read_mesh", absl::StrCat("fuzz.", FileFormatName(format))};
  switch (format) {
    case FileFormat::kStl: return CheckMesh(mesh_internal::ReadStl(bytes, src, kMaxElements), src);
    case FileFormat::kObj: return CheckMesh(mesh_internal::ReadObj(bytes, src, kMaxElements), src);
    case FileFormat::kOff: return CheckMesh(mesh_internal::ReadOff(bytes, src, kMaxElements), src);
    case FileFormat::kPly:
      return CheckMesh(mesh_internal::ReadPlyMesh(bytes, src, kMaxElements), src);
    default: break;
  }
  Check(false, "FuzzMeshReader called with a point-cloud format", FileFormatName(format));
}

void FuzzCloudReader(FileFormat format, std::string_view bytes) {
  if (bytes.empty()) return;
  const Source src{"read_point_cloud", absl::StrCat("fuzz.", FileFormatName(format))};
  switch (format) {
    case FileFormat::kXyz: return CheckCloud(mesh_internal::ReadXyz(bytes, src, kMaxElements), src);
    case FileFormat::kPwn: return CheckCloud(mesh_internal::ReadPwn(bytes, src, kMaxElements), src);
    case FileFormat::kPly: return CheckCloud(PlyCloud(bytes, src), src);
    default: break;
  }
  Check(false, "FuzzCloudReader called with a mesh-only format", FileFormatName(format));
}

void FuzzSniffedFile(std::string_view bytes) {
  if (bytes.empty()) return;
  // An upload without an extension: the format comes from the content alone.
  const FileFormat format =
      mesh_internal::FormatOf("upload", bytes.substr(0, 4096), static_cast<int64_t>(bytes.size()));
  switch (format) {
    case FileFormat::kUnknown: return;
    case FileFormat::kXyz:
    case FileFormat::kPwn: return FuzzCloudReader(format, bytes);
    case FileFormat::kPly: FuzzCloudReader(format, bytes); return FuzzMeshReader(format, bytes);
    case FileFormat::kNrrd:
    case FileFormat::kMha:
    case FileFormat::kMhd:
    case FileFormat::kRaw: return FuzzVolumeFile(format, bytes);
    default: return FuzzMeshReader(format, bytes);
  }
}

}  // namespace meshseg::fuzz
