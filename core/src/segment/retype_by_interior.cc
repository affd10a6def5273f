#include "segment/retype_by_interior.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <tbb/parallel_for.h>

#include "segment/decide_type.h"

namespace meshseg::segment_internal {
namespace {

constexpr std::array<SurfaceType, 4> kCurvedTypes = {SurfaceType::kCylinder, SurfaceType::kSphere,
                                                     SurfaceType::kCone, SurfaceType::kTorus};

// The curved type to give a region of type `own` with interior `interior`
// (`own` if none scores kScoreMargin below it), and its fit there.
SurfaceType BestInteriorType(const SegmentContext& c, SurfaceType own,
                             const std::vector<int>& interior, FitResult* interior_fit) {
  std::array<FitResult, kCurvedTypes.size()> fits;
  bool any_at_noise = false;
  for (std::size_t t = 0; t < kCurvedTypes.size(); ++t) {
    fits[t] = FitType(c, kCurvedTypes[t], interior);
    any_at_noise = any_at_noise || FitsAtNoise(c, fits[t]);
  }
  if (!any_at_noise) return own;
  std::size_t best = 0;
  double best_score = std::numeric_limits<double>::infinity();
  double own_score = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < kCurvedTypes.size(); ++t) {
    if (!fits[t].ok()) continue;
    const double score = InformationScore(c, fits[t].rms_distance * fits[t].rms_distance,
                                          interior.size(), ParameterCount(kCurvedTypes[t]));
    if (score < best_score) {
      best_score = score;
      best = t;
    }
    if (kCurvedTypes[t] == own) own_score = score;
  }
  if (!(best_score + kScoreMargin < own_score)) return own;
  *interior_fit = fits[best];
  return kCurvedTypes[best];
}

}  // namespace

std::vector<int> InteriorVertices(const SegmentContext& c, const std::vector<int>& labels,
                                  std::span<const int> ids, std::span<const int> vertices) {
  std::vector<int> interior;
  for (const int v : vertices) {
    const auto around = c.graph.Neighbors(v);
    if (std::all_of(around.begin(), around.end(), [&](int u) {
          return std::find(ids.begin(), ids.end(), labels[u]) != ids.end();
        })) {
      interior.push_back(v);
    }
  }
  return interior;
}

std::vector<int> RetypeByInterior(const SegmentContext& c, const std::vector<int>& labels,
                                  std::vector<RegionState>* regions) {
  if (!(c.noise_sigma > 0.0)) return {};  // a noise-free mesh: nothing fits "at the noise"
  const int n_regions = static_cast<int>(regions->size());
  std::vector<uint8_t> retyped(n_regions, 0);
  tbb::parallel_for(0, n_regions, [&](int id) {
    RegionState& r = (*regions)[id];
    if (!r.alive || !IsCurved(r.type)) return;
    const int ids[] = {id};
    const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
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
