#include "mesh/ply_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "temp_file.h"

namespace meshseg::mesh_internal {
namespace {

const Source kSrc{"read_mesh", "h.ply"};

TEST(ParsePlyHeader, ReadsElementsPropertiesAndBodyOffset) {
  const std::string text =
      "ply\nformat binary_big_endian 1.0\ncomment x\nelement vertex 3\nproperty float32 x\n"
      "property uint8 red\nelement face 1\nproperty list uchar uint vertex_indices\n"
      "end_header\nBODY";
  const absl::StatusOr<PlyHeader> header = ParsePlyHeader(text, kSrc);
  ASSERT_TRUE(header.ok()) << header.status();
  EXPECT_EQ(header->encoding, PlyEncoding::kBinaryBigEndian);
  ASSERT_EQ(header->elements.size(), 2u);
  EXPECT_EQ(header->elements[0].count, 3);
  EXPECT_EQ(header->elements[0].Find("red"), 1);
  EXPECT_EQ(header->elements[0].Find("z"), -1);
  const PlyProperty& list = header->elements[1].properties[0];
  EXPECT_TRUE(list.is_list);
  EXPECT_EQ(list.count_type, PlyType::kUint8);
  EXPECT_EQ(list.type, PlyType::kUint32);
  EXPECT_EQ(text.substr(header->body_offset), "BODY");
}

TEST(ParsePlyHeader, RejectsFloatListCount) {
  const absl::StatusOr<PlyHeader> header = ParsePlyHeader(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\nend_header\n", kSrc);
  ASSERT_EQ(header.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(testing_files::Message(header.status()),
              ::testing::HasSubstr("header line 4: bad list count type"));
}

TEST(ParsePlyHeader, RejectsMissingMagic) {
  EXPECT_EQ(ParsePlyHeader("plx\nend_header\n", kSrc).status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(PlyTypeSize, MatchesTheSpec) {
  EXPECT_EQ(PlyTypeSize(PlyType::kInt8), 1);
  EXPECT_EQ(PlyTypeSize(PlyType::kUint16), 2);
  EXPECT_EQ(PlyTypeSize(PlyType::kFloat32), 4);
  EXPECT_EQ(PlyTypeSize(PlyType::kFloat64), 8);
}

}  // namespace
}  // namespace meshseg::mesh_internal
