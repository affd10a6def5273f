#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/generate.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

TEST(GroundTruthJson, HoldsPrimitivesWithParametersAndOneLabelPerFace) {
  const auto part = GeneratePart("plate_boss", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  const std::string json = GroundTruthJson(*part);
  EXPECT_THAT(json, HasSubstr("\"name\": \"plate_boss\""));
  EXPECT_THAT(json, HasSubstr("\"voxel_size\": 1,"));
  EXPECT_THAT(json, HasSubstr("\"type\": \"torus\", \"torus\": {\"center\": {\"x\": "));
  EXPECT_THAT(json, HasSubstr("\"major_radius\": 14, \"minor_radius\": 4}"));
  EXPECT_THAT(json, HasSubstr("\"name\": \"bore\", \"type\": \"cylinder\", \"cylinder\": {"));
  EXPECT_THAT(json, HasSubstr("\"radius\": 5}"));
  EXPECT_THAT(json, HasSubstr("\"type\": \"plane\", \"plane\": {\"point\": "));
  // One entry per face in each array: count the commas between the brackets.
  for (const char* key : {"\"face_primitive\": [", "\"face_near_boundary\": ["}) {
    const size_t begin = json.find(key);
    ASSERT_NE(begin, std::string::npos) << key;
    const size_t end = json.find(']', begin);
    const std::string list = json.substr(begin, end - begin);
    EXPECT_EQ(static_cast<size_t>(std::count(list.begin(), list.end(), ',')) + 1,
              part->mesh.tri.n_faces()) << key;
  }
  EXPECT_EQ(json.back(), '\n');
  EXPECT_EQ(json[json.size() - 2], '}');
}

}  // namespace
}  // namespace meshseg
