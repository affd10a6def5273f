// Welding of STL corners: corners with bit-identical coordinates become one
// vertex.
#ifndef MESHSEG_MESH_WELD_H_
#define MESHSEG_MESH_WELD_H_

#include <vector>

#include <Eigen/Core>

namespace meshseg::mesh_internal {

// Returns, for each of `corners`, the index of its vertex in `*vertices`,
// which receives the distinct positions in order of first appearance.
// -0.0 and 0.0 are the same coordinate.
std::vector<int> WeldIdentical(const std::vector<Eigen::Vector3d>& corners,
                               std::vector<Eigen::Vector3d>* vertices);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_WELD_H_
