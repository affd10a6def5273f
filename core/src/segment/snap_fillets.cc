#include "segment/snap_fillets.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "segment/absorb_leftovers.h"
#include "segment/align_coaxial.h"
#include "segment/decide_type.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

// The region's vertices (sub-sampled), each with its squared distance to
// the nearest surface of the analytic regions around it.
struct RegionPoints {
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> neighbor_sq;
};

RegionPoints MakeRegionPoints(const SegmentContext& c, const std::vector<RegionState>& regions,
                              int id, const std::vector<int>& neighbors) {
  RegionPoints points;
  for (const int v : Sample(regions[id].vertices)) {
    const Eigen::Vector3d& p = c.position(v);
    double nearest = std::numeric_limits<double>::infinity();
    for (const int n : neighbors) {
      if (!IsAnalytic(regions[n].type)) continue;
      const double d = SignedDistance(regions[n].surface, p);
      nearest = std::min(nearest, d * d);
    }
    points.positions.push_back(p);
    points.neighbor_sq.push_back(nearest);
  }
  return points;
}

// Mean over `points` of each one's squared distance to the nearest of the
// surfaces around the region, `extra` (if set) and `torus`.
double MeanSquare(const RegionPoints& points, const Surface* extra, const Surface& torus) {
  double sum = 0.0;
  for (std::size_t k = 0; k < points.positions.size(); ++k) {
    const Eigen::Vector3d& p = points.positions[k];
    double nearest = std::min(std::pow(SignedDistance(torus, p), 2), points.neighbor_sq[k]);
    if (extra != nullptr) nearest = std::min(nearest, std::pow(SignedDistance(*extra, p), 2));
    sum += nearest;
  }
  return sum / static_cast<double>(points.positions.size());
}

// The minimum of `cost` over [low, high]: the best of kGrid geometric
// steps, refined by golden section between the steps beside it. Returns
// (argument, value).
std::pair<double, double> MinimizeOnGrid(const std::function<double(double)>& cost, double low,
                                         double high) {
  constexpr int kGrid = 40, kGoldenSteps = 40;
  const double step = std::pow(high / low, 1.0 / (kGrid - 1));
  std::pair<double, double> best{low, std::numeric_limits<double>::infinity()};
  int arg = 0;
  for (int k = 0; k < kGrid; ++k) {
    const double x = low * std::pow(step, k);
    const double f = cost(x);
    if (f < best.second) best = {x, f}, arg = k;
  }
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = low * std::pow(step, std::max(arg - 1, 0));
  double b = low * std::pow(step, std::min(arg + 1, kGrid - 1));
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = cost(x1), f2 = cost(x2);
  for (int k = 0; k < kGoldenSteps; ++k) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = cost(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = cost(x2);
    }
  }
  if (f1 < best.second) best = {x1, f1};
  if (f2 < best.second) best = {x2, f2};
  return best;
}

struct FilletFit {
  Torus torus;
  double mean_square = std::numeric_limits<double>::infinity();
};

// The fillet between `plane` and `cylinder` that meets `points` best (with
// `plane` among the surfaces around if it is `swallowed`): on each side of
// each, r from kMinRadiusShare to kMaxRadiusShare of the region's own
// minor radius.
FilletFit FitFillet(const RegionPoints& points, const Plane& plane, bool swallowed,
                    const Cylinder& cylinder, double own_minor) {
  constexpr double kMinRadiusShare = 0.25, kMaxRadiusShare = 2.0;
  const Surface plane_surface = plane;
  FilletFit best;
  for (const int axial : {-1, 1}) {
    for (const int radial : {-1, 1}) {
      const double low = kMinRadiusShare * own_minor;
      double high = kMaxRadiusShare * own_minor;
      // Inside the cylinder the ball must fit: a major radius above 0.
      if (radial < 0) high = std::min(high, 0.95 * cylinder.radius);
      if (!(high > low)) continue;
      const auto [r, mean_square] = MinimizeOnGrid(
          [&](double r) {
            return MeanSquare(points, swallowed ? &plane_surface : nullptr,
                              FilletTorus(plane, cylinder, r, axial, radial));
          },
          low, high);
      if (mean_square < best.mean_square) {
        best = {FilletTorus(plane, cylinder, r, axial, radial), mean_square};
      }
    }
  }
  return best;
}

