// The polygons of a mesh file as read, before the TriMesh is built, and the
// readers that produce them (one .cc per format).
#ifndef MESHSEG_MESH_RAW_MESH_H_
#define MESHSEG_MESH_RAW_MESH_H_

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "mesh/large_vector.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

struct RawMesh {
  LargeVector<Eigen::Vector3d> vertices;
  // Polygon k has corners[face_start[k] .. face_start[k+1]), 0-based indices
  // checked against vertices.size() by the reader. face_start has F+1 entries.
  LargeVector<int> corners;
  LargeVector<int64_t> face_start{0};
  int64_t input_vertex_count = 0;

  int64_t face_count() const { return static_cast<int64_t>(face_start.size()) - 1; }
};

// Each reader returns the polygons in `bytes` (the whole file) or an
// INVALID_ARGUMENT naming src.name, the problem and the line or byte offset.
// Declared counts over `max_elements` are rejected before allocating.
absl::StatusOr<RawMesh> ReadStl(std::string_view bytes, const Source& src, int64_t max_elements);
absl::StatusOr<RawMesh> ReadObj(std::string_view bytes, const Source& src, int64_t max_elements);
absl::StatusOr<RawMesh> ReadOff(std::string_view bytes, const Source& src, int64_t max_elements);
absl::StatusOr<RawMesh> ReadPlyMesh(std::string_view bytes, const Source& src,
                                    int64_t max_elements);

// Returns the mesh built from `raw` (see BuildMesh for the dropping rules).
absl::StatusOr<Mesh> BuildFromRaw(RawMesh raw, const Source& src);

// Returns an error naming the first vertex (by index) with a NaN/Inf
// coordinate, or OK.
absl::Status CheckFinite(const Source& src, const std::vector<Eigen::Vector3d>& vertices);

// Triangles as vertex-index triples, in a LargeVector.
using Triangles = LargeVector<std::array<int, 3>>;

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_RAW_MESH_H_
