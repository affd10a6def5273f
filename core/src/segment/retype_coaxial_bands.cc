#include "segment/retype_coaxial_bands.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "meshseg/status_macros.h"
#include "segment/align_coaxial.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

// True if the axis of `face` (a cylinder or cone) is the axis of `band`:
// NearlyCoaxial with a torus at its centre for its tube radius; through a
// sphere's centre within kCoaxialMaxOffset of its radius; any axis for a
// cone.
bool OnItsAxis(const Surface& band, const Surface& face) {
  if (const auto* t = std::get_if<Torus>(&band)) {
    return NearlyCoaxial(band, face, t->center, t->minor_radius);
  }
  // A cone band's own axis is what a narrow band leaves uncertain: the fit
  // on the face's axis tests it (BestCoaxialCone's caller asks it to meet
  // the band near the noise).
  if (std::holds_alternative<Cone>(band)) return true;
  const auto* s = std::get_if<Sphere>(&band);
  const std::optional<AxisLine> axis = AxisOf(face);
  if (s == nullptr || !axis) return false;
  const Eigen::Vector3d d = s->center - axis->point;
  return (d - d.dot(axis->direction) * axis->direction).norm() <= kCoaxialMaxOffset * s->radius;
}

// The cone fitted to `interior` on one axis with the vertices that meet
// `face`'s surface (FitCoaxial from its axis); invalid if that fit is.
FitResult CoaxialCone(const SegmentContext& c, const RegionState& face,
                      const std::vector<int>& interior) {
  std::vector<Eigen::Vector3d> face_points, band_points;
  for (const int v : Sample(MeasuredVertices(c, FittingVertices(c, face.surface, face.vertices)))) {
    face_points.push_back(c.position(v));
  }
  for (const int v : MeasuredVertices(c, interior)) band_points.push_back(c.position(v));
  const AxisLine axis = *AxisOf(face.surface);
  const CoaxialMember members[] = {
      {face.type, {.points = face_points, .normals = {}, .weights = {}}},
      {SurfaceType::kCone, {.points = band_points, .normals = {}, .weights = {}}}};
  return FitCoaxial(members, axis.point, axis.direction)[1];
}

}  // namespace

std::optional<RegionState> SphereOnConeAxis(const SegmentContext& c, const RegionState& r,
                                            const Surface& cone) {
  const auto* axis = std::get_if<Cone>(&cone);
  if (r.type != SurfaceType::kSphere || axis == nullptr) return std::nullopt;
  const Eigen::Vector3d d = axis->axis_direction.normalized();
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (const int v : Sample(MeasuredVertices(c, r.vertices))) {
    const Eigen::Vector3d u = c.position(v) - axis->apex;
    const Eigen::Vector2d row(2.0 * u.dot(d), 1.0);
    a += row * row.transpose();
    b += row * u.squaredNorm();
  }
  const Eigen::Vector2d x = a.ldlt().solve(b);
  const double radius_squared = x(1) + x(0) * x(0);
  if (!x.allFinite() || !(radius_squared > 0.0)) return std::nullopt;
  RegionState out = r;
  out.surface = Sphere{.center = axis->apex + x(0) * d, .radius = std::sqrt(radius_squared)};
  out.shared_parameters = ParameterCount(SurfaceType::kSphere) - kCoaxialSphereParameters;
  return out;
}

std::optional<CoaxialFit> BestCoaxialCone(const SegmentContext& c, const std::vector<int>& labels,
                                          const std::vector<RegionState>& regions, int id,
                                          const std::vector<int>& interior) {
  std::optional<CoaxialFit> best;
  for (const int n : RegionsAround(c, labels, regions, id)) {
    const RegionState& face = regions[n];
    if ((face.type != SurfaceType::kCylinder && face.type != SurfaceType::kCone) ||
        !OnItsAxis(regions[id].surface, face.surface)) {
      continue;
    }
    const FitResult cone = CoaxialCone(c, face, interior);
    if (!cone.ok()) continue;
    const double mean_square = SquaredDistances(c, cone.surface, interior) / interior.size();
    const double score = InformationScore(c, mean_square, interior.size(), kCoaxialConeParameters);
    if (!best || score < best->score) {
      best = CoaxialFit{.fit = cone, .mean_square = mean_square, .score = score};
    }
  }
  return best;
}

