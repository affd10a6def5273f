// The mesh a result's ids refer to (PipelineResult::mesh_geometry) to and
// from the result message's flat arrays (v1::MeshGeometry).
#ifndef MESHSEG_PROTO_SRC_MESH_GEOMETRY_PROTO_H_
#define MESHSEG_PROTO_SRC_MESH_GEOMETRY_PROTO_H_

#include <cstdint>

#include "absl/status/statusor.h"
#include "meshseg/pipeline.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Writes `geometry` into `out`: x, y, z per vertex, three ids per face, the
// input face per face.
void SetMeshGeometry(const MeshGeometry& geometry, v1::MeshGeometry* out);

// Returns the core form of `geometry`; `input_face_count` is the number of
// input faces (the result's face_labels) its input_faces index.
// Errors (INVALID_ARGUMENT, naming the array, the index and the bound): an
// array whose length is not a multiple of 3, a vertex id outside the
// vertices, input_faces not one per face or outside [0, input_face_count).
absl::StatusOr<MeshGeometry> MeshGeometryFromProto(const v1::MeshGeometry& geometry,
                                                   int64_t input_face_count);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_SRC_MESH_GEOMETRY_PROTO_H_
