#include "meshseg/proto/result_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace meshseg {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;

v1::SegmentationResult Sample() {
  v1::SegmentationResult r;
  r.mutable_mesh()->set_face_count(2);
  r.add_face_labels(0);
  r.add_face_labels(-1);
  v1::Region* region = r.add_regions();
  region->set_id(0);
  region->set_type(v1::SURFACE_TYPE_PLANE);
  region->mutable_plane()->mutable_normal()->set_z(1.0);
  return r;
}

TEST(ResultJson, UsesSnakeCaseNamesAndEnumNames) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_THAT(*json, HasSubstr("\"face_labels\":[0,-1]"));
  EXPECT_THAT(*json, HasSubstr("\"SURFACE_TYPE_PLANE\""));
  EXPECT_THAT(*json, HasSubstr("\"mean_edge_length\""));
  EXPECT_THAT(*json, ::testing::Not(HasSubstr("faceLabels")));
}

TEST(ResultJson, PrintsZeroValuesSuchAsRegionIdZero) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok());
  EXPECT_THAT(*json, HasSubstr("\"id\":0"));
}

TEST(ResultJson, IsOneLineEndingInANewline) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok());
  EXPECT_THAT(*json, EndsWith("}\n"));
  EXPECT_EQ(json->find('\n'), json->size() - 1);
}

TEST(ResultJson, SameMessageGivesSameBytesAfterAWireRoundTrip) {
  const v1::SegmentationResult a = Sample();
  v1::SegmentationResult b;
  ASSERT_TRUE(b.ParseFromString(a.SerializeAsString()));
  EXPECT_EQ(*ResultJson(a), *ResultJson(b));
}

}  // namespace
}  // namespace meshseg
