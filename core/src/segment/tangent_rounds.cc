#include "segment/tangent_rounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Geometry>

#include "segment/align_coaxial.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
#include "segment/retype_by_interior.h"
#include "segment/round_arc.h"

namespace meshseg::segment_internal {
namespace {

double Radians(double deg) { return deg * std::numbers::pi / 180.0; }

// The plane regions around region `id` whose normals are within
// kCoaxialMaxAngleDeg of square to `axis`.
std::vector<int> PlanesAlong(const SegmentContext& c, const std::vector<int>& labels,
                             const std::vector<RegionState>& regions, int id,
                             const Eigen::Vector3d& axis) {
  const double sin_max = std::sin(Radians(kCoaxialMaxAngleDeg));
  std::vector<int> planes;
  for (const int n : RegionsAround(c, labels, regions, id)) {
    const auto* plane = std::get_if<Plane>(&regions[n].surface);
    if (regions[n].alive && regions[n].type == SurfaceType::kPlane && plane != nullptr &&
        std::abs(plane->normal.normalized().dot(axis)) <= sin_max) {
      planes.push_back(n);
    }
  }
  return planes;
}

// A tangent fit and the plane regions it is tangent to.
struct TangentStart {
  FitResult fit;
  std::array<int, 2> faces;
};

// The tangent fit to `input` with the least error over the pairs of
// `planes` (region ids) at least kMinRoundAngleDeg apart.
std::optional<TangentStart> BestTangentFit(const FitInput& input, const Cylinder& own,
                                           const std::vector<RegionState>& regions,
                                           const std::vector<int>& planes) {
  const double sin_min = std::sin(Radians(kMinRoundAngleDeg));
  std::optional<TangentStart> best;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      const Plane& a = std::get<Plane>(regions[planes[i]].surface);
      const Plane& b = std::get<Plane>(regions[planes[j]].surface);
      if (a.normal.normalized().cross(b.normal.normalized()).norm() < sin_min) continue;
      const std::array<int, 2> sides = {PlaneSide(a, own.axis_origin),
                                        PlaneSide(b, own.axis_origin)};
      FitResult fit = FitCylinderTangentToPlanes(input, a, b, sides, own.radius);
      if (fit.ok() && (!best || fit.rms_distance < best->fit.rms_distance)) {
        best = TangentStart{.fit = std::move(fit), .faces = {planes[i], planes[j]}};
      }
    }
  }
  return best;
}

// True if `tangent` explains `vertices` as well as the cylinder fitted to
// them freely, by both tests: its sum of squared distances rises by at most
// kCoaxialChiSquare residual variances of the free fit, and E (its data
// cost and the label cost of region `r` with the tangent round's one free
// parameter, against the free cylinder's five) is not higher. The first
// sees a misfit far above the data's own noise where E's unit is set by
// the mesh resolution (an exact fillet of r 0.75 fitted tangent at r 0.70);
// the second prices the parameters the planes lend.
bool TangentExplains(const SegmentContext& c, const RegionState& r, const Surface& tangent,
                     const std::vector<int>& vertices) {
  const std::vector<int> sample = Sample(vertices);
  std::vector<Eigen::Vector3d> points, normals;
  for (const int v : sample) {
    points.push_back(c.position(v));
    normals.push_back(c.normal(v));
  }
  const FitResult free = FitCylinder({.points = points, .normals = normals, .weights = {}});
  if (!free.ok()) return false;
  const double m = static_cast<double>(points.size());
  const double free_cost = SquaredDistances(c, free.surface, sample);
  const double rise = SquaredDistances(c, tangent, sample) - free_cost;
  if (!(rise <= kCoaxialChiSquare * ResidualVariance(c, free_cost, m, 5.0))) return false;
  const RegionState as_tangent{
      .type = SurfaceType::kCylinder,
      .shared_parameters = ParameterCount(SurfaceType::kCylinder) - kTangentRoundParameters};
  const RegionState as_free{.type = SurfaceType::kCylinder};
  const std::size_t n = r.vertices.size();
  return DataCost(c, tangent, vertices) + LabelCost(c, as_tangent, n) <=
         DataCost(c, free.surface, vertices) + LabelCost(c, as_free, n);
}

}  // namespace

std::vector<int> FitRoundsTangentToPlanes(const SegmentContext& c, const std::vector<int>& labels,
                                          std::vector<RegionState>* regions) {
  std::vector<int> changed;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    const RegionState& r = (*regions)[id];
    const auto* own = std::get_if<Cylinder>(&r.surface);
    if (!r.alive || r.type != SurfaceType::kCylinder || own == nullptr) continue;
    const std::vector<int> planes =
        PlanesAlong(c, labels, *regions, id, own->axis_direction.normalized());
    if (planes.size() < 2) continue;
    const int ids[] = {id};
    const std::vector<int> fitting = MeasuredVertices(
        c, FittingVertices(c, r.surface, InteriorVertices(c, labels, ids, r.vertices)));
    std::vector<Eigen::Vector3d> points;
    for (const int v : Sample(fitting)) points.push_back(c.position(v));
    if (points.size() < 6) continue;
    const std::optional<TangentStart> start =
        BestTangentFit({.points = points, .normals = {}, .weights = {}}, *own, *regions, planes);
    if (!start) continue;
    const RoundOnArc on_arc =
        FitRoundOnArc(c, *regions, id, start->faces, std::get<Cylinder>(start->fit.surface));
    if (!on_arc.round.ok()) continue;
    // The arc's vertices and the region's own between its lines of contact.
    std::vector<int> compared = on_arc.arc;
    for (const int v : fitting) {
      if (std::binary_search(on_arc.inside.begin(), on_arc.inside.end(), v)) compared.push_back(v);
    }
    std::sort(compared.begin(), compared.end());
    compared.erase(std::unique(compared.begin(), compared.end()), compared.end());
    if (!TangentExplains(c, r, on_arc.round.surface, compared)) continue;
    RegionState& round = (*regions)[id];
    round.surface = on_arc.round.surface;
    round.shared_parameters = ParameterCount(SurfaceType::kCylinder) - kTangentRoundParameters;
    changed.push_back(id);
  }
  return changed;
}

}  // namespace meshseg::segment_internal
