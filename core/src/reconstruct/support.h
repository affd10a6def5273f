// Which faces of the reconstructed surface the points support (issue 38:
// "no invented surface"). Where a scan has no points (occlusion gaps, the
// side a part stood on), the implicit f (ALGORITHMS.md S3) still has a zero set:
// linear fits extrapolated from the nearest supports, which the graph cut and
// marching tetrahedra turn into flaps and tubes hanging into empty space.
//
// The test is the sampling condition itself: on a surface sampled with local
// spacing s (the mean distance of a point to its 6 nearest), every point of
// the surface lies within about s of a sample, and noise moves a sample by
// at most the off-surface band of the outlier test (outliers.h). A face is
// supported when its centroid lies within `spacings` × s(p) + band of its
// nearest input point p, s measured at p: the cloud's own density where the
// face is, not a global constant, so sparse but genuine regions (grazing
// views, far from the scanner) keep their surface.
#ifndef MESHSEG_RECONSTRUCT_SUPPORT_H_
#define MESHSEG_RECONSTRUCT_SUPPORT_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"
#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// Neighbours whose mean distance is the local spacing s (as MeanNeighborDistances).
inline constexpr int kSpacingNeighbors = 6;

// The local spacing s at input point `p` (one of `points`): the mean distance
// to its kSpacingNeighbors nearest others. `near` and `dist2` are scratch.
double SpacingAtPoint(const Eigen::Vector3d& p, const mesh_internal::PointIndex& index,
                      std::vector<uint32_t>* near, std::vector<double>* dist2);

// Returns one flag per face of `tri`: 1 when the face is supported by
// `points` (indexed by `index`, at least kSpacingNeighbors + 1 of them), see
// above; `band` in model units.
std::vector<uint8_t> SupportedFaces(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                    const mesh_internal::PointIndex& index, double spacings,
                                    double band);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SUPPORT_H_
