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

// The curved type to give a region of type `own` with interior `interior`
// (`own` if none scores kScoreMargin below it), and its fit there.
SurfaceType BestInteriorType(const SegmentContext& c, SurfaceType own,
                             const std::vector<int>& interior, FitResult* interior_fit) {
  const auto scored = ScoreCurvedTypes(c, interior);
  if (std::none_of(scored.begin(), scored.end(),
                   [&](const ScoredFit& s) { return FitsAtNoise(c, s.fit); })) {
    return own;
  }
  const ScoredFit* best = &scored.front();
  double own_score = std::numeric_limits<double>::infinity();
  for (const ScoredFit& s : scored) {
    if (s.score < best->score) best = &s;
    if (s.type == own) own_score = s.score;
  }
  if (!(best->score + kScoreMargin < own_score)) return own;
  *interior_fit = best->fit;
  return best->type;
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
