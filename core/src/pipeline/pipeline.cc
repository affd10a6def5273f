// RunPipeline(): read the input (reconstructing a point cloud into a mesh),
// then curvature -> segment -> topology -> features, and map the labels back
// to the faces or points of the input file.
#include "meshseg/pipeline.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <span>
#include <utility>

#include "absl/strings/str_cat.h"
#include "meshseg/fit.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"
#include "pipeline/binary_types.h"
#include "pipeline/finite_result.h"
#include "pipeline/freeform_regions.h"
#include "pipeline/input_labels.h"
#include "pipeline/memory_model.h"
#include "pipeline/mesh_geometry.h"
#include "pipeline/point_labels.h"
#include "pipeline/refit_regions.h"
#include "pipeline/remeshed_labels.h"
#include "pipeline/separating_planes.h"

namespace meshseg {
namespace {

// A CAD export's vertices lie on their surfaces to rounding: a face whose
// corners miss its region's refitted surface by more than this, in l_avg of
// the input, may belong next door.
constexpr double kExactCorner = 1e-4;

absl::Status ValidateParams(const PipelineParams& params) {
  if (params.max_elements <= 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("pipeline: max_elements must be positive, got ", params.max_elements));
  }
  if (params.memory_budget_bytes < 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "pipeline: memory_budget_bytes must be >= 0, got ", params.memory_budget_bytes));
  }
  if (params.length_unit.empty()) return absl::OkStatus();
  const std::string unit = CanonicalLengthUnit(params.length_unit);
  if (unit.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("pipeline: length_unit \"",
                                                   params.length_unit.substr(0, 64),
                                                   "\" is not one of ", LengthUnitList()));
  }
  // The STEP file declares its unit over unscaled coordinates: any other
  // unit than the input's would scale the part.
  if (!params.step_path.empty() && CanonicalLengthUnit(params.brep.length_unit) != unit) {
    return absl::InvalidArgumentError(absl::StrCat(
        "pipeline: the STEP file's length unit \"", params.brep.length_unit.substr(0, 64),
        "\" is not the input's length_unit \"", unit, "\" (coordinates are written unscaled)"));
  }
  return absl::OkStatus();
}

// Copies the mesh the result's ids refer to into `result` when params ask
// for it; `face_of_input` as Mesh::face_of_input (empty: a reconstruction).
void AttachMesh(const Mesh& mesh, std::span<const int> face_of_input, const PipelineParams& params,
                PipelineResult* result) {
  if (params.include_mesh) {
    result->mesh_geometry = pipeline_internal::GeometryOf(mesh.tri, face_of_input);
  }
}

// Returns OK if the job's estimated peak fits params.memory_budget_bytes.
absl::Status CheckMemoryBudget(const std::string& input_path, const PipelineParams& params) {
  if (params.memory_budget_bytes == 0) return absl::OkStatus();
  MESHSEG_ASSIGN_OR_RETURN(const MemoryEstimate estimate, EstimateJobMemory(input_path, params));
  if (estimate.peak_bytes <= params.memory_budget_bytes) return absl::OkStatus();
  const InputSize& in = estimate.input;
  return absl::ResourceExhaustedError(absl::StrCat(
      "pipeline: \"", std::filesystem::path(input_path).filename().string(), "\": ",
      in.point_cloud ? absl::StrCat(in.vertex_count, " points")
                     : absl::StrCat(in.face_count, " faces, ", in.vertex_count, " vertices"),
      " declared need an estimated ", estimate.peak_bytes, " bytes, over the memory budget of ",
      params.memory_budget_bytes));
}

// Each region of `result` a surface of its own (the remeshed path does not
// join them).
void OwnSurfaces(PipelineResult* result) {
  result->surfaces.clear();
  for (Region& r : result->regions) {
    r.surface_id = r.id;
    result->surfaces.push_back({.id = r.id,
                                .type = r.type,
                                .surface = r.surface,
                                .regions = {r.id},
                                .rms_distance = r.rms_distance,
                                .max_distance = r.max_distance});
  }
}

bool IsPointCloudFormat(FileFormat format) {
  return format == FileFormat::kXyz || format == FileFormat::kPwn;
}

