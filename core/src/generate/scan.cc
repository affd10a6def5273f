// ScanPart: the scanner mode of the generator (generate.h). Surface samples
// on the exact primitives, kept per view by line of sight and a laser
// scanner's density, moved by range noise along the ray; then outliers.
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "absl/strings/str_cat.h"
#include "generate/parts.h"
#include "generate/scan_rays.h"
#include "meshseg/fit.h"
#include "meshseg/generate.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

constexpr char kStage[] = "generate: scan";
constexpr int64_t kMaxPoints = 100'000'000;
constexpr double kMaxOutliers = 10.0;
// Candidates drawn per round; rounds go on until the scan has its points.
constexpr int64_t kBatch = 16384;
// A ray starts this many voxels off the surface (the sample sits on the
// exact primitive, which near an edge may dip into the neighbour's material
// by a rounding error).
constexpr double kRayStartVoxels = 0.05;

absl::Status ValidateParams(std::string_view name, const ScanParams& p) {
  const auto bad = [&](const std::string& what) {
    return absl::InvalidArgumentError(
        absl::StrCat(kStage, ": part \"", std::string(name), "\": ", what));
  };
  if (p.points < 1 || p.points > kMaxPoints) {
    return bad(absl::StrCat("points ", p.points, " outside [1, ", kMaxPoints, "]"));
  }
  if (p.views < 1) return bad(absl::StrCat("views ", p.views, " must be >= 1"));
  if (!(p.elevation_deg >= 0.0 && p.elevation_deg < 90.0)) {
    return bad(absl::StrCat("elevation_deg ", p.elevation_deg, " outside [0, 90)"));
  }
  if (!(p.distance > 0.5)) return bad(absl::StrCat("distance ", p.distance, " must be > 0.5"));
  if (!(p.max_incidence_deg > 0.0 && p.max_incidence_deg <= 90.0)) {
    return bad(absl::StrCat("max_incidence_deg ", p.max_incidence_deg, " outside (0, 90]"));
  }
  if (!(p.noise >= 0.0)) return bad(absl::StrCat("noise ", p.noise, " must be >= 0"));
  if (!(p.outliers >= 0.0 && p.outliers <= kMaxOutliers)) {
    return bad(absl::StrCat("outliers ", p.outliers, " outside [0, ", kMaxOutliers, "]"));
  }
  return absl::OkStatus();
}

// The scanner positions on their ring, and the nearest range to the part.
std::vector<Eigen::Vector3d> Viewpoints(const Eigen::AlignedBox3d& box, const ScanParams& p) {
  const Eigen::Vector3d centre = box.center();
  const double radius = p.distance * box.diagonal().norm();
  const double elevation = p.elevation_deg * std::numbers::pi / 180.0;
  std::vector<Eigen::Vector3d> out;
  for (int v = 0; v < p.views; ++v) {
    // Offset by half a step, so no view looks straight along a part's axis.
    const double azimuth = 2.0 * std::numbers::pi * (v + 0.5) / p.views;
    out.push_back(centre + radius * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                                    std::cos(elevation) * std::sin(azimuth),
                                                    std::sin(elevation)));
  }
  return out;
}

double SurfaceArea(const TriMesh& m) {
  double area = 0.0;
  for (const auto f : m.faces()) area += m.calc_face_area(f);
  return area;
}

Eigen::AlignedBox3d BoundingBox(const TriMesh& m) {
  Eigen::AlignedBox3d box;
  for (const auto v : m.vertices()) box.extend(ToEigen(m.point(v)));
  return box;
}

}  // namespace

