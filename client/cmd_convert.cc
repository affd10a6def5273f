// meshseg convert IN OUT: a mesh to PLY/OFF, or a point cloud to XYZ.
#include <cstdio>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunConvert(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {}, {}, 2));
  const std::string& in = args.positional(0);
  const std::string& out = args.positional(1);
  MESHSEG_ASSIGN_OR_RETURN(const bool cloud, IsPointCloudFile(in));
  if (cloud) {
    if (std::filesystem::path(out).extension() != ".xyz") {
      return absl::InvalidArgumentError(
          absl::StrCat("\"", out, "\": a point cloud is written as .xyz"));
    }
    MESHSEG_ASSIGN_OR_RETURN(const PointCloud points, ReadPointCloud(in));
    MESHSEG_RETURN_IF_ERROR(WritePointCloud(points, out));
    std::printf("wrote %s: %zu points\n", out.c_str(), points.points.size());
    return absl::OkStatus();
  }
  MESHSEG_ASSIGN_OR_RETURN(const Mesh& mesh, ReadMesh(in));
  MESHSEG_RETURN_IF_ERROR(WriteMesh(mesh.tri, out));
  std::printf("wrote %s: %zu faces, %zu vertices\n", out.c_str(), mesh.tri.n_faces(),
              mesh.tri.n_vertices());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
