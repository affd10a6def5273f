#include "proto/src/mesh_geometry_proto.h"

#include "absl/strings/str_cat.h"

namespace meshseg {
namespace {

absl::Status Bad(const std::string& what) {
  return absl::InvalidArgumentError(absl::StrCat("result mesh_geometry: ", what));
}

}  // namespace

void SetMeshGeometry(const MeshGeometry& geometry, v1::MeshGeometry* out) {
  out->mutable_vertices()->Reserve(static_cast<int>(3 * geometry.vertices.size()));
  for (const Eigen::Vector3d& p : geometry.vertices) {
    out->add_vertices(p.x());
    out->add_vertices(p.y());
    out->add_vertices(p.z());
  }
  out->mutable_faces()->Reserve(static_cast<int>(3 * geometry.faces.size()));
  for (const std::array<int, 3>& face : geometry.faces) {
    out->mutable_faces()->Add(face.begin(), face.end());
  }
  out->mutable_input_faces()->Add(geometry.input_face.begin(), geometry.input_face.end());
}

absl::StatusOr<MeshGeometry> MeshGeometryFromProto(const v1::MeshGeometry& geometry,
                                                   int64_t input_face_count) {
  if (geometry.vertices_size() % 3 != 0 || geometry.faces_size() % 3 != 0) {
    return Bad(absl::StrCat("vertices (", geometry.vertices_size(), ") and faces (",
                            geometry.faces_size(), ") must hold 3 numbers per element"));
  }
  MeshGeometry out;
  const int vertex_count = geometry.vertices_size() / 3;
  out.vertices.reserve(vertex_count);
  for (int v = 0; v < vertex_count; ++v) {
    out.vertices.emplace_back(geometry.vertices(3 * v), geometry.vertices(3 * v + 1),
                              geometry.vertices(3 * v + 2));
  }
  const int face_count = geometry.faces_size() / 3;
  out.faces.reserve(face_count);
  for (int f = 0; f < face_count; ++f) {
    std::array<int, 3> face{};
    for (int i = 0; i < 3; ++i) {
      face[i] = geometry.faces(3 * f + i);
      if (face[i] < 0 || face[i] >= vertex_count) {
        return Bad(absl::StrCat("face ", f, " has vertex id ", face[i], ", outside [0, ",
                                vertex_count, ")"));
      }
    }
    out.faces.push_back(face);
  }
  if (geometry.input_faces_size() != 0 && geometry.input_faces_size() != face_count) {
    return Bad(absl::StrCat("input_faces has ", geometry.input_faces_size(), " entries for ",
                            face_count, " faces"));
  }
  for (int f = 0; f < geometry.input_faces_size(); ++f) {
    const int input = geometry.input_faces(f);
    if (input < 0 || input >= input_face_count) {
      return Bad(absl::StrCat("face ", f, " has input face ", input, ", outside [0, ",
                              input_face_count, ")"));
    }
    out.input_face.push_back(input);
  }
  return out;
}

}  // namespace meshseg
