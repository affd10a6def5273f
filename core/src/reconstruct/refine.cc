#include "reconstruct/refine.h"

#include <algorithm>
#include <cmath>

#include "meshseg/remesh.h"
#include "meshseg/status_macros.h"
#include "reconstruct/project_to_points.h"

namespace meshseg::reconstruct_internal {

absl::StatusOr<Mesh> RefineOnPoints(const Mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                    const PointIndex& index, double h,
                                    const ReconstructParams& params, const RunContext& ctx,
                                    ReconstructStats* stats) {
  // An equilateral triangle of edge l has area (√3/4) l²: the edge at which
  // the surface holds refine_max_faces of them.
  const double area = Assess(mesh).surface_area;
  const double capped = std::sqrt(4.0 * area / (std::sqrt(3.0) * params.refine_max_faces));
  stats->refine_edge_length = std::max(params.refine_edge_length * h, capped);
  RemeshParams remesh;
  remesh.feature_angle_deg = 180.0;  // no feature edges, see refine.h
  MESHSEG_ASSIGN_OR_RETURN(Mesh fine,
                           IsotropicRemesh(mesh, stats->refine_edge_length, remesh, ctx));
  ProjectToPoints(points, index, params.projection_radius * h, kProjectionIterations, &fine.tri);
  return fine;
}

}  // namespace meshseg::reconstruct_internal
