// File: segment.h
// -----------------------------------------------------------------------------
// The `segment` stage: splits a mesh into regions that each follow one
// analytic surface. Seed 000 (region growing with the height function then
// the quadric, type decision by the alpha test, graph merging) with seed 002's
// improvements (labelled seeds incl. torus histogram, fast linear fits from
// smoothed normals, leftover absorption with stepped thresholds, face labels).
// One criterion, two data terms. Exact tessellations (CAD exports, whose
// vertices a modeller computed on the B-rep's surfaces) are segmented facet
// by facet under the same energy as noisy meshes (below), with its data
// term in the limit of no noise: a facet lies on a surface (cost 0) iff its
// corners lie on it to the rounding of the file's numbers and its plane is
// a chord plane of it, else it cannot be that surface's (cost infinite).
// What remains is the same label cost per surface, minimised as facility
// location is, by a greedy set cover: hypotheses fitted exactly to small
// facet groups and grown over the facets of cost 0, each taken in order of
// least label cost per corner it newly explains, FREEFORM regions for the
// faces no analytic type explains (the outliers), and regions on one
// surface one label (core/src/segment/exact_facets.h, energy.h). Whether a
// mesh is exact is measured (EstimateExactness), never assumed.
// Our additions, for noisy scans: the noise and tolerances are estimated
// from the data; on a noisy mesh, flat seeds grow as planes before seed
// 000's loop. Seeds 000/002's growing is the proposal mechanism; labels,
// types and merges are then decided by one energy (PEARL multi-model
// fitting with label costs, core/src/segment/energy.h): squared distances
// to each region's surface in units of the noise, a boundary cost per
// mesh edge (cheap along creases), and a BIC label cost per surface, with
// the evidence discounted where residuals are correlated (binary voxels,
// chords). Boundaries are placed by alpha-expansion with the surfaces
// re-estimated between sweeps; merges, drops, retypes and planes split off
// a curved region are each proposed and kept iff the energy falls (a
// retype a band's interior proposes, priced together with the expansion
// it enables). Eight steps: grow; absorb; evidence share; merge; expand;
// improve (the moves alternated with the expansion until none lowers the
// energy); split off planes; improve (core/src/segment/segment.cc lists
// them with their principle). Each surface is reported as fitted to its
// region's inliers.
//
// In: a Mesh and its CurvatureField. Out: Segmentation with a label per mesh
// face and vertex and one Region per label.
#ifndef MESHSEG_SEGMENT_H_
#define MESHSEG_SEGMENT_H_

#include <cstdint>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/curvature.h"
#include "meshseg/fit.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"
#include "meshseg/surface.h"

