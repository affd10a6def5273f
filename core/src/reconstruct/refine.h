// The refinement step after marching tetrahedra (our addition to seed 001).
//
// Marching tetrahedra on the support centres gives a coarse mesh (edges of
// 3-4 point spacings on the test parts) full of slivers, whose vertices sit
// wherever the tet edges cross f = 0. It is watertight and within half a
// spacing of the surface, but curvature estimated on it is noise: 40 % of its
// vertices look sharp, and segmenting it merged planes into cones and typed
// planes as cylinders of radius 50-700 (issue 6). This step remeshes it into
// near-equilateral triangles of about refine_edge_length spacings (CGAL,
// meshseg/remesh.h; no feature edges: the sharp dihedral angles of the
// marching-tetrahedra mesh are slivers, not features), then moves every vertex
// onto the input points (project_to_points.h). The result is the scan-like
// mesh the curvature and segmentation stages expect, with the same topology.
#ifndef MESHSEG_RECONSTRUCT_REFINE_H_
#define MESHSEG_RECONSTRUCT_REFINE_H_

#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"
#include "meshseg/run_context.h"
#include "reconstruct/point_index.h"

namespace meshseg::reconstruct_internal {

// Projection steps per vertex; the second and third move a vertex by less
// than a hundredth of a spacing on the test parts.
inline constexpr int kProjectionIterations = 3;

// Returns `mesh` remeshed and projected onto `points` (the non-outliers,
// indexed by `index`) with point spacing `h`, per the refine_* parameters of
// `params`; sets stats->refine_edge_length. Errors: those of IsotropicRemesh.
absl::StatusOr<Mesh> RefineOnPoints(const Mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                    const PointIndex& index, double h,
                                    const ReconstructParams& params, const RunContext& ctx,
                                    ReconstructStats* stats);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_REFINE_H_