// Boundaries and features of `labels` (one per face of `mesh`) into `result`.
absl::Status DescribeRegions(const Mesh& mesh, std::span<const int> labels,
                             const std::vector<Region>& regions, const PipelineParams& params,
                             const RunContext& ctx, PipelineResult* result) {
  ctx.Progress("topology", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(result->topology,
                           ExtractTopology(mesh, labels, regions, params.topology, ctx));
  MESHSEG_ASSIGN_OR_RETURN(result->features,
                           RecognizeFeatures(result->topology, regions, params.features));
  ctx.Progress("topology", 1.0);
  return absl::OkStatus();
}

// Boundaries and features of `segmentation` (of `mesh`) into `result`, with
// its regions, surfaces and estimates; returns its labels per mesh face.
absl::StatusOr<std::vector<int>> TakeSegmentation(const Mesh& mesh, Segmentation segmentation,
                                                  const PipelineParams& params,
                                                  const RunContext& ctx, PipelineResult* result) {
  MESHSEG_RETURN_IF_ERROR(
      DescribeRegions(mesh, segmentation.face_labels, segmentation.regions, params, ctx, result));
  result->vertex_labels = std::move(segmentation.vertex_labels);
  result->regions = std::move(segmentation.regions);
  result->surfaces = std::move(segmentation.surfaces);
  result->estimates = segmentation.estimates;
  return std::move(segmentation.face_labels);
}

// Segments `mesh` and fills everything of `result` but the labels; returns
// the labels per mesh face.
absl::StatusOr<std::vector<int>> SegmentMesh(const Mesh& mesh, const PipelineParams& params,
                                             const RunContext& ctx, PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the caller has decided
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(mesh, curvature, segment, ctx));
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

// An exact tessellation (meshseg/segment.h: SegmentExactFacets), facet by
// facet on the input itself: no curvature, no remesh.
absl::StatusOr<std::vector<int>> SegmentExact(const Mesh& mesh, const Exactness& exactness,
                                              const PipelineParams& params, const RunContext& ctx,
                                              PipelineResult* result) {
  result->mesh = MeshStatistics(mesh);
  SegmentParams segment = params.segment;
  segment.exact_tolerance = exactness.tolerance;
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, SegmentExactFacets(mesh, segment, ctx));
  segmentation.estimates.exact_share = exactness.share;
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

// A CAD tessellation (meshseg/remesh.h): segments an isotropic remesh, then
// labels the faces and vertices of `mesh` from it and extracts boundaries and
// features on `mesh` itself, so curve vertex ids are ids of the input.
// `surface` is what is remeshed: `mesh` itself, or (binary occupancy) its
// de-terraced simplification, whose vertices are not on `mesh`'s facets.
// With `binary` (the binary-occupancy samples of `mesh`), planes are refitted
// as the separators of those samples, as on the relaxed route.
absl::StatusOr<std::vector<int>> SegmentRemeshed(const Mesh& surface, const Mesh& mesh,
                                                 double edge_length, bool on_facets,
                                                 const PipelineParams& params,
                                                 const RunContext& ctx, PipelineResult* result,
                                                 const BinaryVertices* binary = nullptr) {
  RemeshStats remesh;
  MESHSEG_ASSIGN_OR_RETURN(const Mesh fine,
                           IsotropicRemesh(surface, edge_length, params.remesh, ctx, &remesh));
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(fine, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;  // the remesh's vertices lie on chords, under the surface
  segment.on_facets = on_facets;      // the remesh's vertices lie on the input's facets
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(fine, curvature, segment, ctx));
  const double tolerance = segmentation.estimates.distance_tolerance;
  std::vector<int> labels =
      pipeline_internal::TransferFaceLabels(fine.tri, segmentation.face_labels, mesh.tri);
  result->vertex_labels = pipeline_internal::VertexLabelsFromFaces(mesh.tri, labels);
  result->regions = std::move(segmentation.regions);
  pipeline_internal::CompactRegions(&labels, &result->vertex_labels, &result->regions);
  pipeline_internal::RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  if (on_facets && pipeline_internal::RelabelFacesOffTheirSurface(
          mesh.tri, result->regions, kExactCorner * MeanEdgeLength(mesh.tri), &labels) > 0) {
    result->vertex_labels = pipeline_internal::VertexLabelsFromFaces(mesh.tri, labels);
    pipeline_internal::CompactRegions(&labels, &result->vertex_labels, &result->regions);
    pipeline_internal::RefitOnInputVertices(mesh.tri, labels, tolerance, &result->regions);
  }
  if (binary != nullptr) {
    pipeline_internal::RefitPlanesBySeparation(mesh.tri, labels, *binary, &result->regions);
  }
  OwnSurfaces(result);
  MESHSEG_RETURN_IF_ERROR(DescribeRegions(mesh, labels, result->regions, params, ctx, result));
  result->mesh = MeshStatistics(mesh);
  result->estimates = segmentation.estimates;
  result->estimates.path = SegmentationPath::kRemeshed;
  result->remesh_edge_length = edge_length;
  result->remesh_face_count = static_cast<int64_t>(fine.tri.n_faces());
  result->remesh_fine_edge_length = remesh.fine_edge_length;
  return labels;
}

// Writes the STEP file when params ask for one (`labels` one per face of
// `mesh`, the mesh the topology refers to).
absl::Status ExportStep(const Mesh& mesh, std::span<const int> labels,
                        const PipelineParams& params, const RunContext& ctx,
                        PipelineResult* result) {
  if (params.step_path.empty()) return absl::OkStatus();
  BrepParams brep = params.brep;
  if (!brep.noise_sigma) brep.noise_sigma = result->estimates.noise_sigma;
  absl::StatusOr<BrepReport> report =
      WriteStep(mesh, labels, result->regions, result->topology, params.step_path, brep, ctx);
  if (absl::IsCancelled(report.status())) return report.status();
  if (report.ok()) {
    result->brep = *std::move(report);
  } else {
    result->brep_error = std::string(report.status().message());
  }
  return absl::OkStatus();
}

// Seed 003 (ALGORITHMS.md S4) for a binary-occupancy surface `mesh` on
// voxels of size h: its terraces (steps of one voxel on every slanted face)
// defeat curvature and growing, so it is segmented on a de-terraced surface
// (PipelineParams::BinarySurface) that keeps the feature vertices; labels
// and surfaces come back to the full surface's own faces and vertices.
absl::StatusOr<std::vector<int>> SegmentBinary(const Mesh& mesh, const BinaryVertices& binary,
                                               double h, const PipelineParams& params,
                                               const RunContext& ctx, PipelineResult* result) {
  result->binary_occupancy = true;
  // The relaxed surface has the input's faces and vertex ids.
  Mesh relaxed;
  relaxed.tri = mesh.tri;
  BinaryVertices free = binary;
  if (!params.binary_relax_keeps_features) std::fill(free.feature.begin(), free.feature.end(), 0);
  const std::vector<Eigen::Vector3d> moved = RelaxTerraces(mesh.tri, free);
  for (auto v : relaxed.tri.vertices()) {
    const Eigen::Vector3d& p = moved[v.idx()];
    relaxed.tri.set_point(v, TriMesh::Point(p.x(), p.y(), p.z()));
  }
  relaxed.tri.update_normals();
  relaxed.face_of_input = mesh.face_of_input;
  relaxed.name = mesh.name;
  if (params.binary_surface == PipelineParams::BinarySurface::kSimplify) {
    // QEM on the relaxed surface, not the terraced one: measured against the
    // terraces, keeping them costs nothing and the remesh then segments
    // them. The feature vertices (which the relaxation kept in place) stay.
    const SimplifyParams simplify{
        .target_faces = std::max<int64_t>(
            1000, static_cast<int64_t>(params.binary_face_share * mesh.tri.n_faces())),
        .max_error = params.binary_max_error_voxels * h,
        .measure_hausdorff = false};
    absl::StatusOr<Simplification> simple = Simplify(relaxed.tri, simplify, free.feature, {}, ctx);
    if (!simple.ok()) return simple.status();
    result->simplified_face_count = static_cast<int64_t>(simple->mesh.tri.n_faces());
    // To the full (terraced) surface, as the result reports it.
    result->simplified_hausdorff = Hausdorff(mesh.tri, simple->mesh.tri).Max();
    return SegmentRemeshed(simple->mesh, mesh, MeanEdgeLength(mesh.tri), /*on_facets=*/false,
                           params, ctx, result, &binary);
  }
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(relaxed, params.curvature, ctx));
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation,
                           Segment(relaxed, curvature, params.segment, ctx));
  std::vector<int> labels = std::move(segmentation.face_labels);
  result->vertex_labels = std::move(segmentation.vertex_labels);
  result->regions = std::move(segmentation.regions);
  result->estimates = segmentation.estimates;
  // The relaxation moves curved surfaces by their curvature (up to the
  // edges' slack): surfaces are fitted on the original, unbiased vertices.
  pipeline_internal::RetypeCoaxialSpheresOnInputVertices(mesh.tri, labels, &result->regions);
  pipeline_internal::RefitOnInputVertices(mesh.tri, labels, segmentation.estimates.distance_tolerance,
                                          &result->regions);
  // Planes: the separator of the binary samples, sharper than any fit to
  // the vertices between them (separating_planes.h).
  pipeline_internal::RefitPlanesBySeparation(mesh.tri, labels, binary, &result->regions);
  MESHSEG_RETURN_IF_ERROR(DescribeRegions(mesh, labels, result->regions, params, ctx, result));
  result->mesh = MeshStatistics(mesh);
  return labels;
}

