// The mesh a result's vertex, curve, loop and corner ids refer to, copied
// out for the result (PipelineParams::include_mesh), with the input face
// each of its faces came from.
#ifndef MESHSEG_PIPELINE_MESH_GEOMETRY_H_
#define MESHSEG_PIPELINE_MESH_GEOMETRY_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"

namespace meshseg::pipeline_internal {

// Returns the vertices and faces of `mesh`, and, when `face_of_input` is
// not empty, the input face of every mesh face: the mesh holds the kept
// triangles in input order, and face_of_input[k] is the first triangle of
// input face k (-1: dropped), so mesh face f came from the last input face
// whose first triangle is at or before f.
MeshGeometry GeometryOf(const TriMesh& mesh, std::span<const int> face_of_input);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_MESH_GEOMETRY_H_
