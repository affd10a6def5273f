// PLY meshes: the vertex and face elements of ReadPlyData.
#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "mesh/ply_body.h"
#include "mesh/raw_mesh.h"

namespace meshseg::mesh_internal {

absl::StatusOr<RawMesh> ReadPlyMesh(std::string_view bytes, const Source& src,
                                    int64_t max_elements) {
  MESHSEG_ASSIGN_OR_RETURN(PlyData data, ReadPlyData(bytes, src, max_elements));
  if (data.vertices.empty()) return BadInput(src, "no vertices");
  if (!data.has_face_element || data.face_start.size() < 2) {
    return BadInput(src, "no faces (a point cloud, not a mesh)");
  }
  RawMesh raw;
  raw.input_vertex_count = static_cast<int64_t>(data.vertices.size());
  raw.vertices = std::move(data.vertices);
  raw.corners = std::move(data.corners);
  raw.face_start = std::move(data.face_start);
  return raw;
}

}  // namespace meshseg::mesh_internal
