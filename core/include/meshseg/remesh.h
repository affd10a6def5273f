// File: remesh.h
// -----------------------------------------------------------------------------
// Isotropic remeshing of CAD tessellations before segmentation.
//
// Meshes exported from CAD put a few long, thin triangles on every plane and
// fans of slivers on every cylinder; edge lengths vary by two orders of
// magnitude. The curvature and segmentation stages (seeds 000/002) assume a
// scan-like mesh whose edges are all about l_avg long: on a CAD tessellation
// the neighbourhood radius of a plane vertex spans whole holes, and every
// vertex of a small cylinder looks sharp. Rather than bend those stages, the
// pipeline remeshes such inputs into near-equilateral triangles (CGAL's
// isotropic_remeshing, vertices projected back onto the input surface,
// feature edges kept), segments the remeshed surface, and maps the labels back
// to the input faces (pipeline/remeshed_labels.h).
//
// Scan-like meshes (marching cubes, laser scans, reconstructed clouds) are
// left alone: `Assess` tells them apart from the shape of their triangles.
#ifndef MESHSEG_REMESH_H_
#define MESHSEG_REMESH_H_

#include <cstdint>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"

namespace meshseg {

enum class RemeshMode {
  kAuto,    // remesh when Assess() finds a CAD-like tessellation
  kAlways,  // remesh every mesh
  kNever,   // segment the input as it is
};

struct RemeshParams {
  RemeshMode mode = RemeshMode::kAuto;
  // Target edge length; 0 = derived from the mesh (Assess().target_edge_length).
  double target_edge_length = 0.0;
  // kAuto remeshes when more than this share of the surface area lies in
  // triangles whose longest edge exceeds kThinAspect times their height over
  // it. Measured: marching cubes (test_piece, 1M faces) 1.0 %, the scans and
  // fine meshes of shared/data 0-0.4 %; the CAD STL/PLY exports there 6.8 %
  // (tray_bottom_1002), 30.8 % (plate_holes), 93.2 % (abc_00016513_gt).
  double thin_area_fraction = 0.05;
  // Edges whose dihedral angle exceeds this are feature edges: kept as
  // constrained polylines (split, never flipped or moved off the line).
  double feature_angle_deg = 30.0;
  // CGAL's split/collapse/flip/relax rounds.
  int iterations = 3;
  // The target length is raised if the remeshed surface would have more
  // triangles than this. CGAL's remeshing runs on one thread, 5-20 s for
  // 150K triangles here (bench/remesh).
  int64_t max_faces = 150'000;
  // Curved surfaces of a radius under this many target edge lengths (small
  // holes, slots, fillets) are remeshed again, finer; 0 = never. At 2 edges
  // per radius the curvature fits of seed 000 span a hole and its wall is
  // lost (plate_holes.stl: r 3.38 at edges of 1.66); at 3.8 the fillets of
  // the same part are found.
  double small_radius_edges = 3.0;
  // ... at an edge length of their radius over this: 25 edges around a hole.
  double fine_edges_per_radius = 4.0;
};

// What IsotropicRemesh did besides the uniform pass.
struct RemeshStats {
  // Radius of the smallest curved features of the input (5th percentile of
  // the estimates on edges under RemeshParams::small_radius_edges target
  // edges); 0 = none.
  double small_feature_radius = 0.0;
  // Edge length the surface around them was remeshed at; 0 = not refined.
  double fine_edge_length = 0.0;
};

// What the triangles of a mesh look like.
struct TessellationShape {
  double surface_area = 0.0;
  // Share of the area in triangles with aspect (longest edge / height on it)
  // above kThinAspect.
  double thin_area_fraction = 0.0;
  // Median over faces of the shortest edge: the scale the tessellation
  // resolves (chords of the smallest curved surfaces on a CAD export).
  double median_shortest_edge = 0.0;
  // Edge length for remeshing: the median shortest edge, raised so the
  // remeshed surface stays under RemeshParams::max_faces.
  double target_edge_length = 0.0;
  bool cad_like = false;  // thin_area_fraction over the params' limit
  // CAD-like, and max_faces raises the remesh's edges over
  // kMaxRemeshCoarsening times the median shortest edge: the remesh would
  // lose what the export resolves. tray_bottom_1002.stl: edges 1.86 against
  // 0.44, walls of 3.175 and holes of radius 1.13. The pipeline segments
  // such an input facet by facet instead (SegmentParams::exact_facets).
  bool too_fine_to_remesh = false;
};

inline constexpr double kThinAspect = 6.0;
inline constexpr double kMaxRemeshCoarsening = 2.0;
// The surface within kZoneMargin target edges of a small feature is refined,
// to no less than the target over kMaxRefinement; a refinement by less than
// kMinRefinement is not worth a second pass.
inline constexpr double kZoneMargin = 2.0;
inline constexpr double kMaxRefinement = 4.0;
inline constexpr double kMinRefinement = 1.5;
inline constexpr double kFineFaceShare = 0.25;  // of RemeshParams::max_faces

// Returns the shape statistics of `mesh` and the remeshing decision.
TessellationShape Assess(const Mesh& mesh, const RemeshParams& params = {});

// Returns an isotropic remesh of `mesh` with edges of about
// `target_edge_length` (> 0): near-equilateral triangles whose vertices lie on
// the input surface; edges sharper than params.feature_angle_deg are kept as
// polylines. Around small curved features (RemeshParams::small_radius_edges)
// a second pass remeshes finer; `stats`, if given, says how. face_of_input of
// the result indexes the remesh's own triangles, not the input's faces: map
// labels back by position. Reports progress as "remesh".
// Errors: INVALID_ARGUMENT for a non-positive target or a mesh without faces;
// INTERNAL if the remeshed surface cannot be rebuilt; CANCELLED on stop.
absl::StatusOr<Mesh> IsotropicRemesh(const Mesh& mesh, double target_edge_length,
                                     const RemeshParams& params = {},
                                     const RunContext& ctx = {},
                                     RemeshStats* stats = nullptr);

}  // namespace meshseg

#endif  // MESHSEG_REMESH_H_