namespace meshseg {

// Which path segments a mesh.
enum class ExactMode {
  kAuto,    // facet by facet when EstimateExactness() says the mesh is exact
  kAlways,  // facet by facet
  kNever,   // the scan path (seeds 000/002)
};

struct SegmentParams {
  // Max vertex-to-surface distance th_dis, in l_avg. Seed 000 eq. (5).
  double distance_tolerance = 0.5;
  // Max angle th_nm between vertex normal and surface normal, degrees.
  // Seed 000 eq. (6) uses 5 for CT meshes; unset = derived from the
  // estimated noise level of the mesh.
  std::optional<double> angle_tolerance_deg;
  // Fraction alpha of region vertices that must fit for a type to be
  // accepted. Seed 000 §3 step 3.
  double alpha = 0.9;
  // Randomness (tie breaking) comes from here, never a global RNG.
  uint64_t seed = 0;
  // Facet by facet or the scan path (ExactMode).
  ExactMode exact = ExactMode::kAuto;
  // Distance within which a vertex of an exact tessellation lies on its
  // surface, model units; unset = from the rounding of the coordinates
  // (core/src/segment/exact_tolerance.h).
  std::optional<double> exact_tolerance;
  // The mesh's vertices lie on the flat facets of a CAD tessellation (the
  // pipeline sets this for its isotropic remesh of one: remesh.h). On a
  // curved face they sit on chords under the surface, up to the facets'
  // sagitta, so no type fits them at the noise; the curved types are told
  // apart by how closely they fit all of a region's vertices instead.
  bool on_facets = false;
  // One flag per mesh vertex: 1 if the vertex is measured, 0 if it lies on
  // an area no input point supports (a patch a reconstruction closed, all
  // of whose faces Reconstruction::is_filled flags). Such a vertex is no
  // evidence of any surface: it costs nothing under any label, no surface
  // is fitted to it, no label is counted on it and no seed is made on it; it
  // still takes a label, its neighbours' (the boundary term). Empty: every
  // vertex is measured (a mesh as read).
  std::vector<uint8_t> measured;
  // The noise sigma of the points the mesh's vertices were projected onto,
  // model units, for a mesh reconstructed from a point cloud (the pipeline
  // passes Reconstruction's noise). If above 0, the data term weighs a
  // residual in units of the vertices' own scatter (the points' noise
  // averaged by the projection), not of the mesh's resolution (energy.h,
  // "Data unit"). Unset: a mesh as read, whose th_dis sets the unit.
  std::optional<double> point_noise;
};

struct Region {
  int id = 0;
  SurfaceType type = SurfaceType::kQuadric;
  Surface surface;
  int64_t face_count = 0;
  int64_t vertex_count = 0;
  double area = 0.0;
  double rms_distance = 0.0;
  double max_distance = 0.0;
  // Index into Segmentation::surfaces of the surface this region lies on;
  // regions on one surface (coplanar faces, pieces of one cylinder) share it.
  int surface_id = -1;
};

// One surface of the part: the regions on it and their joint fit.
struct SharedSurface {
  int id = 0;
  SurfaceType type = SurfaceType::kPlane;
  Surface surface;           // fitted to all its regions' vertices together
  std::vector<int> regions;  // region ids, ascending
  double rms_distance = 0.0;  // of the regions' vertices to `surface`
  double max_distance = 0.0;
};

// The path a mesh was segmented on.
enum class SegmentationPath {
  kScan,         // seeds 000/002 on the mesh as read
  kExactFacets,  // facet by facet (exact tessellation)
  kRemeshed,     // seeds 000/002 on an isotropic remesh (set by the pipeline)
};

// What the stage measured of the mesh and the thresholds it derived.
struct SegmentEstimates {
  double mean_edge_length = 0.0;     // l_avg
  double noise_sigma = 0.0;          // estimated normal-direction noise, model units
  double distance_tolerance = 0.0;   // th_dis used, model units
  double angle_tolerance_deg = 0.0;  // th_nm used
  double sharp_threshold = 0.0;      // th_sv used (seed 000 §2), in l_i,avg
  SegmentationPath path = SegmentationPath::kScan;
  // The exact-facet tolerance tau, model units, and the share of the facet
  // area it explains locally (EstimateExactness); 0 when not measured.
  double exact_tolerance = 0.0;
  double exact_share = 0.0;
};

// How exact a tessellation is: its tolerance tau and the share of its facet
// area (a sample of facets) that lies exactly in a plane with a neighbour or
// on a curved surface fitted to the facets around it.
struct Exactness {
  double tolerance = 0.0;  // model units
  double share = 0.0;      // in [0, 1]
  // The sag of a facet of the mesh's mean edge on a sphere as wide as the
  // part (its bounding-box diagonal), in tolerances (kMinResolvedSag).
  double resolved_sag = 0.0;
  bool exact = false;  // share >= kMinExactShare and resolved_sag >= kMinResolvedSag
};
// A scan's facets miss every surface by its noise (share 0); a CAD export's
// each lie on the surface of their face (measured on the 18 labelled CAD
// meshes of shared/data: 0.989-1.0); a noise-free voxel surface (the
// generated parts: marching cubes with vertices on the surfaces) has facets
// cutting across every edge between its surfaces (0.93-0.97 at the default
// voxel sizes).
inline constexpr double kMinExactShare = 0.98;
// The exact path types a face by how its facets bend, so it needs the
// bending to stand above the tolerance: a face that curves by less than tau
// over a facet is a plane to it, and any type fits a few of its facets. A
// part's faces curve at radii up to its own size; where the facets sag by
// less than tau on such a radius (a dense mesh whose coordinates carry few
// digits), its gently curved faces would come out as sprays of planes and
// small cylinders, and the share above says nothing (every facet has a
// neighbour "in its plane"). Such a mesh takes the scan path, which fits
// surfaces over many facets. Measured (resolved_sag): the 18 labelled CAD
// meshes and the CAD exports of shared/data 20-8000, fandisk.off (6
// significant digits, 13K facets) 0.24.
inline constexpr double kMinResolvedSag = 1.0;

struct Segmentation {
  std::vector<int> face_labels;    // one per mesh face; region id or -1
  std::vector<int> vertex_labels;  // one per mesh vertex; region id or -1
  std::vector<Region> regions;     // regions[k].id == k
  SegmentEstimates estimates;
  // surfaces[k].id == k; every region's surface_id indexes it. On the scan
  // path each region is a surface of its own.
  std::vector<SharedSurface> surfaces;
};

// Returns the segmentation of `mesh`: facet by facet if params.exact says
// so (kAuto: if EstimateExactness(mesh).exact), else by seeds 000/002.
// Errors: INVALID_ARGUMENT for bad params or a mesh without faces;
// CANCELLED when ctx requests a stop.
absl::StatusOr<Segmentation> Segment(const Mesh& mesh, const CurvatureField& curvature,
                                     const SegmentParams& params = {},
                                     const RunContext& ctx = {});

// The same, with `mean_edge_length` = MeanEdgeLength(mesh.tri) already
// measured (MeshStats::mean_edge_length of this mesh), so it is not summed
// again: the same segmentation bit for bit when the value is that one.
// Errors: also INVALID_ARGUMENT for a mean_edge_length not finite and > 0.
absl::StatusOr<Segmentation> Segment(const Mesh& mesh, const CurvatureField& curvature,
                                     double mean_edge_length, const SegmentParams& params = {},
                                     const RunContext& ctx = {});

// Returns how exact `mesh` is (Exactness), with `tolerance` (model units)
// if given, else the tolerance from the rounding of its coordinates.
Exactness EstimateExactness(const Mesh& mesh, std::optional<double> tolerance = std::nullopt);

// Returns the facet-by-facet segmentation of `mesh` (the exact path above;
// curvature is not needed). estimates.path is kExactFacets; exact_share is
// left 0 (EstimateExactness measures it).
// Errors: INVALID_ARGUMENT for bad params or a mesh without faces;
// CANCELLED when ctx requests a stop.
absl::StatusOr<Segmentation> SegmentExactFacets(const Mesh& mesh, const SegmentParams& params = {},
                                                const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_SEGMENT_H_
