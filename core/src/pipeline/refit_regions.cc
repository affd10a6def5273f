#include "pipeline/refit_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <variant>

#include "meshseg/fit.h"
#include "segment/decide_type.h"

namespace meshseg::pipeline_internal {
namespace {

// The types a curved region may take on its points.
constexpr SurfaceType kRetypeCandidates[] = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                             SurfaceType::kCone};

struct Distances {
  double rms = 0.0;
  double max = 0.0;
};

Distances DistancesTo(const Surface& surface, std::span<const Eigen::Vector3d> points) {
  Distances d;
  for (const Eigen::Vector3d& p : points) {
    const double e = std::abs(SignedDistance(surface, p));
    d.rms += e * e;
    d.max = std::max(d.max, e);
  }
  d.rms = points.empty() ? 0.0 : std::sqrt(d.rms / static_cast<double>(points.size()));
  return d;
}

// The mean over `points` of their squared distances to `surface`, each at
// most band^2 (a point beyond the band counts as one on its edge).
double CappedMeanSquare(const Surface& surface, std::span<const Eigen::Vector3d> points,
                        double band) {
  if (points.empty()) return 0.0;
  double sum = 0.0;
  for (const Eigen::Vector3d& p : points) {
    const double e = std::abs(SignedDistance(surface, p));
    sum += std::min(e, band) * std::min(e, band);
  }
  return sum / static_cast<double>(points.size());
}

// The fit of `type` to `points` (normals: the current surface's), then
// again to the points within `band` of that fit, as the pipeline fits a
// region to its band; rms/max distances are those of the band's points. No
// value if either fit is invalid or the band holds fewer than
// kMinRetypePoints.
std::optional<FitResult> FitOnOwnBand(SurfaceType type, std::span<const Eigen::Vector3d> points,
                                      std::span<const Eigen::Vector3d> normals, double band) {
  const FitResult first = FitOfType(type, {.points = points, .normals = normals, .weights = {}});
  if (!first.ok()) return std::nullopt;
  std::vector<Eigen::Vector3d> kept;
  std::vector<Eigen::Vector3d> kept_normals;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (std::abs(SignedDistance(first.surface, points[k])) <= band) {
      kept.push_back(points[k]);
      kept_normals.push_back(normals[k]);
    }
  }
  if (kept.size() == points.size()) return first;
  if (kept.size() < kMinRetypePoints) return std::nullopt;
  const FitResult second =
      FitOfType(type, {.points = kept, .normals = kept_normals, .weights = {}});
  if (!second.ok()) return std::nullopt;
  return second;
}

}  // namespace

std::vector<Eigen::Vector3d> WithinBand(const Surface& surface,
                                        std::span<const Eigen::Vector3d> points, double band) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : points) {
    if (std::abs(SignedDistance(surface, p)) <= band) out.push_back(p);
  }
  return out;
}

void RefitOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                          double distance_tolerance, std::vector<Region>* regions) {
  // Vertex lists per region: the corners of its faces, each once.
  std::vector<std::vector<int>> members(regions->size());
  std::vector<int> last_region(mesh.n_vertices(), -1);
  for (const auto f : mesh.faces()) {
    const int r = face_labels[f.idx()];
    if (r < 0) continue;
    for (const auto v : mesh.fv_range(f)) {
      // Faces of one region mostly come in runs; a vertex may still be
      // listed twice when they do not, which only weights it double.
      if (last_region[v.idx()] == r) continue;
      last_region[v.idx()] = r;
      members[r].push_back(v.idx());
    }
  }
  std::vector<std::vector<Eigen::Vector3d>> points(regions->size());
  for (std::size_t r = 0; r < members.size(); ++r) {
    std::vector<int>& ids = members[r];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (const int v : ids) points[r].push_back(ToEigen(mesh.point(TriMesh::VertexHandle(v))));
  }
  RefitToPoints(points, distance_tolerance, regions);
}

