// Line of sight for the scanner mode: whether the segment from a surface
// point to a scanner position passes through material, by sphere tracing the
// solid's implicit (Hart 1996). The CSG value is 1-Lipschitz and <= 0 on the
// solid, so it never exceeds the distance to the solid: stepping by it never
// steps over material.
#ifndef MESHSEG_GENERATE_SCAN_RAYS_H_
#define MESHSEG_GENERATE_SCAN_RAYS_H_

#include <Eigen/Core>

#include "generate/csg.h"

namespace meshseg::generate_internal {

// Steps shorter than this, in voxels, are taken as this long (a ray grazing a
// face); a ray that gets inside the solid by more than kBlockedDepth voxels is
// blocked.
inline constexpr double kMinStepVoxels = 0.02;
inline constexpr double kBlockedDepthVoxels = 1e-3;
// Sphere-tracing steps before a ray is given up as blocked.
inline constexpr int kMaxSteps = 2000;

// Returns true if the segment from `surface_point` (on the solid's boundary)
// to `eye` meets no material, apart from the first `start` model units where
// it leaves the surface. `h` is the part's voxel size.
bool LineOfSight(const Csg& solid, const Eigen::Vector3d& surface_point, const Eigen::Vector3d& eye,
                 double start, double h);

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_SCAN_RAYS_H_