absl::StatusOr<PipelineResult> RunOnVolume(const std::string& input_path,
                                           const PipelineParams& params, const RunContext& ctx) {
  VolumeParams volume = params.volume;
  if (params.format) volume.read.format = params.format;
  const absl::StatusOr<VolumeSurface> surface = ExtractSurface(input_path, volume, ctx);
  if (!surface.ok()) return surface.status();
  PipelineResult result;
  result.from_volume = true;
  result.volume = surface->info;
  result.iso_value = surface->iso;
  const double h = surface->info.geometry.Spacing().minCoeff();
  MESHSEG_ASSIGN_OR_RETURN(
      const std::vector<int> labels,
      surface->binary
          ? SegmentBinary(surface->mesh,
                          {surface->feature_vertex, surface->edge_inside, surface->edge_outside}, h,
                          params, ctx, &result)
                      : SegmentMesh(surface->mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(surface->mesh.face_of_input, labels);
  MESHSEG_RETURN_IF_ERROR(ExportStep(surface->mesh, labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(
      pipeline_internal::FitFreeform(surface->mesh, labels, params, ctx, &result));
  AttachMesh(surface->mesh, {}, params, &result);  // the extracted surface; no input faces
  return result;
}

// Segments the mesh reconstructed from `cloud` as SegmentMesh does, with
// the regions' surfaces refitted to the input points (the data; the mesh's
// vertices round creases over a spacing and the faces that close unscanned
// areas carry none), and labels every point (PointLabelsBySurface) before
// the boundaries and features are extracted from those surfaces.
absl::StatusOr<std::vector<int>> SegmentReconstruction(const Reconstruction& reconstruction,
                                                       const PointCloud& cloud,
                                                       const PipelineParams& params,
                                                       const RunContext& ctx,
                                                       PipelineResult* result) {
  const Mesh& mesh = reconstruction.mesh;
  result->mesh = MeshStatistics(mesh);
  MESHSEG_ASSIGN_OR_RETURN(CurvatureField curvature,
                           EstimateCurvature(mesh, params.curvature, ctx));
  SegmentParams segment = params.segment;
  segment.exact = ExactMode::kNever;
  MESHSEG_ASSIGN_OR_RETURN(Segmentation segmentation, Segment(mesh, curvature, segment, ctx));
  // Each region's points: those whose nearest face it holds.
  const std::vector<int> nearest = pipeline_internal::PointLabels(
      mesh.tri, segmentation.face_labels, cloud.points, reconstruction.is_outlier);
  std::vector<std::vector<Eigen::Vector3d>> points(segmentation.regions.size());
  for (std::size_t k = 0; k < nearest.size(); ++k) {
    if (nearest[k] >= 0) points[nearest[k]].push_back(cloud.points[k]);
  }
  const double tolerance = segmentation.estimates.distance_tolerance;
  pipeline_internal::RefitToPoints(points, tolerance, &segmentation.regions);
  // A region's own points are those within its band: the segmentation's
  // distance tolerance th_dis, widened to 3 sigma of the cloud's noise. The
  // others are a neighbour's (the rounded band of a crease, faces given to
  // the wrong side), which the least-squares fit above still follows; the
  // surface is fitted again without them.
  const double band = std::max(tolerance, 3.0 * reconstruction.stats.noise);
  std::vector<uint8_t> trusted(segmentation.regions.size(), 0);
  for (const Region& region : segmentation.regions) {
    std::erase_if(points[region.id], [&](const Eigen::Vector3d& p) {
      return !(std::abs(SignedDistance(region.surface, p)) <= band);
    });
    trusted[region.id] = !points[region.id].empty();
  }
  pipeline_internal::RefitToPoints(points, tolerance, &segmentation.regions);
  pipeline_internal::RetypeToPoints(points, reconstruction.stats.noise, &segmentation.regions,
                                    &segmentation.surfaces);
  // A point keeps its face's region within its noise band (2 sigma of the
  // cloud's noise); regions without points of their own (on the patches
  // that close unscanned areas) take no point from a neighbour.
  result->point_labels = pipeline_internal::PointLabelsBySurface(
      mesh.tri, segmentation.face_labels, segmentation.regions,
      {.keep_distance = 2.0 * reconstruction.stats.noise, .trusted = trusted}, cloud.points,
      reconstruction.is_outlier);
  return TakeSegmentation(mesh, std::move(segmentation), params, ctx, result);
}

absl::StatusOr<PipelineResult> RunOnPointCloud(const std::string& input_path,
                                               const PipelineParams& params,
                                               const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      PointCloud cloud,
      ReadPointCloud(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::CheckCoordinateRange(cloud.name, cloud.points));
  MESHSEG_ASSIGN_OR_RETURN(Reconstruction reconstruction,
                           Reconstruct(cloud, params.reconstruct, ctx));
  PipelineResult result;
  result.from_point_cloud = true;
  result.point_count = static_cast<int64_t>(cloud.points.size());
  MESHSEG_ASSIGN_OR_RETURN(result.face_labels,
                           SegmentReconstruction(reconstruction, cloud, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(
      ExportStep(reconstruction.mesh, result.face_labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(reconstruction.mesh, result.face_labels,
                                                         params, ctx, &result));
  result.point_outlier_count = reconstruction.stats.outlier_count;
  result.face_filled = reconstruction.is_filled;
  result.filled_face_count = reconstruction.stats.filled_face_count;
  result.filled_area = reconstruction.stats.filled_area;
  AttachMesh(reconstruction.mesh, {}, params, &result);
  return result;
}

absl::StatusOr<PipelineResult> RunOnMesh(const std::string& input_path,
                                         const PipelineParams& params, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(
      Mesh mesh,
      ReadMesh(input_path, {.format = params.format, .max_elements = params.max_elements}));
  ctx.Progress("read", 1.0);
  PipelineResult result;
  // Binary occupancy first: a terraced surface's facets lie exactly in the
  // planes of their neighbours, so it would pass for an exact tessellation.
  if (const std::optional<BinaryLattice> lattice = DetectBinaryLattice(mesh.tri)) {
    MESHSEG_ASSIGN_OR_RETURN(const BinaryVertices binary,
                             BinaryMeshFeatures(mesh.tri, *lattice, params.volume));
    MESHSEG_ASSIGN_OR_RETURN(
        const std::vector<int> labels,
        SegmentBinary(mesh, binary, lattice->spacing.minCoeff(), params, ctx, &result));
    result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, labels);
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, labels, params, ctx, &result));
    AttachMesh(mesh, mesh.face_of_input, params, &result);
    return result;
  }
  // An exact tessellation is segmented facet by facet, as read; the share
  // of exact facets is reported either way (estimates.exact_share).
  Exactness exactness;
  if (params.segment.exact != ExactMode::kNever && params.remesh.mode != RemeshMode::kAlways) {
    exactness = EstimateExactness(mesh, params.segment.exact_tolerance);
    if (exactness.exact || params.segment.exact == ExactMode::kAlways) {
      MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> labels,
                               SegmentExact(mesh, exactness, params, ctx, &result));
      result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, labels);
      MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, labels, params, ctx, &result));
      MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, labels, params, ctx, &result));
      AttachMesh(mesh, mesh.face_of_input, params, &result);
      return result;
    }
  }
  const TessellationShape shape = Assess(mesh, params.remesh);
  const bool remesh = params.remesh.mode == RemeshMode::kAlways ||
                      (params.remesh.mode == RemeshMode::kAuto && shape.cad_like);
  const double edge_length = params.remesh.target_edge_length > 0.0
                                 ? params.remesh.target_edge_length
                                 : shape.target_edge_length;
  MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> mesh_labels,
                           remesh ? SegmentRemeshed(mesh, mesh, edge_length, true, params, ctx, &result)
                                  : SegmentMesh(mesh, params, ctx, &result));
  result.face_labels = pipeline_internal::InputFaceLabels(mesh.face_of_input, mesh_labels);
  result.estimates.exact_tolerance = exactness.tolerance;
  result.estimates.exact_share = exactness.share;
  MESHSEG_RETURN_IF_ERROR(ExportStep(mesh, mesh_labels, params, ctx, &result));
  MESHSEG_RETURN_IF_ERROR(pipeline_internal::FitFreeform(mesh, mesh_labels, params, ctx, &result));
  AttachMesh(mesh, mesh.face_of_input, params, &result);
  return result;
}

}  // namespace

