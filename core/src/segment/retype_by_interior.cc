#include "segment/retype_by_interior.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "segment/decide_type.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kScoreMargin = 10.0;

constexpr std::array<SurfaceType, 4> kCurvedTypes = {SurfaceType::kCylinder, SurfaceType::kSphere,
                                                     SurfaceType::kCone, SurfaceType::kTorus};

// Free parameters of a curved type's surface.
int ParameterCount(SurfaceType type) {
  switch (type) {
    case SurfaceType::kCylinder:
      return 5;  // axis line 4, radius
    case SurfaceType::kSphere:
      return 4;
    case SurfaceType::kCone:
      return 6;  // apex 3, axis 2, angle
    case SurfaceType::kTorus:
      return 7;  // centre 3, axis 2, two radii
    default:
      return 0;
  }
}

bool IsCurved(SurfaceType type) {
  return std::find(kCurvedTypes.begin(), kCurvedTypes.end(), type) != kCurvedTypes.end();
}

// The type (of kCurvedTypes) to give a region with interior `interior` and
// type `own`; `own` if none scores kScoreMargin below it.
SurfaceType BestInteriorType(const SegmentContext& c, SurfaceType own,
                             const std::vector<int>& interior, FitResult* interior_fit) {
  std::array<FitResult, kCurvedTypes.size()> fits;
  double least_rms = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < kCurvedTypes.size(); ++t) {
    fits[t] = FitType(c, kCurvedTypes[t], interior);
    if (fits[t].ok()) least_rms = std::min(least_rms, fits[t].rms_distance);
  }
  // Only a type that fits at the noise tells types apart by their scores:
  // on a remeshed CAD export the residuals are the facets' chords, which
  // any type with more parameters follows better.
  if (!(least_rms <= std::hypot(c.noise_sigma, kMinModelError * c.noise_sigma))) return own;
  const double n = static_cast<double>(Sample(interior).size());
  const double sigma2 = c.noise_sigma * c.noise_sigma;
  std::array<double, kCurvedTypes.size()> score;
  std::size_t best = 0;
  double own_score = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < kCurvedTypes.size(); ++t) {
    score[t] = fits[t].ok() ? n * fits[t].rms_distance * fits[t].rms_distance / sigma2 +
                                  ParameterCount(kCurvedTypes[t]) * std::log(n)
                            : std::numeric_limits<double>::infinity();
    if (score[t] < score[best]) best = t;
    if (kCurvedTypes[t] == own) own_score = score[t];
  }
  if (!(score[best] + kScoreMargin < own_score)) return own;
  *interior_fit = fits[best];
  return kCurvedTypes[best];
}

}  // namespace

std::vector<int> InteriorVertices(const SegmentContext& c, const std::vector<int>& labels, int id,
                                  const RegionState& region) {
  std::vector<int> interior;
  for (const int v : region.vertices) {
    const auto around = c.graph.Neighbors(v);
    if (std::all_of(around.begin(), around.end(), [&](int u) { return labels[u] == id; })) {
      interior.push_back(v);
    }
  }
  return interior;
}

std::vector<int> RetypeByInterior(const SegmentContext& c, const std::vector<int>& labels,
                                  std::vector<RegionState>* regions) {
  const int n_regions = static_cast<int>(regions->size());
  std::vector<uint8_t> retyped(n_regions, 0);
  tbb::parallel_for(0, n_regions, [&](int id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type)) return;
    const std::vector<int> interior = InteriorVertices(c, labels, id, r);
    if (interior.size() < kMinInteriorVertices) return;
    FitResult interior_fit;
    const SurfaceType type = BestInteriorType(c, r.type, interior, &interior_fit);
    if (type == r.type) return;
    const FitResult whole = FitType(c, type, r.vertices);
    r.type = type;
    r.surface = whole.ok() ? whole.surface : interior_fit.surface;
    retyped[id] = 1;
  });
  std::vector<int> ids;
  for (int id = 0; id < n_regions; ++id) {
    if (retyped[id]) ids.push_back(id);
  }
  return ids;
}

}  // namespace meshseg::segment_internal
