#include "pipeline/mesh_geometry.h"

#include <array>
#include <cassert>
#include <cstddef>

namespace meshseg::pipeline_internal {

MeshGeometry GeometryOf(const TriMesh& mesh, std::span<const int> face_of_input) {
  MeshGeometry g;
  g.vertices.reserve(mesh.n_vertices());
  for (const TriMesh::VertexHandle v : mesh.all_vertices()) {
    g.vertices.push_back(ToEigen(mesh.point(v)));
  }
  g.faces.reserve(mesh.n_faces());
  for (const TriMesh::FaceHandle f : mesh.all_faces()) {
    std::array<int, 3> corners{};
    int i = 0;
    for (const TriMesh::VertexHandle v : mesh.fv_range(f)) corners[i++] = v.idx();
    g.faces.push_back(corners);
  }
  if (face_of_input.empty()) return g;
  g.input_face.assign(mesh.n_faces(), -1);
  int current = -1;  // the input face the faces being walked came from
  std::size_t next = 0;
  for (std::size_t f = 0; f < g.input_face.size(); ++f) {
    // Advance to the last input face whose first triangle is at or before f.
    while (next < face_of_input.size() &&
           (face_of_input[next] < 0 || static_cast<std::size_t>(face_of_input[next]) <= f)) {
      if (face_of_input[next] >= 0) current = static_cast<int>(next);
      ++next;
    }
    assert(current >= 0 && "a mesh face precedes every input face's first triangle");
    g.input_face[f] = current;
  }
  return g;
}

}  // namespace meshseg::pipeline_internal
