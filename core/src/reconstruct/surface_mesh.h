// The reconstructed surface as a meshseg::Mesh.
#ifndef MESHSEG_RECONSTRUCT_SURFACE_MESH_H_
#define MESHSEG_RECONSTRUCT_SURFACE_MESH_H_

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// Returns the Mesh of `vertices` and `triangles`, every triangle kept (also
// those of zero area, which the closed surface needs), face_of_input the
// identity, normals set. Unlike BuildMesh it drops nothing: marching
// tetrahedra yields a closed manifold by construction.
// Errors: INTERNAL if OpenMesh refuses a triangle (a broken invariant).
absl::StatusOr<Mesh> SurfaceMesh(const std::vector<Eigen::Vector3d>& vertices,
                                 const std::vector<std::array<int, 3>>& triangles,
                                 const std::string& name);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SURFACE_MESH_H_
