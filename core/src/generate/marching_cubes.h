// Marching cubes over a solid given as a CSG implicit. The solid is sampled on
// the grid slice by slice (oneTBB over rows; far-away tiles are filled from
// one sample, as the implicit is 1-Lipschitz). A vertex per crossing grid
// edge sits at the exact crossing of the edge with the solid's boundary
// (root finding on the implicit), kept at least kMinEdgeFraction of the edge
// away from grid points and then projected onto the active analytic surface,
// so the noise-free mesh lies on the true surfaces. Vertices are shared per
// grid edge: the mesh is indexed, closed and manifold.
#ifndef MESHSEG_GENERATE_MARCHING_CUBES_H_
#define MESHSEG_GENERATE_MARCHING_CUBES_H_

#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "generate/csg.h"
#include "meshseg/generate.h"
#include "meshseg/run_context.h"

namespace meshseg::generate_internal {

// Grid point (i, j, k) sits at origin + h (i, j, k), 0 <= i < nx etc.
struct Grid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double h = 1.0;
  int nx = 0, ny = 0, nz = 0;

  Eigen::Vector3d Point(double i, double j, double k) const {
    return origin + h * Eigen::Vector3d(i, j, k);
  }
};

// Returns the grid part `name` is sampled on at params.voxel_size (0 = the
// part's default). Errors: as GeneratePart's parameter and size checks.
absl::StatusOr<Grid> PartGrid(std::string_view name, const GenerateParams& params);

// Keeps vertices this fraction of a grid edge away from its ends, so no two
// vertices of a cube coincide (no zero-area triangles).
inline constexpr double kMinEdgeFraction = 0.02;

struct RawSurface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> vertex_leaf;  // per vertex: the active leaf of the solid there
  std::vector<std::array<int, 3>> triangles;  // normals point out of the solid
};

// Returns the boundary of `solid` on `grid`; the solid must stay clear of the
// grid's outer layer of points. Errors: CANCELLED on stop.
absl::StatusOr<RawSurface> MarchingCubes(const Csg& solid, const Grid& grid,
                                         const RunContext& ctx);

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_MARCHING_CUBES_H_
