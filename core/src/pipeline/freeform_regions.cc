#include "pipeline/freeform_regions.h"

#include <algorithm>
#include <array>
#include <vector>

#include "absl/strings/str_cat.h"

namespace meshseg::pipeline_internal {
namespace {

// The faces of `mesh` labelled `region`, as a mesh of their own: its border
// is the region's boundary.
absl::StatusOr<Mesh> RegionMesh(const Mesh& mesh, std::span<const int> labels, int region) {
  std::vector<int> index(mesh.tri.n_vertices(), -1);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
  for (auto f : mesh.tri.faces()) {
    if (labels[f.idx()] != region) continue;
    std::array<int, 3> t{};
    int c = 0;
    for (auto v : f.vertices()) {
      if (index[v.idx()] < 0) {
        index[v.idx()] = static_cast<int>(vertices.size());
        vertices.push_back(ToEigen(mesh.tri.point(v)));
      }
      t[c++] = index[v.idx()];
    }
    faces.push_back(t);
  }
  return BuildMesh(std::move(vertices), faces, absl::StrCat(mesh.name, " region ", region));
}

// A least-squares system near singular can leave a control vertex non-finite;
// such a fit is dropped rather than failing the segmentation.
bool AllFinite(const ControlMesh& control) {
  return std::all_of(control.vertices.begin(), control.vertices.end(),
                     [](const Eigen::Vector3d& v) { return v.allFinite(); });
}

}  // namespace

bool NeedsSubdivision(const Region& region, double noise, const FreeformFitParams& params) {
  if (region.face_count < params.min_region_faces) return false;
  if (region.type == SurfaceType::kFreeform) return true;
  return region.type == SurfaceType::kQuadric && region.rms_distance > params.noise_factor * noise;
}

absl::StatusOr<std::vector<RegionSubdivision>> FitFreeformRegions(
    const Mesh& mesh, std::span<const int> labels, std::span<const Region> regions, double noise,
    const FreeformFitParams& params, const RunContext& ctx) {
  std::vector<RegionSubdivision> out;
  if (!params.enabled) return out;
  std::vector<int> chosen;
  for (const Region& r : regions) {
    if (NeedsSubdivision(r, noise, params)) chosen.push_back(r.id);
  }
  for (size_t k = 0; k < chosen.size(); ++k) {
    ctx.Progress("freeform", static_cast<double>(k) / chosen.size());
    const absl::StatusOr<Mesh> part = RegionMesh(mesh, labels, chosen[k]);
    if (!part.ok()) continue;
    absl::StatusOr<SubdivFit> fit = FitSubdivisionSurface(*part, params.subdiv, ctx);
    if (absl::IsCancelled(fit.status())) return fit.status();
    if (!fit.ok() || !AllFinite(fit->control)) continue;  // e.g. too few faces
    out.push_back({.region = chosen[k],
                   .control = std::move(fit->control),
                   .rms_distance = fit->rms_distance,
                   .max_distance = fit->max_distance});
  }
  if (!chosen.empty()) ctx.Progress("freeform", 1.0);
  return out;
}

absl::Status FitFreeform(const Mesh& mesh, std::span<const int> labels,
                         const PipelineParams& params, const RunContext& ctx,
                         PipelineResult* result) {
  const double noise = std::max(result->estimates.noise_sigma, result->estimates.exact_tolerance);
  absl::StatusOr<std::vector<RegionSubdivision>> fits =
      FitFreeformRegions(mesh, labels, result->regions, noise, params.freeform, ctx);
  if (!fits.ok()) return fits.status();
  result->subdivisions = *std::move(fits);
  return absl::OkStatus();
}

}  // namespace meshseg::pipeline_internal
