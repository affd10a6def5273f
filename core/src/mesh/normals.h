// Face and vertex normals of a freshly built mesh, computed in parallel.
#ifndef MESHSEG_MESH_NORMALS_H_
#define MESHSEG_MESH_NORMALS_H_

#include "meshseg/mesh.h"

namespace meshseg::mesh_internal {

// Sets every face normal (unit, right-handed) and every vertex normal (the
// normalised sum of its face normals; zero for isolated vertices). Gives the
// same values as OpenMesh's update_normals() with its default vertex normal,
// at any thread count, in a fraction of the time.
void SetNormals(TriMesh* mesh);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_NORMALS_H_
