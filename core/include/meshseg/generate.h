// File: generate.h
// -----------------------------------------------------------------------------
// CT-like test parts with ground truth. A part is a solid built from analytic
// primitives (boxes/planes, cylinders, cones, spheres, tori; union and
// difference; tangent fillets), sampled on a voxel grid of size h, turned into
// a triangle mesh by marching cubes, optionally with Gaussian noise along the
// vertex normals. Every face records the primitive it lies on and every
// primitive its exact parameters, so accuracy tests have an answer key.
#ifndef MESHSEG_GENERATE_H_
#define MESHSEG_GENERATE_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/run_context.h"
#include "meshseg/surface.h"
#include "meshseg/voxel.h"

namespace meshseg {

struct GenerateParams {
  // Voxel size h in model units (mm); 0 = the part's own default.
  double voxel_size = 0.0;
  // Standard deviation of the noise along vertex normals, in multiples of h.
  double noise = 0.0;
  // Seed of the noise; the same seed gives the same mesh.
  uint64_t seed = 1;
};

// One analytic face of the part's boundary.
struct PrimitiveTruth {
  int id = 0;
  std::string name;  // e.g. "bore", "boss_fillet"
  Surface surface;
  // CAD mode: a B-rep face of no analytic type (B-spline, offset, ...);
  // `surface` is then an empty Quadric and the JSON type is "freeform".
  bool freeform = false;
};

struct GeneratedPart {
  std::string name;
  Mesh mesh;
  double voxel_size = 0.0;  // h actually used
  double noise = 0.0;       // noise sigma used, model units
  std::vector<PrimitiveTruth> primitives;  // primitives[k].id == k
  // One per mesh face: the id of the primitive the face lies on, or -1.
  std::vector<int> face_primitive;
  // One per mesh face: 1 if the face lies within one voxel of a boundary
  // between primitives (accuracy metrics may exclude these).
  std::vector<uint8_t> face_near_boundary;
  // One per mesh vertex: the primitive the noise-free vertex lies on (its
  // distance to that surface is below 1e-9 h before noise).
  std::vector<int> vertex_primitive;
};

// Names of the parts GeneratePart knows, smallest first.
std::vector<std::string> PartNames();

// Returns the part `name`.
// Errors: INVALID_ARGUMENT for an unknown name, voxel_size < 0 or a grid over
// the size limit, noise < 0; CANCELLED on stop.
absl::StatusOr<GeneratedPart> GeneratePart(std::string_view name,
                                           const GenerateParams& params = {},
                                           const RunContext& ctx = {});

// Returns the part sampled on its voxel grid as a CT volume (uint16, the
// mesh's grid: origin and spacing h). Grey: air 1000, material 3000, with a
// linear partial-volume ramp over 2 h across the surface (so interpolation
// between two samples next to the surface finds it) and Gaussian noise of
// params.noise h along the normals turned into grey values (sigma = noise *
// 1000). Binary: 1 for grid points inside the solid, else 0 (a thresholded
// scan). Errors: as GeneratePart.
absl::StatusOr<VolumeData> GenerateVolume(std::string_view name, bool binary,
                                          const GenerateParams& params = {},
                                          const RunContext& ctx = {});

// Returns `mesh` (any surface of part `name` at voxel size params.voxel_size,
// e.g. extracted from its volume) with the part's ground truth: primitives,
// face_primitive, face_near_boundary and vertex_primitive as GeneratePart
// gives them, from the solid's active surface at each vertex.
// Errors: INVALID_ARGUMENT for an unknown name.
absl::StatusOr<GeneratedPart> LabelWithGroundTruth(std::string_view name, const Mesh& mesh,
                                                   const GenerateParams& params = {});

// CAD mode: the part built as an exact B-rep with OpenCASCADE (primitives,
// booleans, fillets, chamfers) and tessellated as CAD systems export STL
// (BRepMesh_IncrementalMesh with a chordal and an angular deflection), so
// every vertex lies on the B-rep's surfaces and facets are long and thin.
// Each B-rep face is one primitive (its surface from the face's own geometry,
// BRepAdaptor_Surface); faces on one surface (a bore split by a groove, the
// patches of a chamfer cut by flats) stay separate primitives with equal
// surfaces, as in a B-rep.
enum class CadDeflection {
  // Chordal deflection 2e-3 of the bounding-box diagonal, angular 30 degrees
  // (a CAD system's "coarse" STL export).
  kCoarse,
  // Chordal deflection 2e-4 of the diagonal, angular 10 degrees ("fine").
  kFine,
};

struct CadParams {
  CadDeflection deflection = CadDeflection::kCoarse;
  // Length units per millimetre of the part's own dimensions: 1e-3 writes
  // metres, 1 millimetres, 1e3 micrometres (UnitScale).
  double unit_scale = 1.0;
};

// Names of the CAD-mode parts, smallest first.
std::vector<std::string> CadPartNames();

// Returns the unit_scale of a unit name: "m" 1e-3, "mm" 1, "um" 1e3.
// Errors: INVALID_ARGUMENT naming the unit and the known ones.
absl::StatusOr<double> UnitScale(std::string_view unit);

// Returns the CAD-mode part `name`: the mesh (vertices welded along the
// B-rep's edges, watertight, triangles oriented outwards), one primitive per
// B-rep face, face_primitive for every face (never -1), face_near_boundary
// all 0 (no sampling band: facets end on the B-rep's edges) and
// vertex_primitive (for a vertex on an edge, one of its faces). voxel_size
// and noise are 0.
// Errors: INVALID_ARGUMENT for an unknown name or a unit_scale that is not
// finite and > 0; INTERNAL if OpenCASCADE fails to build or mesh the part;
// CANCELLED on stop.
absl::StatusOr<GeneratedPart> GenerateCadPart(std::string_view name, const CadParams& params = {},
                                              const RunContext& ctx = {});

// Returns the ground truth of `part` as a JSON document:
//   {"name", "voxel_size", "noise" (model units), "face_count",
//    "primitives": [{"id", "name", "type", <parameters as in the result JSON:
//                    "plane": {"point", "normal"}, "cylinder": {"axis_origin",
//                    "axis_direction", "radius"}, ...>}],
//    "face_primitive": [int per face], "face_near_boundary": [0/1 per face]}
// with Vec3 = {"x", "y", "z"}.
std::string GroundTruthJson(const GeneratedPart& part);

// Points drawn uniformly by area on a part's exact primitives.
struct SurfaceSamples {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;  // unit, outward
  std::vector<int> primitive;            // per point; -1 on a face without one
};

// Returns `count` points uniform by area on the faces of `part.mesh`, each
// moved to the closest point of its face's exact primitive (from `seed`).
SurfaceSamples SampleSurface(const GeneratedPart& part, int64_t count, uint64_t seed);

// Scanner mode: a simulated laser scan of a generated part. Points are drawn
// uniformly by area on the part's exact primitives; each scanner position
// keeps a point it sees (its ray meets no material on the way, the surface
// faces it at less than max_incidence_deg) with probability cos(incidence) ×
// (nearest range / range)², as a scanner sweeping its beam at equal angle
// steps does, so density is uneven and overlapping views add up; the point
// is then moved along the ray by Gaussian range noise. Uniform outliers in
// the part's bounding box are appended, flagged.
struct ScanParams {
  // Scan points over all views (outliers come on top).
  int64_t points = 50'000;
  // Scanner positions: evenly spaced in azimuth on a ring around the part's
  // centre, elevation_deg above its horizontal plane (z up), at `distance`
  // bounding-box diagonals from the centre, so faces turned down are unseen.
  int views = 4;
  double elevation_deg = 35.0;
  double distance = 2.0;
  // Rays meeting the surface at more than this from its normal return
  // nothing (a scanner loses a grazing beam).
  double max_incidence_deg = 80.0;
  // Standard deviation of the range noise, in nominal spacings (see
  // ScannedPart::spacing).
  double noise = 0.1;
  // Outliers added uniformly in the part's bounding box, as a fraction of
  // `points`.
  double outliers = 0.0;
  // Give every point the true outward normal (outliers a random one);
  // scanners that estimate normals do so from the points, so default off.
  bool normals = false;
  uint64_t seed = 1;
};

struct ScannedPart {
  GeneratedPart part;  // at GenerateParams' voxel size, noise-free
  // The scan points in draw order, then the outliers.
  PointCloud cloud;
  // One per point: the primitive the point was drawn from; -1 for an outlier
  // (and for a point on a face without a primitive).
  std::vector<int> point_primitive;
  std::vector<uint8_t> is_outlier;  // one per point
  // sqrt(seen area / scan points), model units: the spacing the scan would
  // have at uniform density.
  double spacing = 0.0;
  double seen_area_fraction = 0.0;  // of the part's surface, seen by a view
  // One per primitive: its area seen by a view (model units²), estimated as
  // seen_area_fraction is, from the candidates drawn uniformly by area.
  std::vector<double> primitive_seen_area;
  std::vector<Eigen::Vector3d> viewpoints;
};

// Returns the scan of part `name` (generated with `part_params`).
// Errors: those of GeneratePart; INVALID_ARGUMENT for points < 1 or over
// 100 M, views < 1, elevation outside [0, 90), distance <= 0.5,
// max_incidence_deg outside (0, 90], noise < 0, outliers outside [0, 10];
// FAILED_PRECONDITION if no view sees the part; CANCELLED on stop.
absl::StatusOr<ScannedPart> ScanPart(std::string_view name, const ScanParams& params = {},
                                     const GenerateParams& part_params = {},
                                     const RunContext& ctx = {});

// Returns GroundTruthJson of the scanned part with two more fields:
//   "point_primitive": [int per point], "point_outlier": [0/1 per point].
std::string ScanTruthJson(const ScannedPart& scan);

}  // namespace meshseg

#endif  // MESHSEG_GENERATE_H_
