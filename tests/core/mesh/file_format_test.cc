#include "mesh/file_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;
using testing_files::WriteTemp;

TEST(DetectFileFormat, KnowsVolumesByExtensionAndMagic) {
  EXPECT_EQ(*DetectFileFormat(WriteTemp("v.nrrd", "x")), FileFormat::kNrrd);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("v.NHDR", "x")), FileFormat::kNrrd);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("v.mha", "x")), FileFormat::kMha);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("v.mhd", "x")), FileFormat::kMhd);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("v.raw", "x")), FileFormat::kRaw);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("scan", "NRRD0004\ntype: uint8\n")), FileFormat::kNrrd);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("scan2", "ObjectType = Image\nNDims = 3\n")), FileFormat::kMha);
  EXPECT_TRUE(IsVolumeFormat(FileFormat::kRaw));
  EXPECT_FALSE(IsVolumeFormat(FileFormat::kPly));
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("ct.nrrd", "NRRD0004\n"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_THAT(Message(mesh.status()), ::testing::HasSubstr("volume is not a mesh"));
}

TEST(DetectFileFormat, UsesExtensionInAnyCase) {
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.STL", "x")), FileFormat::kStl);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.Obj", "x")), FileFormat::kObj);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.off", "x")), FileFormat::kOff);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.ply", "x")), FileFormat::kPly);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.xyz", "x")), FileFormat::kXyz);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("a.pwn", "x")), FileFormat::kPwn);
}

TEST(DetectFileFormat, SniffsContentWithoutExtension) {
  EXPECT_EQ(*DetectFileFormat(WriteTemp("ply_file", "ply\nformat ascii 1.0\n")), FileFormat::kPly);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("stl_file", "solid x\nfacet normal 0 0 1\n")),
            FileFormat::kStl);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("off_file", "OFF\n3 1 0\n")), FileFormat::kOff);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("obj_file", "# c\nv 0 0 0\n")), FileFormat::kObj);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("pwn_file", "2\n0 0 0\n1 1 1\n")), FileFormat::kPwn);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("xyz_file", "0,0,0\n1,1,1\n")), FileFormat::kXyz);
  EXPECT_EQ(*DetectFileFormat(WriteTemp("binary_stl_file",
                                        testing_files::BinaryStl(testing_files::CubeTriangles()))),
            FileFormat::kStl);
}

TEST(DetectFileFormat, RejectsUnknownFormat) {
  const absl::StatusOr<FileFormat> format = DetectFileFormat(WriteTemp("notes.txt", "hello"));
  ASSERT_EQ(format.status().code(), absl::StatusCode::kInvalidArgument) << format.status();
  EXPECT_THAT(Message(format.status()), HasSubstr("\"notes.txt\": unknown format"));
}

TEST(DetectFileFormat, ReportsMissingFileAsNotFound) {
  const absl::StatusOr<FileFormat> format = DetectFileFormat("/nonexistent/dir/missing.stl");
  ASSERT_EQ(format.status().code(), absl::StatusCode::kNotFound) << format.status();
  EXPECT_THAT(Message(format.status()), HasSubstr("\"missing.stl\""));
}

TEST(IsPointCloudFile, TellsCloudsFromMeshes) {
  EXPECT_TRUE(*IsPointCloudFile(WriteTemp("c.xyz", "0 0 0\n")));
  EXPECT_TRUE(*IsPointCloudFile(WriteTemp("c.pwn", "1\n0 0 0\n0 0 1\n")));
  EXPECT_TRUE(*IsPointCloudFile(WriteTemp(
      "c.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n")));
  EXPECT_FALSE(*IsPointCloudFile(WriteTemp(
      "m.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n")));
  EXPECT_FALSE(*IsPointCloudFile(WriteTemp("m.off", testing_files::CubeOff())));
}

TEST(FileFormatName, NamesEveryFormat) {
  EXPECT_STREQ(FileFormatName(FileFormat::kStl), "stl");
  EXPECT_STREQ(FileFormatName(FileFormat::kPwn), "pwn");
  EXPECT_STREQ(FileFormatName(FileFormat::kUnknown), "unknown");
}

}  // namespace
}  // namespace meshseg