absl::StatusOr<ScannedPart> ScanPart(std::string_view name, const ScanParams& params,
                                     const GenerateParams& part_params, const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(name, params));
  const std::optional<generate_internal::PartSpec> spec = generate_internal::FindPart(name);
  GenerateParams clean = part_params;
  clean.noise = 0.0;
  absl::StatusOr<GeneratedPart> part = GeneratePart(name, clean, ctx);
  if (!part.ok()) return part.status();
  ScannedPart scan;
  scan.part = *std::move(part);
  const GeneratedPart& g = scan.part;
  const Eigen::AlignedBox3d box = BoundingBox(g.mesh.tri);
  scan.viewpoints = Viewpoints(box, params);
  double nearest_range = std::numeric_limits<double>::infinity();
  for (const auto& eye : scan.viewpoints) {
    nearest_range =
        std::min(nearest_range, (box.center() - eye).norm() - 0.5 * box.diagonal().norm());
  }
  const double min_cos = std::cos(params.max_incidence_deg * std::numbers::pi / 180.0);
  const double start = kRayStartVoxels * g.voxel_size;
  std::mt19937_64 rng(params.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);

  // Per candidate and view: the probability the view keeps it (0 = unseen).
  const size_t views = scan.viewpoints.size();
  std::vector<double> keep(kBatch * views);
  // Per scan point: its surface sample and the unit ray to its eye.
  SurfaceSamples kept;
  std::vector<Eigen::Vector3d> ray;
  int64_t drawn = 0, seen = 0;
  std::vector<int64_t> seen_of(g.primitives.size(), 0);  // per primitive
  for (uint64_t round = 1; static_cast<int64_t>(kept.points.size()) < params.points; ++round) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
    const SurfaceSamples batch = SampleSurface(g, kBatch, params.seed + 7919 * round);
    tbb::parallel_for(size_t{0}, batch.points.size(), [&](size_t i) {
      for (size_t v = 0; v < views; ++v) {
        const Eigen::Vector3d to_eye = scan.viewpoints[v] - batch.points[i];
        const double range = to_eye.norm();
        const double cos_incidence = batch.normals[i].dot(to_eye) / range;
        const bool visible =
            cos_incidence > min_cos &&
            generate_internal::LineOfSight(spec->solid, batch.points[i], scan.viewpoints[v], start,
                                           g.voxel_size);
        const double falloff = nearest_range / range;
        keep[i * views + v] = visible ? cos_incidence * falloff * falloff : 0.0;
      }
    });
    // Each candidate goes to one view drawn at random, so views sample
    // different spots (a candidate kept by two views would be a duplicate).
    for (size_t i = 0;
         i < batch.points.size() && static_cast<int64_t>(kept.points.size()) < params.points; ++i) {
      ++drawn;
      bool any = false;
      for (size_t v = 0; v < views; ++v) any |= keep[i * views + v] > 0.0;
      seen += any;
      if (any && batch.primitive[i] >= 0) ++seen_of[batch.primitive[i]];
      const size_t v = std::min(views - 1, static_cast<size_t>(u(rng) * views));
      if (u(rng) < keep[i * views + v]) {
        kept.points.push_back(batch.points[i]);
        kept.normals.push_back(batch.normals[i]);
        kept.primitive.push_back(batch.primitive[i]);
        ray.push_back((scan.viewpoints[v] - batch.points[i]).normalized());
      }
    }
    if (seen == 0 && drawn >= kBatch) {
      return absl::FailedPreconditionError(absl::StrCat(
          kStage, ": part \"", g.name, "\": none of ", views, " views sees the part (elevation ",
          params.elevation_deg, " deg, incidence under ", params.max_incidence_deg, " deg)"));
    }
    ctx.Progress(kStage, static_cast<double>(kept.points.size()) / params.points);
  }
  scan.seen_area_fraction = static_cast<double>(seen) / drawn;
  const double area = SurfaceArea(g.mesh.tri);
  scan.spacing = std::sqrt(scan.seen_area_fraction * area / params.points);
  for (const int64_t n : seen_of) {
    scan.primitive_seen_area.push_back(area * static_cast<double>(n) / static_cast<double>(drawn));
  }

  const double sigma = params.noise * scan.spacing;
  PointCloud& cloud = scan.cloud;
  cloud.name = absl::StrCat(g.name, "_scan.xyz");
  for (size_t k = 0; k < kept.points.size(); ++k) {
    cloud.points.push_back(kept.points[k] + sigma * gauss(rng) * ray[k]);
    if (params.normals) cloud.normals.push_back(kept.normals[k]);
    scan.point_primitive.push_back(kept.primitive[k]);
    scan.is_outlier.push_back(0);
  }
  const int64_t outliers = std::llround(params.outliers * static_cast<double>(params.points));
  for (int64_t k = 0; k < outliers; ++k) {
    const Eigen::Vector3d t(u(rng), u(rng), u(rng));
    cloud.points.push_back(box.min() + t.cwiseProduct(box.max() - box.min()));
    if (params.normals) {
      cloud.normals.push_back(Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized());
    }
    scan.point_primitive.push_back(-1);
    scan.is_outlier.push_back(1);
  }
  ctx.Progress(kStage, 1.0);
  return scan;
}

}  // namespace meshseg