RegionState CoaxialConeRegion(const RegionState& r, const Surface& cone) {
  RegionState out = r;
  out.type = SurfaceType::kCone;
  out.surface = cone;
  out.shared_parameters = ParameterCount(SurfaceType::kCone) - kCoaxialConeParameters;
  return out;
}

std::vector<int> RetypeCoaxialBands(const SegmentContext& c, const std::vector<int>& labels,
                                    std::vector<RegionState>* regions) {
  std::vector<int> retyped;
  if (!(c.noise_sigma > 0.0)) return retyped;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || (r.type != SurfaceType::kSphere && r.type != SurfaceType::kTorus)) continue;
    const int ids[] = {id};
    const std::vector<int> interior = Sample(InteriorVertices(c, labels, ids, r.vertices));
    if (interior.size() < kMinInteriorVertices) continue;
    const std::optional<CoaxialFit> best = BestCoaxialCone(c, labels, *regions, id, interior);
    if (!best) continue;
    // The cone on the axis, priced as E prices a retype (RetypeDelta's terms
    // with this surface): against the region re-estimated with its own type,
    // and a sphere also on that axis, where it shares it as the cone does
    // (energy.h, "Shared parameters": the comparison is fair only if both
    // are charged what they estimate).
    const RegionState own = Reestimated(c, r);
    const RegionState cone = CoaxialConeRegion(r, best->fit.surface);
    double own_cost = DataCost(c, own.surface, r.vertices) + LabelCost(c, own);
    if (const std::optional<RegionState> sphere = SphereOnConeAxis(c, r, cone.surface)) {
      own_cost = std::min(own_cost, DataCost(c, sphere->surface, r.vertices) + LabelCost(c, *sphere));
    }
    const double delta = DataCost(c, cone.surface, r.vertices) + LabelCost(c, cone) - own_cost;
    if (!(delta < 0.0)) continue;
    r = cone;
    retyped.push_back(id);
  }
  return retyped;
}

absl::StatusOr<std::vector<int>> PlaceCoaxialBands(const SegmentContext& c,
                                                   std::vector<int>* labels,
                                                   std::vector<RegionState>* regions) {
  std::vector<int> moved;
  if (!(c.noise_sigma > 0.0)) return moved;
  double energy = TotalEnergy(c, *labels, *regions);
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    const RegionState& r = (*regions)[id];
    if (!r.alive || (r.type != SurfaceType::kSphere && r.type != SurfaceType::kTorus)) continue;
    const int ids[] = {id};
    const std::vector<int> interior = Sample(InteriorVertices(c, *labels, ids, r.vertices));
    if (interior.size() < kMinInteriorVertices) continue;
    const std::optional<CoaxialFit> best = BestCoaxialCone(c, *labels, *regions, id, interior);
    if (!best ||
        !(ModelErrorOfMeanSquare(c, best->mean_square) <= kScoredNearError * c.noise_sigma)) {
      continue;
    }
    // The models on the axis: the cone, and a sphere's own type there,
    // unless its surface shares that axis already (it is that model).
    std::vector<RegionState> models = {CoaxialConeRegion(r, best->fit.surface)};
    if (r.shared_parameters == 0) {
      if (std::optional<RegionState> sphere = SphereOnConeAxis(c, r, best->fit.surface)) {
        models.push_back(std::move(*sphere));
      }
    }
    // Each re-estimated, with the expansion it enables; the lower kept.
    std::optional<Placed> kept;
    for (const RegionState& model : models) {
      MESHSEG_ASSIGN_OR_RETURN(Placed next,
                               PlacedByExpansion(c, *labels, *regions, id, Reestimated(c, model)));
      if (!(next.energy < (kept ? kept->energy : energy))) continue;
      kept = std::move(next);
    }
    if (!kept) continue;
    *labels = std::move(kept->labels);
    *regions = std::move(kept->regions);
    energy = kept->energy;
    moved.push_back(id);
  }
  return moved;
}

}  // namespace meshseg::segment_internal
