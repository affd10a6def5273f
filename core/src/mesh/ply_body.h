// The vertices (with optional normals) and faces of a PLY file's body.
#ifndef MESHSEG_MESH_PLY_BODY_H_
#define MESHSEG_MESH_PLY_BODY_H_

#include <cstdint>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "mesh/large_vector.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

struct PlyData {
  LargeVector<Eigen::Vector3d> vertices;  // x y z of element "vertex"
  std::vector<Eigen::Vector3d> normals;   // nx ny nz if all three are present
  bool has_face_element = false;
  // Faces as in RawMesh: corners of face k are corners[face_start[k] ..
  // face_start[k+1]); indices checked against the vertex count.
  LargeVector<int> corners;
  LargeVector<int64_t> face_start{0};
};

// Returns the data of the PLY file `bytes` (ascii or binary). Other elements
// and properties are skipped. Errors name the line (ascii) or byte offset
// (binary): truncation, counts over max_elements or over what the file can
// hold, NaN/Inf coordinates, out-of-range indices, faces with < 3 corners.
absl::StatusOr<PlyData> ReadPlyData(std::string_view bytes, const Source& src,
                                    int64_t max_elements);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_PLY_BODY_H_