absl::StatusOr<MemoryEstimate> EstimateJobMemory(const std::string& input_path,
                                                 const PipelineParams& params) {
  MemoryEstimate estimate;
  std::optional<FileFormat> format = params.format;
  if (!format) {
    const absl::StatusOr<FileFormat> detected = DetectFileFormat(input_path);
    if (detected.ok() && IsVolumeFormat(*detected)) format = *detected;
  }
  if (format && IsVolumeFormat(*format)) {  // costed from the volume's header
    VolumeReadOptions read = params.volume.read;
    read.format = format;
    MESHSEG_ASSIGN_OR_RETURN(const VolumeInfo info, ReadVolumeInfo(input_path, read));
    std::error_code ec;
    const auto file_bytes = std::filesystem::file_size(input_path, ec);
    int64_t extra = 0;
    estimate.input = pipeline_internal::VolumeInputSize(
        info, params, ec ? 0 : static_cast<int64_t>(file_bytes), &extra);
    PipelineParams no_remesh = params;  // a volume's surface is not remeshed
    no_remesh.remesh.mode = RemeshMode::kNever;
    estimate.peak_bytes =
        pipeline_internal::PeakBytes(estimate.input, no_remesh) +
        static_cast<int64_t>(pipeline_internal::kSafetyMargin * static_cast<double>(extra));
    return estimate;
  }
  MESHSEG_ASSIGN_OR_RETURN(estimate.input, ProbeInput(input_path, params.format));
  estimate.peak_bytes = pipeline_internal::PeakBytes(estimate.input, params);
  return estimate;
}