void RefitToPoints(std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                   double distance_tolerance, std::vector<Region>* regions) {
  std::vector<Eigen::Vector3d> normals;
  for (Region& region : *regions) {
    const std::vector<Eigen::Vector3d>& points = points_of_region[region.id];
    if (points.empty()) continue;  // nothing to refit to, nothing to measure
    normals.clear();
    for (const Eigen::Vector3d& p : points) {
      normals.push_back(Project(region.surface, p, Eigen::Vector3d::Zero()).normal);
    }
    const Distances before = DistancesTo(region.surface, points);
    const FitResult refit =
        FitOfType(region.type, {.points = points, .normals = normals, .weights = {}});
    if (refit.ok() && refit.rms_distance < before.rms) {
      region.surface = refit.surface;
      region.rms_distance = refit.rms_distance;
      region.max_distance = refit.max_distance;
    } else {
      region.rms_distance = before.rms;
      region.max_distance = before.max;
    }
    // A cone fitted on the remesh's chords can be a cylinder on the input's
    // own vertices: one that does not widen (a CAD tessellation in
    // micrometres: an edge round, 0.29 degrees on the remesh, 0.009 on the
    // input, 39 um wider over 250 mm), or one the cylinder fits as closely
    // (the same tessellation with its coordinates jittered by 1e-12: a corner
    // round 4 remesh edges high went to a cone of 7.7 degrees on an axis 8.5
    // degrees off, rms 0.14 on the input, where the cylinder fits to 2e-6).
    const auto* cone = std::get_if<Cone>(&region.surface);
    if (cone != nullptr) {
      const FitResult cylinder =
          FitOfType(SurfaceType::kCylinder, {.points = points, .normals = normals, .weights = {}});
      if (cylinder.ok() && (ConeWidening(*cone, points) < distance_tolerance ||
                            cylinder.rms_distance <= region.rms_distance)) {
        region.type = SurfaceType::kCylinder;
        region.surface = cylinder.surface;
        region.rms_distance = cylinder.rms_distance;
        region.max_distance = cylinder.max_distance;
      }
    }
  }
}

void TakeOwnSurface(Region* region, std::vector<SharedSurface>* surfaces) {
  // Off the shared surface it was on (whose other regions keep it), onto
  // one of its own; a surface it was alone on becomes its new one.
  const bool shared = region->surface_id >= 0 &&
                      region->surface_id < static_cast<int>(surfaces->size()) &&
                      (*surfaces)[region->surface_id].regions.size() > 1;
  if (shared) std::erase((*surfaces)[region->surface_id].regions, region->id);
  if (shared || region->surface_id < 0 ||
      region->surface_id >= static_cast<int>(surfaces->size())) {
    region->surface_id = static_cast<int>(surfaces->size());
    surfaces->push_back({.id = region->surface_id});
  }
  SharedSurface& mine = (*surfaces)[region->surface_id];
  mine.type = region->type;
  mine.surface = region->surface;
  mine.regions = {region->id};
  mine.rms_distance = region->rms_distance;
  mine.max_distance = region->max_distance;
}

