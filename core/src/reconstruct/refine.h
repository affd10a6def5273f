// The refinement step after marching tetrahedra (our addition to seed 001).
//
// Marching tetrahedra on the support centres gives a coarse mesh (edges of
// 3-10 point spacings, where the supports are large on flat faces) full of
// slivers, whose vertices sit wherever the tet edges cross f = 0. It is
// watertight but curvature estimated on it is noise: 40 % of its vertices
// look sharp, and segmenting it merged planes into cones and typed planes as
// cylinders of radius 50-700 (issue 6). This step remeshes it into
// near-equilateral triangles of about refine_edge_length spacings
// (isotropic_steps.h: split, collapse, flip, relax, each keeping the closed
// 2-manifold and its genus), projecting the vertices onto the input points
// after every round (project_to_points.h), so the result is the scan-like
// mesh the curvature and segmentation stages expect, with the same topology.
//
// Vertices with no points near them (occlusion gaps of a scan, where the cut
// closed the surface minimally) are placed by the membrane fairing of
// fair_unsupported.h between the supported rim; they are reported as filled.
//
// Written by hand rather than with CGAL's isotropic_remeshing (which the
// remesh stage uses for CAD input): that runs on one thread and took 20 s
// CPU of the 68 s for a million points, and its output went through a mesh
// builder that drops degenerate triangles, which left open edges.
#ifndef MESHSEG_RECONSTRUCT_REFINE_H_
#define MESHSEG_RECONSTRUCT_REFINE_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"
#include "meshseg/run_context.h"
#include "reconstruct/point_index.h"
#include "reconstruct/project_to_points.h"

namespace meshseg::reconstruct_internal {

// Rounds of split / collapse / flip / relax / project; the last rounds move
// vertices by a few hundredths of a spacing on the test parts.
inline constexpr int kRemeshRounds = 4;
// Projection steps per vertex after the last round.
inline constexpr int kProjectionIterations = 2;

struct RefinedSurface {
  TriMesh mesh;
  // Per vertex: 1 if no points lie near it (placed by fairing, not projected).
  std::vector<uint8_t> unsupported;
};

// Returns `coarse` remeshed at edge length params.refine_edge_length × h
// (raised to keep at most params.refine_max_faces triangles) and projected
// onto the non-outlier points `surface`. Sets
// stats->refine_edge_length and unsupported_vertex_count. The mesh is a
// closed 2-manifold like `coarse`, with no zero-area triangle.
// Errors: INTERNAL if a zero-area triangle cannot be removed; CANCELLED on stop.
absl::StatusOr<RefinedSurface> RefineOnPoints(const TriMesh& coarse,
                                              const SampledSurface& surface,
                                              const ReconstructParams& params,
                                              const RunContext& ctx, ReconstructStats* stats);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_REFINE_H_
