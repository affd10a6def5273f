#include "segment/refit_to_interior.h"

#include <optional>

#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

// The mean square distance of `vertices` (sub-sampled as FitType samples
// them) to `surface`, as FitResult::rms_distance measures a fit's.
double MeanSquare(const SegmentContext& c, const Surface& surface,
                  const std::vector<int>& vertices) {
  const std::vector<int> sample = Sample(vertices);
  const SurfaceDistance distance_to(surface);
  double sum = 0.0;
  for (const int v : sample) {
    const double d = distance_to(c.position(v), c.curvature->smooth_normal[v]);
    sum += d * d;
  }
  return sample.empty() ? 0.0 : sum / static_cast<double>(sample.size());
}

// The surface region `id` (`r`) is proposed, if any (above).
std::optional<Surface> InteriorSurfaceOf(const SegmentContext& c, const std::vector<int>& labels,
                                         int id, const RegionState& r) {
  const int ids[] = {id};
  const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
  if (interior.size() < kMinInteriorVertices) return std::nullopt;
  if (ModelErrorOfMeanSquare(c, MeanSquare(c, r.surface, interior)) <=
      kMinModelError * c.noise_sigma) {
    return std::nullopt;
  }
  const FitResult fit = FitType(c, r.type, interior);
  if (!FitsAtNoise(c, fit)) return std::nullopt;
  return fit.surface;
}

}  // namespace

std::vector<InteriorSurface> ProposeInteriorSurfaces(const SegmentContext& c,
                                                     const std::vector<int>& labels,
                                                     const std::vector<RegionState>& regions,
                                                     KeptPrices* kept) {
  constexpr KeptPrices::Proposal kProposal = KeptPrices::kInteriorSurface;
  if (!(c.noise_sigma > 0.0) || c.on_facets) return {};
  const int n_regions = static_cast<int>(regions.size());
  if (kept != nullptr) kept->Reserve(regions.size());
  std::vector<std::optional<Surface>> proposed(n_regions);
  // Each region's proposal reads the labels and its region and writes its
  // own entries (of `proposed`, and `kept`'s): concurrent.
  tbb::parallel_for(0, n_regions, [&](int id) {
    const RegionState& r = regions[id];
    if (!r.alive || !IsCurved(r.type)) return;
    if (kept != nullptr && kept->Refused(regions, id, kProposal)) return;
    proposed[id] = InteriorSurfaceOf(c, labels, id, r);
    if (!proposed[id] && kept != nullptr) kept->Refuse(regions, id, kProposal);
  });
  std::vector<InteriorSurface> proposals;
  for (int id = 0; id < n_regions; ++id) {
    if (proposed[id]) proposals.push_back({.id = id, .surface = std::move(*proposed[id])});
  }
  return proposals;
}

absl::StatusOr<std::vector<int>> RefitToInterior(const SegmentContext& c,
                                                 std::vector<int>* labels,
                                                 std::vector<RegionState>* regions,
                                                 KeptPrices* kept) {
  std::vector<int> refitted;
  const std::vector<InteriorSurface> proposals =
      ProposeInteriorSurfaces(c, *labels, *regions, kept);
  if (proposals.empty()) return refitted;
  double energy = TotalEnergy(c, *labels, *regions);
  for (const InteriorSurface& p : proposals) {
    // An earlier accepted proposal's expansion may have emptied this region.
    if (!(*regions)[p.id].alive || (*regions)[p.id].vertices.empty()) continue;
    // The surface, then the expansion with re-estimation.
    RegionState r = (*regions)[p.id];
    r.surface = p.surface;
    r.shared_parameters = 0;  // fitted free
    MESHSEG_ASSIGN_OR_RETURN(Placed next,
                             PlacedByExpansion(c, *labels, *regions, p.id, std::move(r)));
    if (!(next.energy < energy)) continue;
    *labels = std::move(next.labels);
    *regions = std::move(next.regions);
    energy = next.energy;
    refitted.push_back(p.id);
  }
  return refitted;
}

}  // namespace meshseg::segment_internal
