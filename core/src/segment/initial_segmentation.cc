#include "segment/initial_segmentation.h"

#include "meshseg/status_macros.h"
#include "segment/decide_type.h"
#include "segment/grow_region.h"
#include "segment/seeds.h"

namespace meshseg::segment_internal {
namespace {

constexpr int kStopCheckEvery = 16;  // seeds between stop checks
// A curved region whose best analytic type fits at least this fraction
// (but not alpha) has grown past its surface, typically into a tangent
// plane: it keeps only the fitting vertices and regrows with that type.
constexpr double kTrimFraction = 0.75;

// Grows `region` with the surface of `typed.type` and stores the result.
void GrowTyped(const SegmentContext& c, const TypedFit& typed, int id, std::vector<int>* labels,
               RegionState* region) {
  region->type = typed.type;
  region->surface = typed.fit.surface;
  SurfaceModel model(typed.type);
  if (GrowRegion(c, &model, c.tolerance, id, labels, &region->vertices)) {
    region->surface = model.fit().surface;
  }
}

}  // namespace

void GrowAndType(const SegmentContext& c, int id, std::vector<int>* labels,
                 std::vector<RegionState>* regions) {
  RegionState& region = (*regions)[id];
  HeightModel height;
  GrowRegion(c, &height, c.tolerance, id, labels, &region.vertices);
  // seed 000 §3 step 3: a plane if alpha of the vertices fit one.
  if (auto plane = PlaneIfFits(c, region.vertices, c.tolerance)) {
    GrowTyped(c, *plane, id, labels, &region);
    return;
  }
  // Step 4: grow on with the general quadric; step 5: decide the type.
  SurfaceModel quadric(SurfaceType::kQuadric);
  GrowRegion(c, &quadric, c.tolerance, id, labels, &region.vertices);
  TypedFit typed = DecideCurvedType(c, region.vertices, c.tolerance);
  if (typed.fraction > c.alpha) {
    GrowTyped(c, typed, id, labels, &region);
    return;
  }
  if (typed.fraction >= kTrimFraction) {
    std::erase_if(region.vertices, [&](int v) {
      if (Fits(c, v, ProjectVertex(c, typed.fit.surface, v), c.tolerance)) return false;
      (*labels)[v] = -1;
      return true;
    });
    GrowTyped(c, typed, id, labels, &region);
    return;
  }
  region.type = SurfaceType::kQuadric;
  region.surface = FitType(c, SurfaceType::kQuadric, region.vertices).surface;
}

absl::Status GrowInitialRegions(const SegmentContext& c, std::vector<int>* labels,
                                std::vector<RegionState>* regions) {
  const std::vector<int> order = SeedOrder(c);
  NeighborhoodScratch scratch;
  std::size_t labelled = 0;
  int tried = 0;
  for (const int i : order) {
    if ((*labels)[i] != -1) continue;
    if (++tried % kStopCheckEvery == 0) {
      MESHSEG_RETURN_IF_ERROR(c.run->CheckStop("segment"));
      c.run->Progress("segment", 0.6 * labelled / c.vertex_count());
    }
    std::vector<int> seed = CollectSeed(c, i, *labels, &scratch);
    if (seed.empty()) continue;
    const int id = static_cast<int>(regions->size());
    for (const int v : seed) (*labels)[v] = id;
    regions->push_back(RegionState{.type = SurfaceType::kQuadric,
                                   .surface = Quadric{},
                                   .vertices = std::move(seed),
                                   .alive = true});
    GrowAndType(c, id, labels, regions);
    labelled += (*regions)[id].vertices.size();
  }
  return absl::OkStatus();
}

}  // namespace meshseg::segment_internal
