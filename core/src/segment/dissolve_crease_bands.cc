#include "segment/dissolve_crease_bands.h"

#include <cmath>
#include <cstdint>

#include "segment/decide_type.h"

namespace meshseg::segment_internal {

int DissolveCreaseBands(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions) {
  int dissolved = 0;
  std::vector<uint8_t> grew(regions->size(), 0);
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    RegionState& region = (*regions)[id];
    if (!region.alive || region.vertices.empty() || region.type == SurfaceType::kPlane) continue;
    const std::vector<int> around = RegionsAround(c, *labels, *regions, id);
    if (around.empty()) continue;
    std::vector<int> nearest(region.vertices.size(), -1);
    std::size_t near = 0, own_near = 0;
    double own_sum2 = 0.0;
    double near_sum2 = 0.0;
    for (std::size_t k = 0; k < region.vertices.size(); ++k) {
      const double own = ProjectVertex(c, region.surface, region.vertices[k]).distance;
      own_sum2 += own * own;
      if (std::abs(own) < c.tolerance.distance) ++own_near;
      double best = HUGE_VAL;
      for (const int r : around) {
        const double d =
            std::abs(ProjectVertex(c, (*regions)[r].surface, region.vertices[k]).distance);
        if (d < best) {
          best = d;
          nearest[k] = r;
        }
      }
      if (best < c.tolerance.distance) ++near;
      near_sum2 += best * best;
    }
    const bool most_near = near > c.alpha * region.vertices.size() || near >= own_near;
    const bool at_noise = c.noise_sigma > 0.0 &&
                          ModelErrorOfMeanSquare(c, near_sum2 / region.vertices.size()) <=
                              kMinModelError * c.noise_sigma;
    if (!most_near || !(near_sum2 <= own_sum2 || at_noise)) continue;
    for (std::size_t k = 0; k < region.vertices.size(); ++k) {
      const int v = region.vertices[k];
      (*labels)[v] = nearest[k];
      (*regions)[nearest[k]].vertices.push_back(v);
      grew[nearest[k]] = 1;
    }
    region.vertices.clear();
    region.alive = false;
    ++dissolved;
  }
  if (dissolved == 0) return 0;
  RebuildVertexLists(*labels, regions);
  RefitRegions(c, grew, regions);
  return dissolved;
}

}  // namespace meshseg::segment_internal
