// File: pipeline.h
// -----------------------------------------------------------------------------
// The whole job, as both the in-process CLI and the server's workers run it:
// read the input, reconstruct a point cloud into a mesh, estimate curvature,
// segment, extract boundaries and features, and map labels back to the faces
// (or points) of the input file. Reports progress per
// stage and honours cancellation. Same input and params give the same result
// on any thread count.
#ifndef MESHSEG_PIPELINE_H_
#define MESHSEG_PIPELINE_H_

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/brep.h"
#include "meshseg/curvature.h"
#include "meshseg/features.h"
#include "meshseg/input_size.h"
#include "meshseg/mesh.h"
#include "meshseg/reconstruct.h"
#include "meshseg/remesh.h"
#include "meshseg/run_context.h"
#include "meshseg/segment.h"
#include "meshseg/subdiv.h"
#include "meshseg/topology.h"
#include "meshseg/voxel.h"

namespace meshseg {

// Which regions get a Loop subdivision surface (issue #35, ALGORITHMS.md
// S5) and how large their control meshes are.
struct FreeformFitParams {
  // On by default: a region no analytic surface describes is otherwise
  // reported only as a quadric that misses it, and the control mesh is what
  // a CAD user needs of such a surface. It costs time only on parts that
  // have such regions (measured: 0.13-0.16 s for an 1819-face region; the
  // bunny scan's two quadric regions add 0.12 s to its 1.4 s).
  bool enabled = true;
  // A QUADRIC region qualifies when its rms distance exceeds this many noise
  // sigmas (SegmentEstimates::noise_sigma; on an exact tessellation its
  // tolerance): the rms of n >= 30 residuals of pure Gaussian noise stays
  // below 1.43 sigma with probability 0.999 (chi-square with 30 degrees of
  // freedom), so a larger rms means the quadric misses the shape, not noise.
  // FREEFORM regions always qualify.
  double noise_factor = 1.5;
  // Smallest region fitted: with SubdivParams::face_fraction 0.05 a region
  // of 80 faces gets the smallest control mesh (4 faces) the stage builds.
  int64_t min_region_faces = 80;
  // The fit itself; the region's faces are its input, its border the
  // control mesh's boundary (a sharp B-spline edge of the limit surface).
  SubdivParams subdiv;
};

struct PipelineParams {
  // Overrides format detection (e.g. the upload's format hint).
  std::optional<FileFormat> format;
  // Used when the input is a point cloud (seed 001).
  ReconstructParams reconstruct;
  // CAD tessellations are segmented on an isotropic remesh (remesh.h).
  RemeshParams remesh;
  CurvatureParams curvature;
  SegmentParams segment;
  TopologyParams topology;
  FeatureParams features;
  // Volumes (NRRD, MetaImage, raw): reading and iso-surface (voxel.h).
  VolumeParams volume;
  // How binary-occupancy surfaces (binary volumes, terraced marching-cubes
  // meshes) lose their terraces before segmentation. Both keep the vertices
  // at feature voxels (edges and corners of the material, ALGORITHMS.md S4),
  // whose position the occupancy fixes, and fit the surfaces on the original
  // vertices, which are unbiased where the smoothed ones are not.
  enum class BinarySurface {
    kRelax,     // RelaxTerraces on the full surface (voxel.h)
    kSimplify,  // feature-preserving QEM simplification, remeshed (remesh.h)
  };
  BinarySurface binary_surface = BinarySurface::kRelax;
  // kRelax: feature vertices stay put while the rest relax, so edges and
  // corners are not rounded off by the smoothing.
  bool binary_relax_keeps_features = true;
  // kSimplify: at most this share of the faces, and a quadric error of at
  // most this many voxels: a binary surface's vertices lie within about half
  // a voxel of the true surface, so that bound removes the terraces and
  // keeps real shape
  // (ALGORITHMS.md S4: 0.5-0.6 voxel).
  double binary_face_share = 0.1;
  double binary_max_error_voxels = 0.5;
  // Upper bound on declared vertex/face counts of the input.
  int64_t max_elements = 200'000'000;
  // When set, the B-rep of the result is written there as STEP (brep.h);
  // brep.noise_sigma defaults to the segmentation's estimate.
  std::string step_path;
  BrepParams brep;
  // Peak memory the job may take, in bytes; 0 = no limit. A job whose
  // EstimateJobMemory exceeds it is refused before its input is read.
  int64_t memory_budget_bytes = 0;
  // Copy the mesh the result's ids refer to into PipelineResult::mesh_geometry.
  bool include_mesh = false;
  // The length unit of the input's coordinates, echoed in the result: ""
  // (unspecified: model units) or one of CanonicalLengthUnit's (brep.h), any
  // case. With step_path set, brep.length_unit must name the same unit
  // (coordinates are written unscaled).
  std::string length_unit;
  // Loop subdivision surfaces of freeform regions (PipelineResult::subdivisions).
  FreeformFitParams freeform;
};

// The Loop subdivision surface fitted to one region's faces (#35).
struct RegionSubdivision {
  int region = -1;  // Region::id
  ControlMesh control;
  // From the region's mesh vertices to the limit surface, model units.
  double rms_distance = 0.0;
  double max_distance = 0.0;
};

// The mesh the result's vertex ids (vertex_labels, curves, corners) and mesh
// faces refer to: the input as loaded (STL welded, polygons fan-triangulated,
// dropped faces left out; also when it was segmented on a remesh), or the
// mesh reconstructed from a point cloud.
struct MeshGeometry {
  std::vector<Eigen::Vector3d> vertices;
  // Vertex ids, in each face's winding order (the input's).
  std::vector<std::array<int, 3>> faces;
  // One per face: the input face it came from (a polygon's triangles share
  // one). Empty for a point cloud, whose faces are all reconstructed.
  std::vector<int> input_face;
};

struct PipelineResult {
  // Statistics of the mesh the labels, vertex ids and curves refer to: the
  // input's (also when it was remeshed), or the reconstructed mesh.
  MeshStats mesh;
  // One per INPUT face, in input order; -1 = no region. For a point cloud:
  // one per face of the reconstructed mesh.
  std::vector<int> face_labels;
  std::vector<int> vertex_labels; // one per mesh vertex; -1 = no region
  std::vector<Region> regions;
  // The surfaces the regions lie on (Segmentation::surfaces).
  std::vector<SharedSurface> surfaces;
  SegmentEstimates estimates;
  Topology topology;
  std::vector<Feature> features;
  // Set when a CAD tessellation was segmented on an isotropic remesh: its
  // target edge length and face count (0 = segmented as read).
  double remesh_edge_length = 0.0;
  int64_t remesh_face_count = 0;
  // Edge length of the remesh around small curved features (RemeshStats);
  // 0 = uniform.
  double remesh_fine_edge_length = 0.0;
  // Point-cloud input only: true, and one label per input point (the label
  // of the nearest reconstructed face, or of a neighbouring region whose
  // fitted surface is nearer to the point; -1 for outliers).
  bool from_point_cloud = false;
  int64_t point_count = 0;
  std::vector<int> point_labels;
  // Point-cloud input: how many input points the reconstruction's outlier
  // test discarded (Reconstruction::is_outlier; their point_labels are -1).
  // The other -1 labels are points whose nearest face has no region.
  int64_t point_outlier_count = 0;
  // Point-cloud input: one per face of the reconstructed mesh, 1 where the
  // face closes an area no input point supports (Reconstruction::is_filled),
  // and the count and total area (model units²) of those faces.
  std::vector<uint8_t> face_filled;
  int64_t filled_face_count = 0;
  double filled_area = 0.0;
  // When PipelineParams::step_path is set: what the `brep` stage wrote, or
  // (brep unset) why it wrote nothing; the segmentation stands either way.
  std::optional<BrepReport> brep;
  std::string brep_error;
  // Volume input: the volume's header and the iso value used; face_labels
  // and the mesh statistics are those of the extracted surface.
  bool from_volume = false;
  VolumeInfo volume;
  double iso_value = 0.0;
  // Binary occupancy (a binary volume, or a mesh detected as terraced
  // marching-cubes output): segmented on the seed 003 simplification of this
  // many faces, whose Hausdorff distance to the full surface is given; labels
  // refer to the full-resolution faces.
  bool binary_occupancy = false;
  int64_t simplified_face_count = 0;
  double simplified_hausdorff = 0.0;
  // Set when PipelineParams::include_mesh is.
  std::optional<MeshGeometry> mesh_geometry;
  // PipelineParams::length_unit, lowercase ("" = unspecified).
  std::string length_unit;
  // With PipelineParams::freeform.enabled: one per qualifying region, by
  // ascending region id.
  std::vector<RegionSubdivision> subdivisions;
};

// A job's predicted peak resident memory, from the size its input declares
// (ProbeInput), by the model measured in core/src/pipeline/memory_model.h:
// a base, the mapped file, a cost per mesh face (plus a full-size remesh when
// the remesh may run) or per point, times a safety margin.
struct MemoryEstimate {
  InputSize input;
  int64_t peak_bytes = 0;
};

// Returns the estimate for the file at `input_path` under `params` (its
// format and remesh settings), reading only its header or its lines.
// Errors: those of ProbeInput.
absl::StatusOr<MemoryEstimate> EstimateJobMemory(const std::string& input_path,
                                                 const PipelineParams& params = {});

// Returns the segmentation of the mesh, point cloud or volume in
// `input_path`. A point cloud is first reconstructed into a watertight mesh
// (Reconstruct); a volume's surface is extracted (ExtractSurface). Binary
// occupancy surfaces go through seed 003: feature voxels, QEM simplification,
// segmentation of its remesh, labels mapped back to the full surface.
// Errors: those of ReadMesh / ReadPointCloud, Reconstruct, EstimateCurvature,
// Segment, ExtractTopology and RecognizeFeatures; RESOURCE_EXHAUSTED, before
// the input is read, when params.memory_budget_bytes is set and the job's
// EstimateJobMemory exceeds it (the message gives both); INVALID_ARGUMENT
// for coordinates beyond +-1e75 (their fourth powers overflow the fits);
// INTERNAL if a number of the result is not finite; CANCELLED on stop;
// INVALID_ARGUMENT for a length_unit CanonicalLengthUnit does not know, or
// one that is not the STEP file's (brep.length_unit) when step_path is set.
absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params = {},
                                           const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_PIPELINE_H_
