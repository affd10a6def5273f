#include "segment/exact_hypotheses.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>

#include <tbb/parallel_for.h>

#include "meshseg/fit.h"
#include "segment/facet_on_surface.h"
#include "segment/fit_exclusion.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// At most this many corners enter a fit (every k-th of a larger support).
constexpr std::size_t kMaxFitCorners = 2000;
// A support is grown and refitted at most this many times.
constexpr int kMaxGrowRounds = 3;
// Facet normals closer than this (radians) are one direction.
constexpr double kDistinctNormal = 1e-4;
// Seed groups stop growing at this many facets.
constexpr std::size_t kMaxSeedFacets = 48;
// The corners of at most this many facets are told apart by a scan.
constexpr std::size_t kScannedFacets = kMaxSeedFacets;
// An exact fit iterates to the rounding of the numbers; from the initial
// fit of exact corners it converges in under ten steps, and a group that
// needs more lies on no surface of the type.
const FitParams kExactFit{.max_iterations = 25, .relative_tolerance = 1e-15, .refine = true};

int ParameterCount(SurfaceType type) {
  switch (type) {
    case SurfaceType::kPlane:
      return 3;
    case SurfaceType::kCylinder:
      return 5;
    case SurfaceType::kCone:
      return 6;
    case SurfaceType::kSphere:
      return 4;
    case SurfaceType::kTorus:
      return 8;
    default:
      return 10;
  }
}

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