int RetypeToPoints(std::span<const std::vector<Eigen::Vector3d>> points_of_region, double band,
                   double sigma, std::vector<Region>* regions, std::vector<SharedSurface>* surfaces,
                   std::vector<std::vector<Eigen::Vector3d>>* band_points) {
  int changed = 0;
  std::vector<Eigen::Vector3d> normals;
  for (Region& region : *regions) {
    const std::vector<Eigen::Vector3d>& points = points_of_region[region.id];
    const SurfaceType own = region.type;
    if (own == SurfaceType::kPlane || own == SurfaceType::kQuadric ||
        own == SurfaceType::kFreeform || points.size() < kMinRetypePoints) {
      continue;
    }
    normals.clear();
    for (const Eigen::Vector3d& p : points) {
      normals.push_back(Project(region.surface, p, Eigen::Vector3d::Zero()).normal);
    }
    // The criterion needs only the noise: the cloud's, or the scatter the
    // region's own type leaves on its band if larger (the cloud's sigma
    // comes from local planes; range noise along oblique rays scatters
    // points more across a surface), so "near the noise" means "near what
    // the own type achieves".
    segment_internal::SegmentContext c;
    c.noise_sigma = std::max(sigma, region.rms_distance);
    // Every type is scored on the same points, all the region's, each at
    // its distance to that type's own fit capped at the band. The fit a
    // type is judged by is its own band's: fitted to all the points, then
    // again to those within the band of that fit. Judged instead on the
    // points within the band of the region's current surface, the
    // comparison is the current type's: where the region holds a flat side
    // and the rounded crease to its neighbour, a cylinder bent to the
    // crease keeps the crease's points in its band and drops the side's
    // points it misses, and on that set a plane scores worse although the
    // side's points lie on one at the noise. With the cap, a point beyond a
    // type's band costs the band's square whichever type leaves it there (a
    // neighbour's point, or one the type cannot reach), so a type gains
    // nothing by the points it chooses to leave out, and a point it
    // explains counts its distance.
    const double own_ms = CappedMeanSquare(region.surface, points, band);
    const double own_score = segment_internal::InformationScore(
        c, own_ms, points.size(), segment_internal::ParameterCount(own));
    std::optional<std::pair<SurfaceType, FitResult>> best;
    double best_score = std::numeric_limits<double>::infinity();
    for (const SurfaceType t : kRetypeCandidates) {
      // A plane is a limit of every curved type (IsLimitOf covers the
      // family around an axis). A sphere and the axial types are no limits
      // of each other, so that rule never moves a region between them; but
      // the reconstruction closes a bore seen near its rim only into a
      // sphere of its radius, which the points, deeper down the band, can
      // refute: a sphere may become a cylinder or cone when that scores
      // kScoreMargin below it (its extra parameters paid). Not the other
      // way: over a band too short to fix a cylinder's axis a sphere fits as
      // closely with one parameter fewer, and on a chamfer whose points
      // include the rounded crease bands beyond both its edges it fits
      // better; neither is evidence of a sphere. Nor a more general type of
      // the region's own family (a torus for a cone): its extra parameters
      // bend to those crease bands.
      const bool limit = t == SurfaceType::kPlane || segment_internal::IsLimitOf(t, own);
      const bool axial_of_sphere = own == SurfaceType::kSphere &&
                                   (t == SurfaceType::kCylinder || t == SurfaceType::kCone);
      if (!limit && !axial_of_sphere) continue;
      const std::optional<FitResult> fit = FitOnOwnBand(t, points, normals, band);
      if (!fit) continue;
      const double ms = CappedMeanSquare(fit->surface, points, band);
      const double score = segment_internal::InformationScore(c, ms, points.size(),
                                                              segment_internal::ParameterCount(t));
      // Near the noise on its own band: the points it explains.
      const double band_ms = fit->rms_distance * fit->rms_distance;
      const bool near = segment_internal::ModelErrorOfMeanSquare(c, band_ms) <=
                        segment_internal::kScoredNearError * c.noise_sigma;
      if (near && score < best_score &&
          (limit ? score < own_score + segment_internal::kScoreMargin
                 : score + segment_internal::kScoreMargin < own_score)) {
        best_score = score;
        best.emplace(t, *fit);
      }
    }
    if (!best) continue;
    region.type = best->first;
    region.surface = best->second.surface;
    region.rms_distance = best->second.rms_distance;
    region.max_distance = best->second.max_distance;
    ++changed;
    TakeOwnSurface(&region, surfaces);
    if (band_points != nullptr) {
      (*band_points)[region.id] = WithinBand(region.surface, points, band);
    }
  }
  return changed;
}

int RelabelFacesOffTheirSurface(const TriMesh& mesh, std::span<const Region> regions, double exact,
                                std::vector<int>* face_labels) {
  // The farthest corner of face f from region r's surface.
  auto farthest_corner = [&](TriMesh::FaceHandle f, int r) {
    double farthest = 0.0;
    for (const auto v : mesh.fv_range(f)) {
      farthest =
          std::max(farthest, std::abs(SignedDistance(regions[r].surface, ToEigen(mesh.point(v)))));
    }
    return farthest;
  };
  const std::vector<int> before = *face_labels;
  int moved = 0;
  for (const auto f : mesh.faces()) {
    const int own = before[f.idx()];
    if (own < 0) continue;
    const double own_distance = farthest_corner(f, own);
    if (!(own_distance > exact)) continue;
    int best = own;
    double best_distance = 0.5 * own_distance;
    for (const auto g : mesh.ff_range(f)) {
      const int other = before[g.idx()];
      if (other < 0 || other == own) continue;
      const double distance = farthest_corner(f, other);
      if (distance < best_distance) best = other, best_distance = distance;
    }
    if (best != own) {
      (*face_labels)[f.idx()] = best;
      ++moved;
    }
  }
  return moved;
}

}  // namespace meshseg::pipeline_internal
