#include "segment/exact_fit.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "meshseg/fit.h"
#include "segment/decide_type.h"
#include "segment/facet_on_surface.h"
#include "segment/fit_exclusion.h"

namespace meshseg::segment_internal {
namespace {

// At most this many corners enter a fit (every k-th of a larger support).
constexpr std::size_t kMaxFitCorners = 2000;
// The corners of at most this many facets are told apart by a scan.
constexpr std::size_t kScannedFacets = kMaxSeedFacets;
// An exact fit iterates to the rounding of the numbers; from the initial
// fit of exact corners it converges in under ten steps, and a group that
// needs more lies on no surface of the type.
const FitParams kExactFit{.max_iterations = 25, .relative_tolerance = 1e-15, .refine = true};

// The distinct corners of `facets` with the area-weighted normals of the
// facets around each (in the group), every k-th if more than kMaxFitCorners;
// corners on a chord (facet_mesh.h: OnChord within tau) left out.
void FitCornersOf(const FacetMesh& fm, std::span<const int> facets, double tau,
                  std::vector<Eigen::Vector3d>* points, std::vector<Eigen::Vector3d>* normals) {
  std::unordered_map<int, int> slot;
  // A seed group's few corners are found by a scan (in scratch kept per
  // thread: allocating it cost as much); a region's by hashing.
  const bool scan = facets.size() <= kScannedFacets;
  thread_local std::vector<Eigen::Vector3d> scan_sum;
  thread_local std::vector<int> scan_order;
  std::vector<Eigen::Vector3d> region_sum;
  std::vector<int> region_order;
  std::vector<Eigen::Vector3d>& sum = scan ? scan_sum : region_sum;
  std::vector<int>& order = scan ? scan_order : region_order;
  sum.clear(), order.clear();
  for (const int f : facets) {
    for (const int v : fm.corners[f]) {
      int at = 0;
      if (scan) {
        at = static_cast<int>(std::find(order.begin(), order.end(), v) - order.begin());
      } else {
        at = slot.try_emplace(v, static_cast<int>(order.size())).first->second;
      }
      if (at == static_cast<int>(order.size())) {
        sum.push_back(Eigen::Vector3d::Zero());
        order.push_back(v);
      }
      sum[at] += fm.area[f] * fm.normal[f];
    }
  }
  const std::size_t stride =
      std::max<std::size_t>(1, (order.size() + kMaxFitCorners - 1) / kMaxFitCorners);
  points->clear();
  normals->clear();
  for (std::size_t i = 0; i < order.size(); i += stride) {
    if (OnChord(fm, order[i], tau)) continue;  // under a curved surface, by its sag
    points->push_back(fm.points[order[i]]);
    const double n = sum[i].norm();
    normals->push_back(n > 0.0 ? Eigen::Vector3d(sum[i] / n) : Eigen::Vector3d::UnitZ());
  }
}

int DistinctCorners(const FacetMesh& fm, std::span<const int> facets) {
  std::vector<int> v;
  v.reserve(3 * facets.size());
  for (const int f : facets) v.insert(v.end(), fm.corners[f].begin(), fm.corners[f].end());
  std::sort(v.begin(), v.end());
  return static_cast<int>(std::unique(v.begin(), v.end()) - v.begin());
}

int DistinctNormals(const FacetMesh& fm, std::span<const int> facets, int enough) {
  std::vector<Eigen::Vector3d> seen;
  for (const int f : facets) {
    const Eigen::Vector3d& n = fm.normal[f];
    if (n.isZero()) continue;
    const bool known = std::any_of(seen.begin(), seen.end(), [&](const Eigen::Vector3d& m) {
      return std::atan2(n.cross(m).norm(), n.dot(m)) < kDistinctNormal;
    });
    if (!known) seen.push_back(n);
    if (static_cast<int>(seen.size()) >= enough) break;
  }
  return static_cast<int>(seen.size());
}

// The axis a cylinder's chord facets give: each facet of a strip between
// two rulings contains the ruling direction, so its normal is perpendicular
// to the axis; the axis is the direction least along the facets' normals
// (area-weighted). Also returns `tilt`, the largest |n . axis| over the
// facets (0 for strips, small for a fine tessellation whose triangles cut
// across the rulings).
Eigen::Vector3d ChordAxis(const FacetMesh& fm, std::span<const int> facets, double* tilt) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const int f : facets) scatter += fm.area[f] * fm.normal[f] * fm.normal[f].transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Vector3d axis = eigen.eigenvectors().col(0);
  *tilt = 0.0;
  for (const int f : facets) *tilt = std::max(*tilt, std::abs(fm.normal[f].dot(axis)));
  return axis;
}

