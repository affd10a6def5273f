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
//
// Vertices with no points near them go onto f = 0 instead (Newton steps on
// the partition-of-unity implicit, to convergence), and from there onto the
// points if f = 0 brought them onto the sampled surface (their projection
// neighbourhood holds points). They are of two kinds: in
// occlusion gaps of a scan, where f = 0 is the surface the reconstruction
// chose; and on "tents", marching-tetrahedra triangles up to 26 mm long that
// span between two faces through the solid, where f = 0 follows the faces
// the triangles cut off. Tents are as large as the supports (flat faces fit
// one plane over many spacings), so on a dense sample they reach tens of
// spacings from the points: a fixed number of bounded Newton steps left them
// there (15 % of the refined vertices on a 1M-point sample), and the support
// step cut their faces out and patched the holes across the creases.
#ifndef MESHSEG_RECONSTRUCT_REFINE_H_
#define MESHSEG_RECONSTRUCT_REFINE_H_

#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"
#include "meshseg/run_context.h"
#include "mesh/point_index.h"
#include "reconstruct/pu_function.h"

namespace meshseg::reconstruct_internal {

// Projection steps per vertex; the second and third move a vertex by less
// than a hundredth of a spacing on the test parts.
inline constexpr int kProjectionIterations = 3;
// Newton steps onto f = 0 for the vertices far from every point, each at
// most projection_radius long, until a step moves less than
// kZeroSetTolerance × h: such a vertex sits on a marching-tetrahedra
// triangle spanning between support centres, as far from f = 0 as those
// triangles are large, which is fixed by the supports' sizes, not by h (on
// a dense sample tens of spacings). kZeroSetIterations only bounds the
// work. Below kMinGradient f is flat (no support reaches there) and the
// vertex stays.
inline constexpr int kZeroSetIterations = 100;
inline constexpr double kZeroSetTolerance = 0.01;
inline constexpr double kMinGradient = 1e-3;
// Above this many triangles the surface is remeshed at twice the edge and
// split in four (CGAL's remesher takes ~5 s for as many here, on one thread).
inline constexpr double kSerialRemeshFaces = 100'000;
// After the projection an edge longer than this many refined edge lengths
// (the remesher leaves them within 4/3) was stretched across a crease and
// is halved, round after round until none is left; a midpoint projected to
// within kStuckFraction of the half edge from an end made no progress, and
// its edges are not split again. kStretchedRounds only bounds the work:
// tents tens of spacings wide need about ten rounds (each split adds edges
// that may cross too).
inline constexpr double kStretchedEdge = 2.0;
inline constexpr int kStretchedRounds = 30;
inline constexpr double kStuckFraction = 0.5;

// Returns `mesh` with every triangle split into four at the midpoints of its
// edges: edges halve, triangle shapes and the surface stay, a closed oriented
// 2-manifold stays one. Errors: those of BuildMesh.
absl::StatusOr<Mesh> SplitInFour(const Mesh& mesh);

// Returns `mesh` remeshed and projected onto `points` (the non-outliers,
// indexed by `index`, with inward unit `normals`) with point spacing `h`, or
// onto the zero set of `f` far from them, per the refine_* parameters of
// `params`; with params.sharp_creases the creases the points show are kept
// sharp (crease.h, crease_snap.h). Sets stats->refine_edge_length,
// unsupported_vertex_count, stretched_split_count, crease_vertex_count and
// crease_snapped_count.
// Returns `mesh`
// itself (refine_edge_length 0) when the remeshed mesh is not closed (the
// remesher pinched a thin sheet). Errors: those of IsotropicRemesh.
absl::StatusOr<Mesh> RefineOnPoints(const Mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<Eigen::Vector3d>& normals,
                                    const mesh_internal::PointIndex& index, const PuFunction& f,
                                    double h, const ReconstructParams& params,
                                    const RunContext& ctx, ReconstructStats* stats);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_REFINE_H_
