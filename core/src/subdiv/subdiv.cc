// FitSubdivisionSurface(): checks params, then in order: the control mesh,
// quasi-interpolation (a linear first guess, so the least squares start near
// the data and their footpoints are meaningful), and the least-squares rounds
// on the limit surface.
#include "meshseg/subdiv.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "absl/strings/str_cat.h"
#include "meshseg/curvature.h"
#include "meshseg/status_macros.h"
#include "subdiv/control_from_mesh.h"
#include "subdiv/control_topology.h"
#include "subdiv/feature_lines.h"
#include "subdiv/fit_control_points.h"

namespace meshseg {
namespace {

// Level 5 samples a control face with 1024 triangles: beyond that the limit
// mesh outgrows any input it would be fitted to.
constexpr int kMaxLimitLevel = 5;
constexpr int kMaxRounds = 50;
constexpr int64_t kMinControlFaces = 4;

absl::Status ValidateParams(const SubdivParams& params) {
  if (params.target_faces && *params.target_faces < kMinControlFaces) {
    return absl::InvalidArgumentError(absl::StrCat("subdiv: target_faces ", *params.target_faces,
                                                   " is below ", kMinControlFaces));
  }
  if (!(params.face_fraction > 0.0 && params.face_fraction <= 1.0)) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: face_fraction ", params.face_fraction, " must be in (0, 1]"));
  }
  if (params.sharp_threshold &&
      !(*params.sharp_threshold > 0.0 && std::isfinite(*params.sharp_threshold))) {
    return absl::InvalidArgumentError(absl::StrCat(
        "subdiv: sharp_threshold ", *params.sharp_threshold, " must be finite and > 0"));
  }
  if (params.min_crease_edges < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: min_crease_edges ", params.min_crease_edges, " must be >= 1"));
  }
  if (params.limit_level < 0 || params.limit_level > kMaxLimitLevel) {
    return absl::InvalidArgumentError(absl::StrCat("subdiv: limit_level ", params.limit_level,
                                                   " must be in [0, ", kMaxLimitLevel, "]"));
  }
  if (params.fit_iterations < 0 || params.fit_iterations > kMaxRounds) {
    return absl::InvalidArgumentError(absl::StrCat("subdiv: fit_iterations ", params.fit_iterations,
                                                   " must be in [0, ", kMaxRounds, "]"));
  }
  if (!(params.tangent_weight > 0.0 && params.tangent_weight <= 1.0)) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: tangent_weight ", params.tangent_weight, " must be in (0, 1]"));
  }
  if (!(params.smoothing_weight >= 0.0 && std::isfinite(params.smoothing_weight))) {
    return absl::InvalidArgumentError(absl::StrCat(
        "subdiv: smoothing_weight ", params.smoothing_weight, " must be finite and >= 0"));
  }
  if (!(params.data_guard_fraction >= 0.0 && params.data_guard_fraction <= 1.0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "subdiv: data_guard_fraction ", params.data_guard_fraction, " must be in [0, 1]"));
  }
  if (params.tolerance && !(*params.tolerance > 0.0 && std::isfinite(*params.tolerance))) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: tolerance ", *params.tolerance, " must be finite and > 0"));
  }
  if (!(params.max_face_fraction > 0.0 && params.max_face_fraction <= 1.0)) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: max_face_fraction ", params.max_face_fraction, " must be in (0, 1]"));
  }
  return absl::OkStatus();
}

// Returns the feature lines of `mesh` (none without params.tag_creases):
// the curvature stage's sharp vertices, thinned along |kappa_max|.
absl::StatusOr<subdiv_internal::FeatureLines> DetectFeatures(const Mesh& mesh,
                                                             const SubdivParams& params,
                                                             const RunContext& ctx) {
  if (!params.tag_creases) {
    return subdiv_internal::FeatureLines{std::vector<uint8_t>(mesh.tri.n_edges(), 0),
                                         std::vector<int>(mesh.tri.n_vertices(), 0)};
  }
  CurvatureParams curvature_params;
  curvature_params.sharp_threshold = params.sharp_threshold;
  RunContext curvature_ctx;
  curvature_ctx.stop = ctx.stop;
  const absl::StatusOr<CurvatureField> field =
      EstimateCurvature(mesh, curvature_params, curvature_ctx);
  if (absl::IsCancelled(field.status())) return absl::CancelledError("subdiv: stop requested");
  MESHSEG_RETURN_IF_ERROR(field.status());
  std::vector<double> strength(field->kappa_max.size());
  for (size_t v = 0; v < strength.size(); ++v) strength[v] = std::abs(field->kappa_max[v]);
  const std::vector<uint8_t> ridges = subdiv_internal::RidgeVertices(
      mesh.tri, *field, curvature_params.w2, subdiv_internal::kMinRidgeContrast);
  return subdiv_internal::DetectFeatureLines(mesh.tri, ridges, strength, params.min_crease_edges);
}