// The cylinder about `axis` through `points`: the circle through their
// projections across the axis (algebraic least squares); nullopt if the
// points are degenerate or any misses it by more than tau.
std::optional<Surface> CylinderAbout(const Eigen::Vector3d& axis,
                                     const std::vector<Eigen::Vector3d>& points, double tau) {
  const Eigen::Vector3d u = axis.unitOrthogonal();
  const Eigen::Vector3d v = axis.cross(u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) mean += p / static_cast<double>(points.size());
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = (points[i] - mean).dot(u), y = (points[i] - mean).dot(v);
    a.row(static_cast<Eigen::Index>(i)) << 2.0 * x, 2.0 * y, 1.0;
    b(static_cast<Eigen::Index>(i)) = x * x + y * y;
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  const double r2 = c(2) + c(0) * c(0) + c(1) * c(1);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  const Cylinder cylinder{
      .axis_origin = mean + c(0) * u + c(1) * v, .axis_direction = axis, .radius = std::sqrt(r2)};
  for (const Eigen::Vector3d& p : points) {
    if (!(std::abs(SignedDistance(cylinder, p)) <= tau)) return std::nullopt;
  }
  return Surface{cylinder};
}

}  // namespace

std::optional<Surface> FitExactly(const FacetMesh& fm, SurfaceType type,
                                  std::span<const int> facets, double tau) {
  // Per thread (at most kMaxFitCorners each; nothing here calls FitExactly).
  thread_local std::vector<Eigen::Vector3d> points, normals;
  FitCornersOf(fm, facets, tau, &points, &normals);
  // Corners on few rims lie on many cylinders (rim to rim strips: corners at
  // two heights only, and a cylinder of any tilt through them). The surface
  // is one whose axis is as perpendicular to the facets' normals as they
  // allow: a fit whose axis they tilt from by more than twice their least
  // tilt (ChordAxis) is another cylinder through the corners.
  double least_tilt = 0.0;
  const Eigen::Vector3d axis =
      type == SurfaceType::kCylinder ? ChordAxis(fm, facets, &least_tilt) : Eigen::Vector3d::Zero();
  const double max_tilt = 2.0 * least_tilt + kDistinctNormal;
  // A fit that a proof from the corners excludes (no surface of the type,
  // and for a cylinder none of an axis this tilt allows, lies within tau of
  // every corner) fails whatever its iterations do: not run.
  if (type == SurfaceType::kSphere && NoSphereWithin(points, tau)) return std::nullopt;
  if (type == SurfaceType::kCylinder) {
    std::vector<Eigen::Vector3d> facet_normals(facets.size());
    for (std::size_t i = 0; i < facets.size(); ++i) facet_normals[i] = fm.normal[facets[i]];
    if (NoCylinderWithin(points, facet_normals, max_tilt, tau)) return std::nullopt;
  }
  if (type == SurfaceType::kCylinder && ExcludeAxial(points, tau).cylinder) return std::nullopt;
  if (type == SurfaceType::kCone && ExcludeAxial(points, tau).cone) return std::nullopt;
  const FitResult fit =
      FitOfType(type, {.points = points, .normals = normals, .weights = {}}, kExactFit);
  const bool fits = fit.ok() && fit.max_distance <= tau;
  if (type != SurfaceType::kCylinder)
    return fits ? std::optional<Surface>(fit.surface) : std::nullopt;
  if (fits) {
    const Eigen::Vector3d& fitted = std::get<Cylinder>(fit.surface).axis_direction;
    double tilt = 0.0;
    for (const int f : facets) tilt = std::max(tilt, std::abs(fm.normal[f].dot(fitted)));
    if (tilt <= max_tilt) return fit.surface;
  }
  return CylinderAbout(axis, points, tau);
}

bool HoldsEvidence(const FacetMesh& fm, SurfaceType type, std::span<const int> facets) {
  if (type == SurfaceType::kPlane) return DistinctCorners(fm, facets) >= 4;
  return DistinctNormals(fm, facets, kMinCurvedFacets) >= kMinCurvedFacets &&
         DistinctCorners(fm, facets) >= ParameterCount(type) + kSpareCorners;
}

}  // namespace meshseg::segment_internal
