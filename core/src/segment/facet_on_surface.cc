#include "segment/facet_on_surface.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "meshseg/fit.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

double AngleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

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
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& p = fm.points[fm.corners[f][k]];
    const Projection pr = Project(surface, p, foot.normal);
    if (!(std::abs(pr.distance) <= tau)) return false;  // (1)
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
  if (!(tilt <= spread + own)) return false;                           // (2)
  return std::abs(foot.distance) <= tau + reach * std::tan(0.5 * spread);  // (3)
}

}  // namespace meshseg::segment_internal
