// A generated part with its true labels as a segmentation state: every
// primitive one region of its true type on its true surface. The tests of
// the energy and of the loops over a part's vertices start from it.
#ifndef MESHSEG_TESTS_CORE_SEGMENT_TRUE_LABELS_H_
#define MESHSEG_TESTS_CORE_SEGMENT_TRUE_LABELS_H_

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "segment/energy.h"
#include "segment/estimate_noise.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

struct Labeled {
  GeneratedPart part;
  CurvatureField field;
  RunContext run;
  SegmentContext c;
  std::vector<int> labels;
  std::vector<RegionState> regions;  // one per primitive
};

// `name` at `noise` h (draw 7; voxel size `voxel`, 0 for the part's own)
// with the true labels, each region its primitive's true type and surface.
inline void BuildTrueLabels(const std::string& name, double noise, double voxel, Labeled* t) {
  absl::StatusOr<GeneratedPart> part =
      GeneratePart(name, {.voxel_size = voxel, .noise = noise, .seed = 7});
  ASSERT_TRUE(part.ok()) << part.status();
  t->part = *std::move(part);
  absl::StatusOr<CurvatureField> field = EstimateCurvature(t->part.mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  t->field = *std::move(field);
  const SegmentEstimates estimates =
      EstimateNoise(t->field, MeanEdgeLength(t->part.mesh.tri), {});
  t->c = MakeSegmentContext(t->part.mesh.tri, t->field, estimates, 0.9, t->run);
  t->labels = t->part.vertex_primitive;
  for (const PrimitiveTruth& p : t->part.primitives) {
    t->regions.push_back({.type = TypeOf(p.surface), .surface = p.surface, .vertices = {}});
  }
  RebuildVertexLists(t->labels, &t->regions);
}

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_TESTS_CORE_SEGMENT_TRUE_LABELS_H_
