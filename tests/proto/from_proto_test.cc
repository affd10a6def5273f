#include <cmath>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/proto/convert.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

TEST(FromProto, UnsetOptionsGiveTheDefaults) {
  const absl::StatusOr<PipelineParams> p = FromProto(v1::SegmentOptions());
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_EQ(p->segment.distance_tolerance, SegmentParams{}.distance_tolerance);
  EXPECT_FALSE(p->segment.angle_tolerance_deg.has_value());
}

TEST(FromProto, CopiesTolerances) {
  v1::SegmentOptions o;
  o.set_distance_tolerance(0.8);
  o.set_angle_tolerance_deg(4.0);
  const absl::StatusOr<PipelineParams> p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_DOUBLE_EQ(p->segment.distance_tolerance, 0.8);
  EXPECT_DOUBLE_EQ(*p->segment.angle_tolerance_deg, 4.0);
}

TEST(FromProto, RejectsNanNegativeAndHugeTolerances) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), -1.0, 0.0, 1e9}) {
    v1::SegmentOptions o;
    o.set_distance_tolerance(bad);
    const absl::StatusOr<PipelineParams> p = FromProto(o);
    EXPECT_EQ(p.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(p.status().message(), HasSubstr("distance_tolerance"));
  }
  v1::SegmentOptions o;
  o.set_angle_tolerance_deg(120.0);
  EXPECT_THAT(FromProto(o).status().message(), HasSubstr("angle_tolerance_deg"));
}

TEST(FormatFromHint, KnowsEveryFormatInAnyCase) {
  EXPECT_FALSE(FormatFromHint("")->has_value());
  EXPECT_EQ(**FormatFromHint("STL"), FileFormat::kStl);
  EXPECT_EQ(**FormatFromHint("ply"), FileFormat::kPly);
  EXPECT_EQ(**FormatFromHint("pwn"), FileFormat::kPwn);
  const auto bad = FormatFromHint("step");
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(bad.status().message(), HasSubstr("step"));
}

TEST(FromProto, ReadsThePathAndTheExactTolerance) {
  v1::SegmentOptions o;
  o.set_segmentation_path(v1::SEGMENTATION_PATH_EXACT_FACETS);
  o.set_exact_tolerance(1e-6);
  const absl::StatusOr<PipelineParams> p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_EQ(p->segment.exact, ExactMode::kAlways);
  EXPECT_EQ(p->segment.exact_tolerance, 1e-6);
  o.set_segmentation_path(v1::SEGMENTATION_PATH_SCAN);
  EXPECT_EQ(FromProto(o)->segment.exact, ExactMode::kNever);
}

TEST(FromProto, RefusesANonPositiveExactToleranceAndTheRemeshedPath) {
  v1::SegmentOptions o;
  o.set_exact_tolerance(-1.0);
  absl::StatusOr<PipelineParams> p = FromProto(o);
  EXPECT_EQ(p.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(p.status().message().find("exact_tolerance"), std::string::npos) << p.status();
  v1::SegmentOptions remeshed;
  remeshed.set_segmentation_path(v1::SEGMENTATION_PATH_REMESHED);
  p = FromProto(remeshed);
  EXPECT_EQ(p.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(p.status().message().find("segmentation_path"), std::string::npos) << p.status();
}

}  // namespace
}  // namespace meshseg