// The flat face a round grew over: the plane across `axis` through the
// region's vertices whose n'_i is within th_nm of it (on the side most
// are), if there are kMinRegionVertices of them.
std::optional<Plane> SwallowedPlane(const SegmentContext& c, const std::vector<int>& vertices,
                                    const Eigen::Vector3d& axis) {
  const double cos_max = std::cos(c.angle_tolerance_deg * std::numbers::pi / 180.0);
  Eigen::Vector3d sum[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::size_t count[2] = {0, 0};
  for (const int v : vertices) {
    const double cos = c.normal(v).dot(axis);
    if (std::abs(cos) <= cos_max) continue;
    const int side = cos > 0.0 ? 0 : 1;
    sum[side] += c.position(v);
    ++count[side];
  }
  const int side = count[0] >= count[1] ? 0 : 1;
  if (count[side] < kMinRegionVertices) return std::nullopt;
  return Plane{.point = sum[side] / static_cast<double>(count[side]),
               .normal = side == 0 ? axis : Eigen::Vector3d(-axis)};
}

// The best fillet for torus region `id` between a plane and a cylinder
// around it whose normal and axis are within kCoaxialMaxAngleDeg of its
// axis; with no such plane, the plane it swallowed (SwallowedPlane) is
// tried and returned in `swallowed`.
std::optional<FilletFit> BestFillet(const SegmentContext& c,
                                    const std::vector<RegionState>& regions, int id,
                                    const std::vector<int>& neighbors, const RegionPoints& points,
                                    std::optional<Plane>* swallowed) {
  const Torus& own = std::get<Torus>(regions[id].surface);
  const double cos_max = std::cos(kCoaxialMaxAngleDeg * std::numbers::pi / 180.0);
  std::vector<Plane> planes;
  std::vector<const Cylinder*> cylinders;
  for (const int n : neighbors) {
    const Surface& s = regions[n].surface;
    if (const auto* p = std::get_if<Plane>(&s);
        p && std::abs(p->normal.dot(own.axis_direction)) > cos_max) {
      planes.push_back(*p);
    }
    if (const auto* cyl = std::get_if<Cylinder>(&s);
        cyl && std::abs(cyl->axis_direction.dot(own.axis_direction)) > cos_max) {
      cylinders.push_back(cyl);
    }
  }
  if (cylinders.empty()) return std::nullopt;
  std::optional<Plane> hidden;
  if (planes.empty()) {
    hidden = SwallowedPlane(c, regions[id].vertices, own.axis_direction);
    if (!hidden) return std::nullopt;
    planes.push_back(*hidden);
  }
  FilletFit best;
  for (const Plane& plane : planes) {
    for (const Cylinder* cylinder : cylinders) {
      const FilletFit fit =
          FitFillet(points, plane, hidden.has_value(), *cylinder, own.minor_radius);
      if (fit.mean_square < best.mean_square) best = fit;
    }
  }
  *swallowed = hidden;
  return best;
}

// Hands each vertex of region `id` to the nearest of `fillet`, the analytic
// regions around it and `swallowed` (a new plane region, if it gets
// kMinRegionVertices), if that is within th_dis; marks the regions that
// changed in `refit`.
void HandOver(const SegmentContext& c, int id, const Torus& fillet,
              const std::vector<int>& neighbors, const std::optional<Plane>& swallowed,
              std::vector<int>* labels, std::vector<RegionState>* regions,
              std::vector<uint8_t>* refit) {
  const Surface fillet_surface = fillet;
  const Surface plane_surface = swallowed ? Surface(*swallowed) : Surface();
  std::vector<int> on_plane;
  for (const int v : (*regions)[id].vertices) {
    const Eigen::Vector3d& p = c.position(v);
    double nearest = std::abs(SignedDistance(fillet_surface, p));
    int to = id;
    for (const int n : neighbors) {
      if (!IsAnalytic((*regions)[n].type)) continue;
      const double d = std::abs(SignedDistance((*regions)[n].surface, p));
      if (d < nearest && d < c.tolerance.distance) nearest = d, to = n;
    }
    if (swallowed &&
        std::abs(SignedDistance(plane_surface, p)) < std::min(nearest, c.tolerance.distance)) {
      on_plane.push_back(v);
      continue;
    }
    (*labels)[v] = to;
    (*refit)[to] = 1;
  }
  (*regions)[id].surface = fillet;
  // Too few for a region of their own: they stay with the fillet.
  if (on_plane.size() < kMinRegionVertices) return;
  for (const int v : on_plane) (*labels)[v] = static_cast<int>(regions->size());
  regions->push_back(
      RegionState{.type = SurfaceType::kPlane, .surface = *swallowed, .vertices = {}});
  refit->push_back(1);
}

}  // namespace

Torus FilletTorus(const Plane& plane, const Cylinder& cylinder, double r, int axial, int radial) {
  Eigen::Vector3d a = cylinder.axis_direction.normalized();
  if (a.dot(plane.normal) < 0.0) a = -a;
  const double t = (plane.point - cylinder.axis_origin).dot(plane.normal) / a.dot(plane.normal);
  const Eigen::Vector3d foot = cylinder.axis_origin + t * a;
  return Torus{.center = foot + axial * r * a,
               .axis_direction = a,
               .major_radius = cylinder.radius + radial * r,
               .minor_radius = r};
}

std::vector<int> SnapFillets(const SegmentContext& c, std::vector<int>* labels,
                             std::vector<RegionState>* regions) {
  std::vector<int> snapped;
  if (!(c.noise_sigma > 0.0)) return snapped;
  std::vector<uint8_t> refit(regions->size(), 0);
  const int n_regions = static_cast<int>(regions->size());
  for (int id = 0; id < n_regions; ++id) {
    const RegionState& r = (*regions)[id];
    if (!r.alive || r.type != SurfaceType::kTorus || !std::holds_alternative<Torus>(r.surface) ||
        !TypeMissesInterior(c, *labels, id, r)) {
      continue;
    }
    const std::vector<int> neighbors = RegionsAround(c, *labels, *regions, id);
    const RegionPoints points = MakeRegionPoints(c, *regions, id, neighbors);
    std::optional<Plane> swallowed;
    const std::optional<FilletFit> fillet =
        BestFillet(c, *regions, id, neighbors, points, &swallowed);
    if (!fillet) continue;
    // r, and the swallowed plane's offset along the axis.
    const int parameters = swallowed ? 2 : 1;
    const std::size_t m = points.positions.size();
    if (!(InformationScore(c, fillet->mean_square, m, parameters) + kScoreMargin <
          InformationScore(c, MeanSquare(points, nullptr, r.surface), m, ParameterCount(r.type)))) {
      continue;
    }
    HandOver(c, id, fillet->torus, neighbors, swallowed, labels, regions, &refit);
    snapped.push_back(id);
  }
  if (snapped.empty()) return snapped;
  RebuildVertexLists(*labels, regions);
  RefitRegions(c, refit, regions);
  return snapped;
}

}  // namespace meshseg::segment_internal
