#include "topology/trace_loops.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "labelled_meshes.h"

namespace meshseg::topology_internal {
namespace {

// The gridded box's six sides with +x relabelled -x: label 0 has two
// patches (the sides do not touch), numbered in order of their lowest face;
// an unlabelled face is in none.
TEST(LabelPatches, NumbersEachLabelsFaceComponentsByTheirLowestFace) {
  testing::LabelledMesh box = testing::GriddedBox({2.0, 3.0, 4.0}, 4);
  std::vector<int> labels = box.face_labels;
  const auto first_of = [&](int label) {
    return static_cast<int>(std::find(labels.begin(), labels.end(), label) - labels.begin());
  };
  const int first_minus_x = first_of(0);
  const int first_plus_x = first_of(1);
  for (int& l : labels) {
    if (l == 1) l = 0;
  }
  const int unlabelled = first_of(3);
  labels[unlabelled] = -1;
  const FacePatches patches = LabelPatches(box.mesh.tri, labels, 6);
  EXPECT_EQ(patches.patch_count, std::vector<int>({2, 0, 1, 1, 1, 1}));
  EXPECT_EQ(patches.face_patch[unlabelled], -1);
  const bool minus_x_first = first_minus_x < first_plus_x;
  for (std::size_t f = 0; f < labels.size(); ++f) {
    if (labels[f] < 0) continue;
    const int side = box.face_labels[f];
    const int expected = side == 0 ? (minus_x_first ? 0 : 1) : side == 1 ? (minus_x_first ? 1 : 0) : 0;
    ASSERT_EQ(patches.face_patch[f], expected) << "face " << f << " of side " << side;
  }
}

}  // namespace
}  // namespace meshseg::topology_internal
