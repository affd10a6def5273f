#include "reconstruct/surface_mesh.h"

#include "absl/strings/str_cat.h"

namespace meshseg::reconstruct_internal {

absl::StatusOr<Mesh> SurfaceMesh(const std::vector<Eigen::Vector3d>& vertices,
                                 const std::vector<std::array<int, 3>>& triangles,
                                 const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  mesh.input_vertex_count = static_cast<int64_t>(vertices.size());
  std::vector<TriMesh::VertexHandle> handle(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) {
    handle[v] =
        mesh.tri.add_vertex(TriMesh::Point(vertices[v].x(), vertices[v].y(), vertices[v].z()));
  }
  mesh.face_of_input.reserve(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const auto face = mesh.tri.add_face(handle[tri[0]], handle[tri[1]], handle[tri[2]]);
    if (!face.is_valid()) {
      return absl::InternalError(absl::StrCat("reconstruct: surface triangle ", t, " (", tri[0],
                                              ", ", tri[1], ", ", tri[2],
                                              ") makes the mesh non-manifold"));
    }
    mesh.face_of_input.push_back(face.idx());
  }
  mesh.tri.update_normals();
  return mesh;
}

}  // namespace meshseg::reconstruct_internal