absl::StatusOr<PipelineResult> RunPipeline(const std::string& input_path,
                                           const PipelineParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  MESHSEG_RETURN_IF_ERROR(CheckMemoryBudget(input_path, params));
  ctx.Progress("read", 0.0);
  std::optional<FileFormat> format = params.format;
  if (!format) {
    const absl::StatusOr<FileFormat> detected = DetectFileFormat(input_path);
    if (detected.ok() && IsVolumeFormat(*detected)) format = *detected;
  }
  if (format && IsVolumeFormat(*format)) {
    absl::StatusOr<PipelineResult> result = RunOnVolume(input_path, params, ctx);
    if (result.ok()) MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
    return result;
  }
  bool point_cloud = params.format && IsPointCloudFormat(*params.format);
  if (!params.format || *params.format == FileFormat::kPly) {
    MESHSEG_ASSIGN_OR_RETURN(point_cloud, IsPointCloudFile(input_path));
  }
  absl::StatusOr<PipelineResult> result = point_cloud ? RunOnPointCloud(input_path, params, ctx)
                                                      : RunOnMesh(input_path, params, ctx);
  if (result.ok()) {
    result->length_unit = CanonicalLengthUnit(params.length_unit);
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("pipeline"));
    MESHSEG_RETURN_IF_ERROR(pipeline_internal::CheckResultFinite(
        std::filesystem::path(input_path).filename().string(), *result));
  }
  return result;
}

}  // namespace meshseg
