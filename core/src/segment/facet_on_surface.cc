#include "segment/facet_on_surface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include "meshseg/fit.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The largest principal curvature of `surface` at the corners `p` (a cone:
// cos(half angle) over the least distance from its axis); 0 for a plane or
// a quadric.
double LargestCurvature(const Surface& surface, const std::array<Eigen::Vector3d, 3>& p) {
  if (const auto* c = std::get_if<Cylinder>(&surface)) return 1.0 / c->radius;
  if (const auto* s = std::get_if<Sphere>(&surface)) return 1.0 / s->radius;
  if (const auto* t = std::get_if<Torus>(&surface)) return 1.0 / t->minor_radius;
  if (const auto* c = std::get_if<Cone>(&surface)) {
    double rho = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& x : p) {
      const Eigen::Vector3d d = x - c->apex;
      rho = std::min(rho, (d - d.dot(c->axis_direction) * c->axis_direction).norm());
    }
    return rho > 0.0 ? std::cos(c->half_angle) / rho : std::numeric_limits<double>::infinity();
  }
  return 0.0;
}

}  // namespace

bool ChordOnSurface(const FacetMesh& fm, int v, const Surface& surface, double tau) {
  if (!OnChord(fm, v, tau)) return false;
  for (const int end : fm.ChordEnds(v)) {
    if (!(std::abs(SignedDistance(surface, fm.points[end])) <= tau)) return false;
  }
  return true;
}

bool CornersOnSurface(const FacetMesh& fm, int f, const Surface& surface, double tau) {
  for (const int v : fm.corners[f]) {
    if (!(std::abs(SignedDistance(surface, fm.points[v])) <= tau)) return false;
  }
  return true;
}

bool FacetOnSurface(const FacetMesh& fm, int f, const Surface& surface, double tau) {
  const Eigen::Vector3d& n = fm.normal[f];
  if (n.isZero()) return CornersOnSurface(fm, f, surface, tau);
  const Eigen::Vector3d centroid = fm.Centroid(f);
  const Projection foot = Project(surface, centroid);
  double spread = 0.0, reach = 0.0, longest = 0.0;
  std::array<double, 3> along{};  // n . the surface's normal at each corner
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& p = fm.points[fm.corners[f][k]];
    const Projection pr = Project(surface, p, foot.normal);
    if (!(std::abs(pr.distance) <= tau) && !ChordOnSurface(fm, fm.corners[f][k], surface, tau)) {
      return false;  // (1)
    }
    along[k] = n.dot(pr.normal);
    spread = std::max(spread, AngleBetween(pr.normal, foot.normal));
    reach = std::max(reach, (p - centroid).norm());
    longest = std::max(longest, (fm.points[fm.corners[f][(k + 1) % 3]] - p).norm());
  }
  if (!(spread < kMaxSpreadDeg * kPi / 180.0)) return false;  // (4)
  const double height = 2.0 * fm.area[f] / longest;
  // Corners at depths differing by up to the facet's sag (and tau each)
  // tilt its plane by as much over its least height.
  const double own = std::atan2(2.0 * (tau + std::abs(foot.distance)), height);
  const double tilt = std::min(AngleBetween(n, foot.normal), AngleBetween(-n, foot.normal));
  if (!(tilt <= spread + own)) return false;  // (2)
  if (std::holds_alternative<Quadric>(surface)) return true;
  // (5): the surface over a chord facet is a graph over the facet's plane,
  // so its normal at every corner points to the same side of that plane, at
  // less than a right angle to the facet's normal by more than the tilt tau
  // gives the facet over its least height.
  const double least = std::sin(std::atan2(2.0 * tau, height));
  const bool up = along[0] > 0.0;
  for (const double a : along) {
    if (!((up ? a : -a) > least)) return false;
  }
  // (3): a point within `reach` of corners on a surface of curvature at most
  // kappa lies under it by at most the sag of a sphere of radius 1/kappa.
  const std::array<Eigen::Vector3d, 3> corners = {
      fm.points[fm.corners[f][0]], fm.points[fm.corners[f][1]], fm.points[fm.corners[f][2]]};
  const double kappa = LargestCurvature(surface, corners);
  double sag = 0.0;
  if (kappa > 0.0) {
    const double r = 1.0 / kappa;
    sag = reach >= r ? r : r - std::sqrt(r * r - reach * reach);
  }
  return std::abs(foot.distance) <= tau + sag;
}

}  // namespace meshseg::segment_internal
