#include "segment/merge_same_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "segment/decide_type.h"
#include "segment/region_graph.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

constexpr std::array<SurfaceType, 5> kAnalyticTypes = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                                       SurfaceType::kSphere, SurfaceType::kCone,
                                                       SurfaceType::kTorus};

bool IsAnalytic(SurfaceType type) {
  return std::find(kAnalyticTypes.begin(), kAnalyticTypes.end(), type) != kAnalyticTypes.end();
}

struct UnionTest {
  double gain = 0.0;  // score of two surfaces minus score of one
  SurfaceType type = SurfaceType::kQuadric;
};

UnionTest TestUnion(const SegmentContext& c, const std::vector<int>& labels, int a, int b,
                    const std::vector<RegionState>& regions) {
  const int ids[] = {a, b};
  const std::vector<int> part_a = InteriorVertices(c, labels, ids, regions[a].vertices);
  const std::vector<int> part_b = InteriorVertices(c, labels, ids, regions[b].vertices);
  UnionTest out;
  if (part_a.size() < kMinInteriorVertices || part_b.size() < kMinInteriorVertices) return out;
  std::vector<int> both = part_a;
  both.insert(both.end(), part_b.begin(), part_b.end());
  std::sort(both.begin(), both.end());
  const SurfaceType type_a = regions[a].type;
  const SurfaceType type_b = regions[b].type;
  const FitResult fit_a = FitType(c, type_a, part_a);
  const FitResult fit_b = FitType(c, type_b, part_b);
  if (!fit_a.ok() || !fit_b.ok()) return out;
  const double squares = part_a.size() * fit_a.rms_distance * fit_a.rms_distance +
                         part_b.size() * fit_b.rms_distance * fit_b.rms_distance;
  const double two = InformationScore(c, squares / both.size(), both.size(),
                                      ParameterCount(type_a) + ParameterCount(type_b));
  for (const SurfaceType type : kAnalyticTypes) {
    const FitResult fit = FitType(c, type, both);
    if (!FitsAtNoise(c, fit)) continue;
    const double gain = two - InformationScore(c, fit.rms_distance * fit.rms_distance, both.size(),
                                               ParameterCount(type));
    if (gain > out.gain) out = UnionTest{.gain = gain, .type = type};
  }
  return out;
}

}  // namespace

int MergeSameSurface(const SegmentContext& c, std::vector<int>* labels,
                     std::vector<RegionState>* regions) {
  if (!(c.noise_sigma > 0.0)) return 0;
  std::map<std::pair<int, int>, UnionTest> cache;
  int merges = 0;
  while (true) {
    const std::vector<RegionArc> arcs = BuildRegionGraph(c, *labels, *regions);
    const RegionArc* best_arc = nullptr;
    const UnionTest* best = nullptr;
    for (const RegionArc& arc : arcs) {
      const SurfaceType type_a = (*regions)[arc.a].type;
      const SurfaceType type_b = (*regions)[arc.b].type;
      if (!arc.smooth || !IsAnalytic(type_a) || !IsAnalytic(type_b) ||
          (type_a == SurfaceType::kPlane && type_b == SurfaceType::kPlane)) {
        continue;
      }
      auto it = cache.find({arc.a, arc.b});
      if (it == cache.end()) {
        it = cache.emplace(std::pair{arc.a, arc.b}, TestUnion(c, *labels, arc.a, arc.b, *regions))
                 .first;
      }
      if (!(it->second.gain > kScoreMargin)) continue;
      if (best == nullptr || it->second.gain > best->gain) {
        best = &it->second;
        best_arc = &arc;
      }
    }
    if (best == nullptr) return merges;
    const int a = best_arc->a;
    const int b = best_arc->b;
    const bool a_larger = (*regions)[a].vertices.size() >= (*regions)[b].vertices.size();
    const int into = a_larger ? a : b;
    const SurfaceType type = best->type;
    MergeInto(into, a_larger ? b : a, labels, regions);
    RegionState& merged = (*regions)[into];
    merged.type = type;
    const FitResult fit = FitType(c, type, merged.vertices);
    if (fit.ok()) merged.surface = fit.surface;
    ++merges;
    std::erase_if(cache, [&](const auto& e) {
      return e.first.first == a || e.first.second == a || e.first.first == b || e.first.second == b;
    });
  }
}

}  // namespace meshseg::segment_internal
