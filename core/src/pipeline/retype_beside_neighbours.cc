#include "pipeline/retype_beside_neighbours.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "meshseg/fit.h"
#include "pipeline/refit_regions.h"
#include "segment/decide_type.h"

namespace meshseg::pipeline_internal {
namespace {

// A bound on FitBeside's assign-and-refit rounds; if the assignment has not
// settled by then, the last fit stands.
constexpr int kMaxRounds = 8;

// The types a region may take here: the axial types.
constexpr SurfaceType kAxialTypes[] = {SurfaceType::kCylinder, SurfaceType::kCone};

bool Analytic(SurfaceType type) {
  return type == SurfaceType::kPlane || type == SurfaceType::kCylinder ||
         type == SurfaceType::kCone || type == SurfaceType::kSphere ||
         type == SurfaceType::kTorus;
}

// A fit of one type to the points it explains better than the neighbours'
// surfaces, and the mean square over all the band's points of the distance
// to the nearest of it and those surfaces.
struct BesideFit {
  FitResult fit;  // on the points it explains (rms, max over those)
  double mean_square = 0.0;
};

// Fits `type`, starting from `start`, alternately to the points nearer to
// it than `other_distance` (each point's distance to its nearest
// neighbouring surface) and again; nullopt if the fit fails or explains
// fewer than kMinRetypePoints points.
std::optional<BesideFit> FitBeside(SurfaceType type, const Surface& start,
                                   std::span<const Eigen::Vector3d> points,
                                   std::span<const double> other_distance) {
  Surface current = start;
  std::vector<uint8_t> mine(points.size(), 0), previous;
  std::vector<Eigen::Vector3d> own, normals;
  FitResult fit;
  for (int round = 0; round < kMaxRounds; ++round) {
    own.clear();
    normals.clear();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Projection p = Project(current, points[k]);
      mine[k] = std::abs(p.distance) <= other_distance[k];
      if (!mine[k]) continue;
      own.push_back(points[k]);
      normals.push_back(p.normal);
    }
    if (mine == previous) break;
    if (own.size() < kMinRetypePoints) return std::nullopt;
    fit = FitOfType(type, {.points = own, .normals = normals, .weights = {}});
    if (!fit.ok()) return std::nullopt;
    current = fit.surface;
    previous = mine;
  }
  BesideFit out{.fit = fit};
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double d = std::min(std::abs(SignedDistance(current, points[k])), other_distance[k]);
    out.mean_square += d * d;
  }
  out.mean_square /= static_cast<double>(points.size());
  return out;
}

}  // namespace

std::vector<std::vector<int>> RegionNeighbours(const TriMesh& mesh,
                                               std::span<const int> face_labels,
                                               std::size_t region_count) {
  std::vector<std::vector<int>> out(region_count);
  for (const auto f : mesh.faces()) {
    const int a = face_labels[f.idx()];
    if (a < 0) continue;
    for (const auto g : mesh.ff_range(f)) {
      const int b = face_labels[g.idx()];
      if (b >= 0 && b != a) out[a].push_back(b);
    }
  }
  for (std::vector<int>& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

int RetypeBesideNeighbours(std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                           std::span<const std::vector<int>> neighbours, double sigma,
                           std::vector<Region>* regions, std::vector<SharedSurface>* surfaces) {
  int changed = 0;
  std::vector<double> other_distance;
  std::vector<Eigen::Vector3d> normals;
  // Decided on the surfaces as they were before any retype here, so the
  // order of the regions does not matter.
  const std::vector<Region> before = *regions;
  for (Region& region : *regions) {
    const std::vector<Eigen::Vector3d>& points = points_of_region[region.id];
    const SurfaceType own_type = region.type;
    if ((own_type != SurfaceType::kTorus && own_type != SurfaceType::kCone &&
         own_type != SurfaceType::kSphere) ||
        points.size() < kMinRetypePoints) {
      continue;
    }
    other_distance.assign(points.size(), std::numeric_limits<double>::infinity());
    bool any = false;
    for (const int n : neighbours[region.id]) {
      const Region& other = before[n];
      if (!Analytic(other.type) || points_of_region[n].empty()) continue;
      any = true;
      for (std::size_t k = 0; k < points.size(); ++k) {
        other_distance[k] =
            std::min(other_distance[k], std::abs(SignedDistance(other.surface, points[k])));
      }
    }
    if (!any) continue;  // nothing beside it: RetypeToPoints has decided
    // The region's own hypothesis: all its band points on its surface (as
    // RetypeToPoints scores it), near the noise as there.
    segment_internal::SegmentContext c;
    c.noise_sigma = std::max(sigma, region.rms_distance);
    // A region whose points its neighbours' surfaces explain without it,
    // near the noise as its own type measures it, has no surface of its own
    // here (a fragment of a neighbour's surface): what a limit type fits of
    // the few points nearer to it is no evidence.
    double neighbours_only = 0.0;
    for (const double d : other_distance) neighbours_only += d * d;
    neighbours_only /= static_cast<double>(points.size());
    if (segment_internal::ModelErrorOfMeanSquare(c, neighbours_only) <=
        segment_internal::kScoredNearError * c.noise_sigma) {
      continue;
    }
    const double own_score = segment_internal::InformationScore(
        c, region.rms_distance * region.rms_distance, points.size(),
        segment_internal::ParameterCount(own_type));
    // The limit beside the neighbours claims every point lies on one of
    // the surfaces: near the cloud's noise, not the region's own scatter,
    // which the neighbours' points it holds inflate.
    segment_internal::SegmentContext cloud;
    cloud.noise_sigma = sigma;
    normals.clear();
    for (const Eigen::Vector3d& p : points) normals.push_back(Project(region.surface, p).normal);
    std::optional<std::pair<SurfaceType, BesideFit>> best;
    double best_score = std::numeric_limits<double>::infinity();
    for (const SurfaceType t : kAxialTypes) {
      // A limit of the region's type (a cylinder or cone of a torus, a
      // cylinder of a cone) must score less than kScoreMargin above it; an
      // axial type in place of a sphere (no limit of it, nor it of them)
      // kScoreMargin below it, its extra parameters paid (as in
      // RetypeToPoints).
      const bool limit = segment_internal::IsLimitOf(t, own_type);
      if (!limit && own_type != SurfaceType::kSphere) continue;
      const FitResult start = FitOfType(t, {.points = points, .normals = normals, .weights = {}});
      if (!start.ok()) continue;
      const std::optional<BesideFit> fit = FitBeside(t, start.surface, points, other_distance);
      if (!fit) continue;
      const double score = segment_internal::InformationScore(
          c, fit->mean_square, points.size(), segment_internal::ParameterCount(t));
      const bool near = segment_internal::ModelErrorOfMeanSquare(cloud, fit->mean_square) <=
                        segment_internal::kScoredNearError * sigma;
      if (near && score < best_score &&
          (limit ? score < own_score + segment_internal::kScoreMargin
                 : score + segment_internal::kScoreMargin < own_score)) {
        best_score = score;
        best.emplace(t, *fit);
      }
    }
    if (!best) continue;
    region.type = best->first;
    region.surface = best->second.fit.surface;
    region.rms_distance = best->second.fit.rms_distance;
    region.max_distance = best->second.fit.max_distance;
    TakeOwnSurface(&region, surfaces);
    ++changed;
  }
  return changed;
}

}  // namespace meshseg::pipeline_internal