// Returns the fit with a control mesh of about `target` faces.
absl::StatusOr<SubdivFit> FitAtSize(const Mesh& mesh, const std::vector<Eigen::Vector3d>& data,
                                    const subdiv_internal::FeatureLines& features, int64_t target,
                                    const SubdivParams& params, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(ControlMesh control,
                           subdiv_internal::ControlFromMesh(mesh.tri, target, features, ctx));
  MESHSEG_ASSIGN_OR_RETURN(const subdiv_internal::ControlTopology topo,
                           subdiv_internal::BuildControlTopology(control));
  control.vertices = subdiv_internal::QuasiInterpolate(control, topo);
  ctx.Progress("subdiv", 0.5);
  MESHSEG_ASSIGN_OR_RETURN(
      subdiv_internal::ControlFit fit,
      subdiv_internal::FitControlPoints(control, data, params.limit_level, params.fit_iterations,
                                        params.smoothing_weight, params.tangent_weight,
                                        params.data_guard_fraction, ctx));
  SubdivFit out;
  out.control = std::move(control);
  out.control.vertices = std::move(fit.vertices);
  out.limit_vertices = std::move(fit.limit.mesh.vertices);
  out.limit_faces = std::move(fit.limit.mesh.faces);
  out.rms_distance = fit.rms_distance;
  out.max_distance = fit.max_distance;
  out.rms_per_round = std::move(fit.rms_per_round);
  return out;
}

}  // namespace

absl::StatusOr<SubdivFit> FitSubdivisionSurface(const Mesh& mesh, const SubdivParams& params,
                                                const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  const int64_t faces = static_cast<int64_t>(mesh.tri.n_faces());
  if (faces < kMinControlFaces) {
    return absl::InvalidArgumentError(absl::StrCat("subdiv: \"", mesh.name, "\" has ", faces,
                                                   " faces, fewer than ", kMinControlFaces));
  }
  int64_t target = params.target_faces.value_or(
      std::max<int64_t>(kMinControlFaces, std::llround(params.face_fraction * faces)));
  if (target > faces) {
    return absl::InvalidArgumentError(absl::StrCat("subdiv: target_faces ", target, " exceeds the ",
                                                   faces, " faces of \"", mesh.name, "\""));
  }
  ctx.Progress("subdiv", 0.0);
  std::vector<Eigen::Vector3d> data;
  data.reserve(mesh.tri.n_vertices());
  for (auto v : mesh.tri.vertices()) {
    if (!mesh.tri.is_isolated(v)) data.push_back(ToEigen(mesh.tri.point(v)));
  }
  MESHSEG_ASSIGN_OR_RETURN(const subdiv_internal::FeatureLines features,
                           DetectFeatures(mesh, params, ctx));
  const int64_t max_faces = std::max<int64_t>(
      target, std::llround(params.max_face_fraction * static_cast<double>(faces)));
  std::optional<SubdivFit> best;
  std::vector<int64_t> tried_faces;
  std::vector<double> tried_rms;
  while (true) {
    MESHSEG_ASSIGN_OR_RETURN(SubdivFit fit, FitAtSize(mesh, data, features, target, params, ctx));
    tried_faces.push_back(static_cast<int64_t>(fit.control.faces.size()));
    tried_rms.push_back(fit.rms_distance);
    if (!best || fit.rms_distance < best->rms_distance) best = std::move(fit);
    // Doubling stops when the collapse can no longer reach the target
    // (feature lines keep their vertices) or at the size bound.
    if (!params.tolerance || best->rms_distance <= *params.tolerance || target >= max_faces ||
        tried_faces.back() < target / 2) {
      break;
    }
    target = std::min(2 * target, max_faces);
  }
  best->tried_faces = std::move(tried_faces);
  best->tried_rms = std::move(tried_rms);
  ctx.Progress("subdiv", 1.0);
  return *std::move(best);
}

}  // namespace meshseg
