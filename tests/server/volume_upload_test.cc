// CT volumes uploaded to a real server on 127.0.0.1 (ephemeral port): an
// NRRD and a headerless .raw with its layout in the upload header give the
// offline result byte for byte; a MetaImage header whose samples are in a
// separate file (only one file is uploaded) is refused at upload with
// INVALID_ARGUMENT naming the data file and what to send instead.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>

#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/proto/convert.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/voxel.h"
#include "tests/server/test_server.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_server::FreshDir;
using testing_server::TestServer;

// The generator's small block (8 true surfaces) as a volume: a few tens of
// thousands of voxels, so a job takes a second or two.
VolumeData SmallBlock(bool binary) {
  absl::StatusOr<VolumeData> volume = GenerateVolume("small_block", binary);
  EXPECT_TRUE(volume.ok()) << volume.status();
  return volume.ok() ? *std::move(volume) : VolumeData{};
}

std::string OfflineJson(const std::string& path, const PipelineParams& params = {}) {
  absl::StatusOr<PipelineResult> r = RunPipeline(path, params);
  EXPECT_TRUE(r.ok()) << r.status();
  if (!r.ok()) return "";
  absl::StatusOr<std::string> json = ResultJson(ToProto(*r));
  EXPECT_TRUE(json.ok()) << json.status();
  return json.ok() ? *json : "";
}

// The samples of `v` as little-endian uint16, x fastest.
void WriteUint16(const VolumeData& v, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  for (const double value : v.values) {
    const auto s = static_cast<uint16_t>(value);
    const char bytes[2] = {static_cast<char>(s & 0xff), static_cast<char>(s >> 8)};
    out.write(bytes, 2);
  }
}

TEST(VolumeUpload, BinaryAndGreyNrrdGiveTheOfflineResult) {
  TestServer server;
  MeshsegClient client = server.Client();
  const std::string dir = FreshDir("files");
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "grey");
    const std::string path = dir + (binary ? "/block_binary.nrrd" : "/block_grey.nrrd");
    ASSERT_TRUE(WriteNrrd(SmallBlock(binary), path, /*gzip=*/true).ok());
    const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(path);
    ASSERT_TRUE(remote.ok()) << remote.status();
    EXPECT_TRUE(remote->has_volume());
    EXPECT_EQ(remote->volume().format(), "nrrd");
    EXPECT_EQ(remote->binary_occupancy(), binary);
    // The block's 8 faces (6 planes, the bore, the round), within 1.1 x.
    EXPECT_GE(remote->regions_size(), 8);
    EXPECT_LE(remote->regions_size(), 8);
    const absl::StatusOr<std::string> json = ResultJson(*remote);
    ASSERT_TRUE(json.ok());
    EXPECT_EQ(*json, OfflineJson(path));
  }
}

TEST(VolumeUpload, RawWithTheLayoutInTheHeaderGivesTheOfflineResult) {
  TestServer server;
  MeshsegClient client = server.Client();
  const VolumeData volume = SmallBlock(/*binary=*/false);
  const std::string path = FreshDir("files") + "/block.raw";
  WriteUint16(volume, path);

  UploadOptions options;
  options.format_hint = "raw";
  for (int a = 0; a < 3; ++a) {
    options.raw.add_raw_dims(volume.geometry.dims[a]);
    options.raw.add_raw_spacing(volume.geometry.axes[a].norm());
    options.raw.add_raw_origin(volume.geometry.origin[a]);
  }
  options.raw.set_raw_voxel_type("uint16");
  const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(path, options);
  ASSERT_TRUE(remote.ok()) << remote.status();
  EXPECT_EQ(remote->volume().format(), "raw");

  PipelineParams params;
  params.format = FileFormat::kRaw;
  ASSERT_TRUE(RawLayoutFromProto(options.raw, &params).ok());
  const absl::StatusOr<std::string> json = ResultJson(*remote);
  ASSERT_TRUE(json.ok());
  EXPECT_EQ(*json, OfflineJson(path, params));

  // Without the layout the upload is refused before any job exists.
  const absl::StatusOr<v1::UploadResponse> bare = client.Upload(path, {.format_hint = "raw"});
  ASSERT_FALSE(bare.ok());
  EXPECT_EQ(bare.status().code(), absl::StatusCode::kInvalidArgument) << bare.status();
  EXPECT_THAT(bare.status().message(), HasSubstr("\"block.raw\": a .raw volume needs its dims"));
}

TEST(VolumeUpload, MetaImageWithASeparateDataFileIsRefusedNamingIt) {
  TestServer server;
  MeshsegClient client = server.Client();
  const VolumeData volume = SmallBlock(/*binary=*/false);
  const std::string dir = FreshDir("files");
  WriteUint16(volume, dir + "/block_data.raw");
  std::ofstream(dir + "/block.mhd")
      << "ObjectType = Image\nNDims = 3\nDimSize = " << volume.geometry.dims[0] << " "
      << volume.geometry.dims[1] << " " << volume.geometry.dims[2]
      << "\nElementType = MET_USHORT\n"
         "ElementDataFile = block_data.raw\n";
  // Offline both files are there and it reads.
  EXPECT_TRUE(ReadVolumeInfo(dir + "/block.mhd").ok());
  const absl::StatusOr<v1::UploadResponse> upload = client.Upload(dir + "/block.mhd");
  ASSERT_FALSE(upload.ok());
  EXPECT_EQ(upload.status().code(), absl::StatusCode::kInvalidArgument) << upload.status();
  EXPECT_THAT(upload.status().message(), HasSubstr("\"block.mhd\""));
  EXPECT_THAT(upload.status().message(), HasSubstr("separate file \"block_data.raw\""));
  EXPECT_THAT(upload.status().message(), HasSubstr("ElementDataFile = LOCAL"));
  EXPECT_EQ(server.SpoolFiles(), 0);

  // The documented single-file form: the same header with LOCAL data.
  std::ifstream data(dir + "/block_data.raw", std::ios::binary);
  std::ofstream local(dir + "/block_local.mhd", std::ios::binary);
  local << "ObjectType = Image\nNDims = 3\nDimSize = " << volume.geometry.dims[0] << " "
        << volume.geometry.dims[1] << " " << volume.geometry.dims[2]
        << "\nElementType = MET_USHORT\nElementDataFile = LOCAL\n"
        << data.rdbuf();
  local.close();
  const absl::StatusOr<v1::SegmentationResult> remote = client.Segment(dir + "/block_local.mhd");
  ASSERT_TRUE(remote.ok()) << remote.status();
  EXPECT_EQ(remote->volume().format(), "mhd");
  EXPECT_GE(remote->regions_size(), 8);
}

}  // namespace
}  // namespace meshseg
