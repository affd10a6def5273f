#include "pipeline/input_labels.h"

#include <vector>

#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace meshseg::pipeline_internal {
namespace {

using ::testing::ElementsAre;

TEST(InputFaceLabels, DroppedInputFacesGetMinusOneAndOthersKeepOrder) {
  // Input faces 0..4; face 2 was dropped while loading, so input faces 3 and 4
  // became mesh faces 2 and 3.
  const std::vector<int> face_of_input = {0, 1, -1, 2, 3};
  const std::vector<int> mesh_labels = {7, 7, 4, -1};
  EXPECT_THAT(InputFaceLabels(face_of_input, mesh_labels), ElementsAre(7, 7, -1, 4, -1));
}

TEST(InputFaceLabels, PolygonFacesTakeTheLabelOfTheirFirstTriangle) {
  // A quad (input face 0) became mesh faces 0 and 1; input face 1 is face 2.
  const std::vector<int> face_of_input = {0, 2};
  const std::vector<int> mesh_labels = {3, 3, 5};
  EXPECT_THAT(InputFaceLabels(face_of_input, mesh_labels), ElementsAre(3, 5));
}

}  // namespace
}  // namespace meshseg::pipeline_internal
