// rounded_prism at noise 0.15 h with its true segmentation, for tests of the
// boundary steps: six radius-3.5 fillets (about 10 h), each tangent to two
// planes; one region per true primitive with its true surface, and the
// generator's label per vertex.
#ifndef MESHSEG_TESTS_CORE_SEGMENT_ROUNDED_PRISM_TRUTH_H_
#define MESHSEG_TESTS_CORE_SEGMENT_ROUNDED_PRISM_TRUTH_H_

#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "segment/estimate_noise.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal::testing {

class RoundedPrismTruth : public ::testing::Test {
 protected:
  void SetUp() override {
    absl::StatusOr<GeneratedPart> part = GeneratePart("rounded_prism", {.noise = 0.15, .seed = 7});
    ASSERT_TRUE(part.ok()) << part.status();
    part_ = *std::move(part);
    absl::StatusOr<CurvatureField> field = EstimateCurvature(part_.mesh);
    ASSERT_TRUE(field.ok()) << field.status();
    field_ = *std::move(field);
    estimates_ = EstimateNoise(field_, MeanEdgeLength(part_.mesh.tri), {});
    for (const PrimitiveTruth& p : part_.primitives) {
      regions_.push_back({.type = TypeOf(p.surface), .surface = p.surface, .vertices = {}});
    }
  }

  bool IsPlane(int r) const { return r >= 0 && regions_[r].type == SurfaceType::kPlane; }

  // What region growing does at high noise: every plane takes `rings` rings
  // of the fillets next to it, each vertex that meets (5) and (6) for it.
  // Returns the vertices taken; `labels` holds the result.
  std::vector<int> PlanesTakeFilletRings(const SegmentContext& c, int rings,
                                         std::vector<int>* labels) const {
    *labels = part_.vertex_primitive;
    std::vector<int> taken;
    for (int ring = 0; ring < rings; ++ring) {
      std::vector<int> next = *labels;
      for (int v = 0; v < c.vertex_count(); ++v) {
        if ((*labels)[v] < 0 || IsPlane((*labels)[v])) continue;
        for (const int u : c.graph.Neighbors(v)) {
          if (!IsPlane((*labels)[u])) continue;
          if (Fits(c, v, ProjectVertex(c, regions_[(*labels)[u]].surface, v), c.tolerance)) {
            next[v] = (*labels)[u];
          }
        }
        if (next[v] != (*labels)[v]) taken.push_back(v);
      }
      labels->swap(next);
    }
    return taken;
  }

  GeneratedPart part_;
  CurvatureField field_;
  SegmentEstimates estimates_;
  std::vector<RegionState> regions_;  // the true regions, no vertex lists
  RunContext run_;
};

}  // namespace meshseg::segment_internal::testing

#endif  // MESHSEG_TESTS_CORE_SEGMENT_ROUNDED_PRISM_TRUTH_H_
