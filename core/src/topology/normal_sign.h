// Which way a region's fitted surface normals point: out of the solid (as
// the face normals do) or into it. Fitted planes carry an arbitrary sign and
// a hole's cylinder points its normals away from the material.
#ifndef MESHSEG_SRC_TOPOLOGY_NORMAL_SIGN_H_
#define MESHSEG_SRC_TOPOLOGY_NORMAL_SIGN_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::topology_internal {

// Returns, per region, +1 if Project()'s normals on its surface agree with
// the area-weighted face normals of its faces, -1 if they oppose, 0 for a
// region without faces.
std::vector<int> RegionNormalSigns(const TriMesh& mesh, std::span<const int> face_labels,
                                   std::span<const Region> regions);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_NORMAL_SIGN_H_
