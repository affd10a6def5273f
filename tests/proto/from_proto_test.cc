#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

TEST(FromProto, OpenUnsupportedLeavesTheReconstructionOpen) {
  EXPECT_FALSE(FromProto(v1::SegmentOptions())->reconstruct.leave_unsupported_open);
  v1::SegmentOptions o;
  o.set_open_unsupported(true);
  const absl::StatusOr<PipelineParams> p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_TRUE(p->reconstruct.leave_unsupported_open);
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

// Every option refused at a bound, past it, NaN and Inf, with its field and
// range named; the values just inside are accepted.
TEST(FromProto, RefusesEveryOptionOutsideItsRangeNamingFieldAndRange) {
  struct Case {
    void (v1::SegmentOptions::*set)(double);
    const char* range_text;
    double inside;
    std::vector<double> outside;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
      {&v1::SegmentOptions::set_distance_tolerance,
       "distance_tolerance must be in (0, 100]",
       100.0,
       {0.0, -0.5, 100.5, nan, inf}},
      {&v1::SegmentOptions::set_angle_tolerance_deg,
       "angle_tolerance_deg must be in (0, 90)",
       89.9,
       {90.0, 0.0, -3.0, 180.0, nan, -inf}},
  };
  for (const Case& c : cases) {
    v1::SegmentOptions good;
    (good.*c.set)(c.inside);
    EXPECT_TRUE(FromProto(good).ok()) << c.range_text << " " << c.inside;
    for (const double bad : c.outside) {
      v1::SegmentOptions o;
      (o.*c.set)(bad);
      const absl::Status s = FromProto(o).status();
      EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument) << c.range_text << " " << bad;
      EXPECT_THAT(s.message(), HasSubstr(c.range_text)) << bad;
    }
  }
}

TEST(LengthUnitFromWire, KnowsTheStepUnitsInAnyCaseAndNamesAnUnknownOne) {
  EXPECT_EQ(*LengthUnitFromWire("length_unit", ""), "");
  EXPECT_EQ(*LengthUnitFromWire("length_unit", "MM"), "mm");
  EXPECT_EQ(*LengthUnitFromWire("length_unit", "uin"), "uin");
  const absl::Status bad = LengthUnitFromWire("length_unit", "furlong").status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_EQ(bad.message(),
            "length_unit \"furlong\" is not one of mm, cm, m, km, in, ft, mi, mil, um, uin");
}

TEST(StepUnitFromWire, StepUnitThenLengthUnitThenMillimetres) {
  EXPECT_EQ(*StepUnitFromWire("", ""), "mm");
  EXPECT_EQ(*StepUnitFromWire("", "In"), "in");
  EXPECT_EQ(*StepUnitFromWire("CM", ""), "cm");
  EXPECT_EQ(*StepUnitFromWire("cm", "CM"), "cm");
  absl::Status bad = StepUnitFromWire("parsec", "mm").status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_THAT(bad.message(), HasSubstr("step_unit \"parsec\" is not one of mm,"));
  bad = StepUnitFromWire("mm", "yd").status();
  EXPECT_THAT(bad.message(), HasSubstr("length_unit \"yd\" is not one of mm,"));
  // Coordinates are written unscaled: a STEP unit other than the input's
  // would scale the part.
  bad = StepUnitFromWire("in", "mm").status();
  EXPECT_TRUE(absl::IsInvalidArgument(bad)) << bad;
  EXPECT_THAT(bad.message(), HasSubstr("step_unit \"in\" is not length_unit \"mm\""));
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

TEST(FormatFromHint, KnowsTheVolumeFormats) {
  EXPECT_EQ(**FormatFromHint("nrrd"), FileFormat::kNrrd);
  EXPECT_EQ(**FormatFromHint("MHA"), FileFormat::kMha);
  EXPECT_EQ(**FormatFromHint("mhd"), FileFormat::kMhd);
  EXPECT_EQ(**FormatFromHint("raw"), FileFormat::kRaw);
}

TEST(FromProto, ReadsTheVolumeOptions) {
  v1::SegmentOptions o;
  o.set_iso_value(1500.0);
  o.set_volume_mode("binary");
  const absl::StatusOr<PipelineParams> p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_EQ(p->volume.iso, 1500.0);
  EXPECT_EQ(p->volume.mode, VolumeMode::kBinary);
  o.set_volume_mode("fuzzy");
  EXPECT_THAT(FromProto(o).status().message(), HasSubstr("volume_mode \"fuzzy\""));
  o.set_volume_mode("");
  o.set_iso_value(std::numeric_limits<double>::quiet_NaN());
  EXPECT_THAT(FromProto(o).status().message(), HasSubstr("iso_value"));
}

TEST(RawLayoutFromProto, TakesTheHeadersRawFieldsAndRefusesBadOnes) {
  v1::UploadHeader h;
  PipelineParams params;
  ASSERT_TRUE(RawLayoutFromProto(h, &params).ok());
  EXPECT_FALSE(params.volume.read.raw.has_value());  // none given
  for (int64_t d : {64, 32, 16}) h.add_raw_dims(d);
  for (double s : {0.5, 0.5, 1.0}) h.add_raw_spacing(s);
  h.set_raw_voxel_type("int16");
  ASSERT_TRUE(RawLayoutFromProto(h, &params).ok());
  ASSERT_TRUE(params.volume.read.raw.has_value());
  EXPECT_EQ(params.volume.read.raw->dims[1], 32);
  EXPECT_EQ(params.volume.read.raw->spacing.z(), 1.0);
  EXPECT_EQ(params.volume.read.raw->type, VoxelType::kInt16);
  h.set_raw_voxel_type("double");
  EXPECT_THAT(RawLayoutFromProto(h, &params).message(), HasSubstr("voxel type \"double\""));
  h.set_raw_voxel_type("uint8");
  h.add_raw_dims(8);
  EXPECT_THAT(RawLayoutFromProto(h, &params).message(), HasSubstr("4 dims given, need 3"));
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

namespace meshseg {
namespace {

TEST(FromProto, FreeformFitIsOnUnlessTurnedOffAndTakesAFractionInRange) {
  v1::SegmentOptions o;
  absl::StatusOr<PipelineParams> p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_TRUE(p->freeform.enabled);
  EXPECT_EQ(p->freeform.subdiv.face_fraction, 0.05);
  o.set_freeform_fit(false);
  o.set_freeform_face_fraction(0.1);
  p = FromProto(o);
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_FALSE(p->freeform.enabled);
  EXPECT_EQ(p->freeform.subdiv.face_fraction, 0.1);
  for (double bad : {0.0, -0.1, 0.3, std::nan("")}) {
    o.set_freeform_face_fraction(bad);
    p = FromProto(o);
    ASSERT_FALSE(p.ok()) << bad;
    EXPECT_THAT(p.status().message(),
                ::testing::HasSubstr("freeform_face_fraction must be in (0, 0.25]"));
  }
}

}  // namespace
}  // namespace meshseg