double Dihedral(const FacetMesh& fm, int f, int g) {
  const Eigen::Vector3d& a = fm.normal[f];
  const Eigen::Vector3d& b = fm.normal[g];
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The facets edge-connected to `seed` that meet the criterion for `surface`
// (the seed's own facets are taken as given), sorted.
std::vector<int> Support(const FacetMesh& fm, const Surface& surface, std::span<const int> seed,
                         double tau, std::vector<char>* mark) {
  std::vector<int> out(seed.begin(), seed.end());
  for (const int f : out) (*mark)[f] = 1;
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (const int g : fm.across[out[k]]) {
      if (g < 0 || (*mark)[g]) continue;
      (*mark)[g] = 1;  // tried; reset below
      if (FacetOnSurface(fm, g, surface, tau)) {
        out.push_back(g);
      } else {
        (*mark)[g] = 2;
      }
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (const int g : fm.across[out[k]]) {
      if (g >= 0) (*mark)[g] = 0;
    }
    (*mark)[out[k]] = 0;
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Grows `h` from its support, refitting on what it holds, until it stops
// growing or the refit no longer fits within tau.
void Grow(const FacetMesh& fm, double tau, Hypothesis* h) {
  // Marks of facets tried, all zero between calls (Support resets the ones it
  // sets): one array per thread, so that a hypothesis costs what it touches
  // rather than the size of the mesh.
  thread_local std::vector<char> mark;
  if (mark.size() < fm.corners.size()) mark.assign(fm.corners.size(), 0);
  for (int round = 0; round < kMaxGrowRounds; ++round) {
    std::vector<int> grown = Support(fm, h->surface, h->support, tau, &mark);
    const bool same = grown.size() == h->support.size();
    h->support = std::move(grown);
    if (same && round > 0) break;
    const std::optional<Surface> refit = FitExactly(fm, h->type, h->support, tau);
    if (!refit) break;
    h->surface = *refit;
  }
}

// f and the facets around it over edges at less than kSeedCreaseDeg, until
// they hold `corners` distinct corners (or kMaxSeedFacets facets): in
// rings (breadth first: a compact patch), or smoothest first (the next is
// the one across the flattest edge from the group: along a narrow band
// rather than over into the face beside it, but along the rulings of a
// finely tessellated cylinder, where a ring is better).
std::vector<int> SeedGroup(const FacetMesh& fm, int f, int corners, bool smoothest_first) {
  const double crease = kSeedCreaseDeg * kPi / 180.0;
  std::vector<int> group;
  std::vector<int> seen;
  using Entry = std::pair<double, int>;  // (order key, facet)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> next;
  next.emplace(0.0, f);
  double order = 0.0;
  while (!next.empty()) {
    const int g = next.top().second;
    next.pop();
    if (std::find(group.begin(), group.end(), g) != group.end()) continue;
    group.push_back(g);
    for (const int v : fm.corners[g]) {
      if (std::find(seen.begin(), seen.end(), v) == seen.end()) seen.push_back(v);
    }
    if (static_cast<int>(seen.size()) >= corners || group.size() >= kMaxSeedFacets) break;
    for (const int h : fm.across[g]) {
      if (h < 0 || fm.normal[h].isZero()) continue;
      const double angle = Dihedral(fm, g, h);
      if (angle < crease && std::find(group.begin(), group.end(), h) == group.end()) {
        next.emplace(smoothest_first ? angle : (order += 1.0), h);
      }
    }
  }
  return group;
}

// The seed groups tried, in order: (corners, smoothest first).
std::vector<std::pair<int, bool>> SeedShapes() {
  std::vector<std::pair<int, bool>> shapes;
  for (const int corners : kSeedCorners) {
    shapes.emplace_back(corners, false);
    shapes.emplace_back(corners, true);
  }
  return shapes;
}

// The first curved type that fits `group` exactly with every facet of it on
// the surface, if the group holds evidence for it.
std::optional<Hypothesis> CurvedFit(const FacetMesh& fm, const std::vector<int>& group,
                                    double tau) {
  for (const SurfaceType type :
       {SurfaceType::kCylinder, SurfaceType::kCone, SurfaceType::kSphere, SurfaceType::kTorus}) {
    if (!HoldsEvidence(fm, type, group)) continue;
    const std::optional<Surface> fit = FitExactly(fm, type, group, tau);
    if (!fit) continue;
    if (!std::all_of(group.begin(), group.end(),
                     [&](int g) { return FacetOnSurface(fm, g, *fit, tau); })) {
      continue;
    }
    Hypothesis h{.type = type, .surface = *fit, .support = group};
    std::sort(h.support.begin(), h.support.end());
    return h;
  }
  return std::nullopt;
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

// A cylinder or cone grown from facet f one neighbour at a time, each kept
// only if the group still fits the type exactly with every facet on it: the
// seed of a coarse round (a few strips of 15 degrees or more, rim to rim),
// whose facets meet tangent neighbours (a blend, a flat side) across
// flatter edges than their own, so that rings and smoothest-first groups
// reach over into the next face before they hold a round's evidence. Each
// neighbour of f (or of a facet in f's plane) across a bend is tried as the
// first: two strips fix a cylinder, and a wrong first bend fits nothing
// further.
std::optional<Hypothesis> StripsAt(const FacetMesh& fm, int f, double tau) {
  const double crease = kSeedCreaseDeg * kPi / 180.0;
  // f and the facets in its plane around it, then the bends out of them.
  std::vector<int> flat = {f};
  std::vector<int> bends;
  for (std::size_t k = 0; k < flat.size() && flat.size() < kMaxSeedFacets; ++k) {
    for (const int h : fm.across[flat[k]]) {
      if (h < 0 || fm.normal[h].isZero() || std::find(flat.begin(), flat.end(), h) != flat.end())
        continue;
      const double angle = Dihedral(fm, flat[k], h);
      if (angle < kDistinctNormal) {
        flat.push_back(h);
      } else if (angle < crease && std::find(bends.begin(), bends.end(), h) == bends.end()) {
        bends.push_back(h);
      }
    }
  }
  for (const SurfaceType type : {SurfaceType::kCylinder, SurfaceType::kCone}) {
    for (const int first : bends) {
      std::vector<int> group = flat;
      group.push_back(first);
      std::optional<Surface> fit = FitExactly(fm, type, group, tau);
      if (!fit) continue;
      std::vector<int> tried = group;
      for (std::size_t k = 0; k < group.size() && group.size() < kMaxSeedFacets; ++k) {
        for (const int h : fm.across[group[k]]) {
          if (h < 0 || fm.normal[h].isZero() || Dihedral(fm, group[k], h) >= crease ||
              std::find(tried.begin(), tried.end(), h) != tried.end()) {
            continue;
          }
          tried.push_back(h);
          group.push_back(h);
          const std::optional<Surface> next = FitExactly(fm, type, group, tau);
          // Without evidence yet the fit is one of many through the
          // corners (three rulings lie on cylinders of any tilt): the
          // corners decide; with it, the criterion on every facet.
          if (next && (!HoldsEvidence(fm, type, group) ||
                       std::all_of(group.begin(), group.end(),
                                   [&](int g) { return FacetOnSurface(fm, g, *next, tau); }))) {
            fit = next;
          } else {
            group.pop_back();
          }
        }
      }
      if (!HoldsEvidence(fm, type, group) || !std::all_of(group.begin(), group.end(), [&](int g) {
            return FacetOnSurface(fm, g, *fit, tau);
          })) {
        continue;
      }
      Hypothesis h{.type = type, .surface = *fit, .support = group};
      std::sort(h.support.begin(), h.support.end());
      return h;
    }
  }
  return std::nullopt;
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

std::optional<Hypothesis> PlaneAt(const FacetMesh& fm, int f, double tau) {
  if (fm.normal[f].isZero()) return std::nullopt;
  Hypothesis h{
      .type = SurfaceType::kPlane, .surface = Plane{fm.Centroid(f), fm.normal[f]}, .support = {f}};
  Grow(fm, tau, &h);
  if (!HoldsEvidence(fm, h.type, h.support)) return std::nullopt;
  return h;
}

std::optional<Hypothesis> CurvedAt(const FacetMesh& fm, int f, double tau) {
  // The seed shapes' fits are independent: they run in parallel, each in the
  // order of the shapes, and a fit is skipped once an earlier shape has
  // fitted (the earliest that fits and holds evidence when grown is the
  // seed's, as if tried one after the other).
  static const std::vector<std::pair<int, bool>> shapes = SeedShapes();
  const int count = static_cast<int>(shapes.size());
  std::vector<std::optional<Hypothesis>> fits(count);
  std::vector<char> tried(count, 0);
  std::atomic<int> first_fit{count};
  auto fit_shape = [&](int i) {
    fits[i] = CurvedFit(fm, SeedGroup(fm, f, shapes[i].first, shapes[i].second), tau);
    tried[i] = 1;
    if (fits[i]) {
      for (int k = first_fit.load(); i < k && !first_fit.compare_exchange_weak(k, i);) {
      }
    }
  };
  tbb::parallel_for(0, count, [&](int i) {
    if (i < first_fit.load()) fit_shape(i);
  });
  for (int i = 0; i < count; ++i) {
    if (!tried[i]) fit_shape(i);  // after an earlier fit that did not hold
    std::optional<Hypothesis>& h = fits[i];
    if (!h) continue;
    Grow(fm, tau, &*h);
    // A narrow seed can leave a simpler type undecided (a cone of a small
    // angle through a few rulings of a cylinder); the grown support decides.
    for (const SurfaceType simpler :
         {SurfaceType::kCylinder, SurfaceType::kCone, SurfaceType::kSphere}) {
      if (Simplicity(simpler) >= Simplicity(h->type)) break;
      if (const std::optional<Surface> fit = FitExactly(fm, simpler, h->support, tau)) {
        h->type = simpler;
        h->surface = *fit;
        Grow(fm, tau, &*h);
        break;
      }
    }
    if (HoldsEvidence(fm, h->type, h->support)) return h;
  }
  if (std::optional<Hypothesis> h = StripsAt(fm, f, tau)) {
    Grow(fm, tau, &*h);
    return h;
  }
  return std::nullopt;
}

void GrowHypothesis(const FacetMesh& fm, double tau, Hypothesis* h) { Grow(fm, tau, h); }

bool ExplainedLocally(const FacetMesh& fm, int f, double tau) {
  if (fm.normal[f].isZero()) return false;
  const Plane plane{fm.Centroid(f), fm.normal[f]};
  for (const int g : fm.across[f]) {
    if (g >= 0 && CornersOnSurface(fm, g, plane, tau)) return true;
  }
  for (const auto& [corners, smoothest_first] : SeedShapes()) {
    if (CurvedFit(fm, SeedGroup(fm, f, corners, smoothest_first), tau)) return true;
  }
  // A facet at its face's border: the facets around a neighbour may fit
  // where its own do not.
  for (const int g : fm.across[f]) {
    if (g < 0 || fm.normal[g].isZero()) continue;
    for (const auto& [corners, smoothest_first] : SeedShapes()) {
      const std::optional<Hypothesis> h =
          CurvedFit(fm, SeedGroup(fm, g, corners, smoothest_first), tau);
      if (h && FacetOnSurface(fm, f, h->surface, tau)) return true;
    }
  }
  return false;
}

}  // namespace meshseg::segment_internal
