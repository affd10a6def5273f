#include <sys/resource.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::ScratchPath;

// A 5 x 4 x 3 volume whose values name their index, within every type.
VolumeData Ramp(VoxelType type) {
  VolumeData v;
  v.type = type;
  v.geometry.dims = {5, 4, 3};
  v.geometry.origin = Eigen::Vector3d(1.5, -2.0, 3.25);
  v.geometry.axes = {Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d(0, 0.75, 0),
                     Eigen::Vector3d(0, 0, 1.25)};
  for (int x = 0; x < 60; ++x) {
    v.values.push_back(type == VoxelType::kInt16     ? x * 7 - 200
                       : type == VoxelType::kFloat32 ? x * 0.5
                                                     : x * 3);
  }
  return v;
}

std::vector<double> ReadAll(const VolumeInfo& info) {
  absl::StatusOr<VolumeSlices> slices = VolumeSlices::Open(info);
  EXPECT_TRUE(slices.ok()) << slices.status();
  std::vector<double> all, slice;
  for (int k = 0; k < info.geometry.dims[2]; ++k) {
    const absl::Status s = slices->Next(slice);
    EXPECT_TRUE(s.ok()) << s;
    all.insert(all.end(), slice.begin(), slice.end());
  }
  EXPECT_FALSE(slices->Next(slice).ok());  // past the last slice
  return all;
}

void ExpectSameGeometry(const VolumeGeometry& a, const VolumeGeometry& b) {
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_TRUE(a.origin.isApprox(b.origin)) << a.origin.transpose();
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(a.axes[i].isApprox(b.axes[i])) << a.axes[i].transpose();
}

std::string Bytes(const VolumeData& v, bool big_endian) {
  std::string out;
  const int size = VoxelTypeSize(v.type);
  for (double x : v.values) {
    unsigned char b[4];
    switch (v.type) {
      case VoxelType::kUint8:
        b[0] = static_cast<uint8_t>(x);
        break;
      case VoxelType::kUint16: {
        uint16_t y = static_cast<uint16_t>(x);
        std::memcpy(b, &y, 2);
        break;
      }
      case VoxelType::kInt16: {
        int16_t y = static_cast<int16_t>(x);
        std::memcpy(b, &y, 2);
        break;
      }
      case VoxelType::kFloat32: {
        float y = static_cast<float>(x);
        std::memcpy(b, &y, 4);
        break;
      }
    }
    if (big_endian) std::reverse(b, b + size);
    out.append(reinterpret_cast<char*>(b), size);
  }
  return out;
}

const char* MetaType(VoxelType t) {
  switch (t) {
    case VoxelType::kUint8:
      return "MET_UCHAR";
    case VoxelType::kUint16:
      return "MET_USHORT";
    case VoxelType::kInt16:
      return "MET_SHORT";
    case VoxelType::kFloat32:
      return "MET_FLOAT";
  }
  return "";
}

std::string MetaHeader(const VolumeData& v, bool big_endian, const std::string& data_file) {
  return "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = " +
         std::string(big_endian ? "True" : "False") +
         "\nCompressedData = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 1.5 -2 3.25\n"
         "ElementSpacing = 0.5 0.75 1.25\nDimSize = 5 4 3\nElementType = " +
         MetaType(v.type) + "\nElementDataFile = " + data_file + "\n";
}

void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

constexpr VoxelType kTypes[] = {VoxelType::kUint8, VoxelType::kUint16, VoxelType::kInt16,
                                VoxelType::kFloat32};

TEST(ReadVolume, NrrdRoundTripsEveryTypeRawAndGzip) {
  for (VoxelType type : kTypes) {
    for (bool gzip : {false, true}) {
      const VolumeData v = Ramp(type);
      const std::string path =
          ScratchPath(std::string("ramp_") + VoxelTypeName(type) + (gzip ? "_gz" : "") + ".nrrd");
      ASSERT_TRUE(WriteNrrd(v, path, gzip).ok());
      const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path);
      ASSERT_TRUE(info.ok()) << info.status();
      EXPECT_EQ(info->format, FileFormat::kNrrd);
      EXPECT_EQ(info->type, type);
      EXPECT_EQ(info->gzip, gzip);
      ExpectSameGeometry(info->geometry, v.geometry);
      EXPECT_EQ(ReadAll(*info), v.values) << VoxelTypeName(type);
    }
  }
}

TEST(ReadVolume, MetaImageRoundTripsMhaAndMhdBothByteOrders) {
  for (VoxelType type : kTypes) {
    for (bool big : {false, true}) {
      const VolumeData v = Ramp(type);
      const std::string stem = std::string("ramp_") + VoxelTypeName(type) + (big ? "_msb" : "_lsb");
      WriteFile(ScratchPath(stem + ".mha"), MetaHeader(v, big, "LOCAL") + Bytes(v, big));
      WriteFile(ScratchPath(stem + ".mhd"), MetaHeader(v, big, stem + ".zraw"));
      WriteFile(ScratchPath(stem + ".zraw"), Bytes(v, big));
      for (const char* ext : {".mha", ".mhd"}) {
        const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(ScratchPath(stem + ext));
        ASSERT_TRUE(info.ok()) << info.status();
        EXPECT_EQ(info->type, type);
        ExpectSameGeometry(info->geometry, v.geometry);
        EXPECT_EQ(ReadAll(*info), v.values) << stem << ext;
      }
    }
  }
}

TEST(ReadVolume, RawTakesItsLayoutFromTheCaller) {
  for (VoxelType type : kTypes) {
    const VolumeData v = Ramp(type);
    const std::string path = ScratchPath(std::string("ramp_") + VoxelTypeName(type) + ".raw");
    WriteFile(path, Bytes(v, false));
    const RawVolumeLayout layout{
        .dims = {5, 4, 3}, .spacing = {0.5, 0.75, 1.25}, .origin = {1.5, -2.0, 3.25}, .type = type};
    const absl::StatusOr<VolumeInfo> info =
        ReadVolumeInfo(path, {.format = std::nullopt, .raw = layout});
    ASSERT_TRUE(info.ok()) << info.status();
    ExpectSameGeometry(info->geometry, v.geometry);
    EXPECT_EQ(ReadAll(*info), v.values);
  }
}

// Each bad header gives an error naming the file and the problem.
void ExpectBad(const std::string& name, const std::string& text, const std::string& problem,
               const VolumeReadOptions& options = {}) {
  const std::string path = ScratchPath(name);
  WriteFile(path, text);
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path, options);
  ASSERT_FALSE(info.ok()) << name;
  EXPECT_EQ(info.status().code(), absl::StatusCode::kInvalidArgument) << info.status();
  EXPECT_THAT(info.status().message(), HasSubstr(name));
  EXPECT_THAT(info.status().message(), HasSubstr(problem));
}

std::string Nrrd(const std::string& fields) {
  return "NRRD0004\ntype: uint8\ndimension: 3\n" + fields + "\n\n";
}

TEST(ReadVolume, BadNrrdHeadersNameTheProblem) {
  const std::string data(60, '\1');
  ExpectBad("two_sizes.nrrd", Nrrd("sizes: 5 4\nencoding: raw") + data, "must give 3 sizes");
  ExpectBad("zero_size.nrrd", Nrrd("sizes: 5 0 3\nencoding: raw") + data,
            "must be a positive integer");
  ExpectBad("bzip2.nrrd", Nrrd("sizes: 5 4 3\nencoding: bzip2") + data,
            "unknown encoding \"bzip2\"");
  ExpectBad("truncated.nrrd", Nrrd("sizes: 5 4 3\nencoding: raw") + data.substr(0, 50),
            "truncated data");
  ExpectBad("too_long.nrrd", Nrrd("sizes: 5 4 3\nencoding: raw") + data + "xx", "wrong sizes");
  ExpectBad("huge.nrrd", Nrrd("sizes: 1000000 1000000 1000000\nencoding: raw") + data,
            "over the limit");
  ExpectBad("double.nrrd", "NRRD0004\ntype: double\ndimension: 3\nsizes: 5 4 3\n\n" + data,
            "unsupported type \"double\"");
  ExpectBad("flat.nrrd", "NRRD0004\ntype: uint8\ndimension: 2\nsizes: 5 4\n\n",
            "dimension 2 is not 3");
  ExpectBad("no_blank.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 5 4 3\n",
            "no blank line");
  ExpectBad("garbled.nrrd", Nrrd("sizes 5 4 3") + data, "is not \"field: value\"");
  ExpectBad("no_sizes.nrrd", Nrrd("encoding: raw") + data, "gives no sizes");
}

TEST(ReadVolume, TruncatedGzipDataFailsAtTheSliceItEnds) {
  VolumeData v = Ramp(VoxelType::kUint16);
  const std::string path = ScratchPath("cut_gzip.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path, /*gzip=*/true).ok());
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  WriteFile(path, bytes.substr(0, bytes.size() - 30));
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path);
  ASSERT_TRUE(info.ok()) << info.status();
  absl::StatusOr<VolumeSlices> slices = VolumeSlices::Open(*info);
  ASSERT_TRUE(slices.ok());
  std::vector<double> slice;
  absl::Status s;
  for (int k = 0; k < 3 && s.ok(); ++k) s = slices->Next(slice);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.message(), HasSubstr("cut_gzip.nrrd"));
  EXPECT_THAT(s.message(),
              ::testing::AnyOf(HasSubstr("truncated data"), HasSubstr("corrupt gzip")));
}

// A gzip header can claim far more samples than its stream holds (here a
// 256 MiB slice over 240 bytes of data): the read fails naming the truncation,
// and the process never holds the claimed slice in memory.
TEST(ReadVolume, GzipHeaderClaimingMoreThanItsStreamHoldsCostsOnlyTheStream) {
  const std::string path = ScratchPath("overstated_gzip.nrrd");
  ASSERT_TRUE(WriteNrrd(Ramp(VoxelType::kFloat32), path, /*gzip=*/true).ok());
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string sizes = "sizes: 5 4 3";
  const std::size_t at = bytes.find(sizes);
  ASSERT_NE(at, std::string::npos);
  WriteFile(path, bytes.replace(at, sizes.size(), "sizes: 8192 8192 2"));
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path);
  ASSERT_TRUE(info.ok()) << info.status();
  absl::StatusOr<VolumeSlices> slices = VolumeSlices::Open(*info);
  ASSERT_TRUE(slices.ok()) << slices.status();
  std::vector<double> slice;
  const absl::Status s = slices->Next(slice);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.message(), HasSubstr("overstated_gzip.nrrd"));
  EXPECT_THAT(s.message(), HasSubstr("truncated data"));
  rusage usage{};
  ASSERT_EQ(getrusage(RUSAGE_SELF, &usage), 0);
  EXPECT_LT(usage.ru_maxrss, 128 * 1024) << "peak KiB; the claimed slice is 256 MiB";
}

TEST(ReadVolume, BadMetaImageHeadersNameTheProblem) {
  const VolumeData v = Ramp(VoxelType::kUint8);
  const std::string good = MetaHeader(v, false, "LOCAL");
  auto with = [&](const std::string& from, const std::string& to) {
    std::string h = good;
    h.replace(h.find(from), from.size(), to);
    return h;
  };
  const std::string data = Bytes(v, false);
  ExpectBad("two_dims.mha", with("DimSize = 5 4 3", "DimSize = 5 4") + data, "must give 3 sizes");
  ExpectBad("compressed.mha", with("CompressedData = False", "CompressedData = True") + data,
            "unknown encoding");
  ExpectBad("truncated.mha", good + data.substr(0, 10), "truncated data");
  ExpectBad("huge.mha", with("DimSize = 5 4 3", "DimSize = 1000000 1000000 1000000") + data,
            "over the limit");
  ExpectBad("double.mha", with("MET_UCHAR", "MET_DOUBLE") + data, "unsupported ElementType");
  ExpectBad("no_data_line.mha", with("ElementDataFile = LOCAL\n", ""), "no ElementDataFile");
}

// A header naming a separate data file, refused where only the one file
// may be read, gets a one-line error even when that "file name" is long
// binary junk (a fuzzer's find: the whole name went into the message).
TEST(ReadVolume, SeparateDataFileNamedByJunkIsRefusedInOneShortLine) {
  const VolumeData v = Ramp(VoxelType::kUint8);
  std::string junk(300, '\xf6');
  junk[10] = '\0';
  junk += "C33KA";
  const std::string path = ScratchPath("junk_data_file.mhd");
  WriteFile(path, MetaHeader(v, false, junk));
  const absl::StatusOr<VolumeInfo> info =
      ReadVolumeInfo(path, {.attached_data_only = true});
  ASSERT_FALSE(info.ok());
  EXPECT_EQ(info.status().code(), absl::StatusCode::kInvalidArgument) << info.status();
  const std::string message(info.status().message());
  EXPECT_THAT(message, HasSubstr("junk_data_file.mhd"));
  EXPECT_THAT(message, HasSubstr("separate file"));
  EXPECT_LT(message.size(), 512u) << message;
  for (const char c : message) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << message;
}

TEST(ReadVolume, RawWithoutLayoutOrOfTheWrongSizeIsRefused) {
  ExpectBad("no_layout.raw", std::string(60, '\0'), "needs its dims");
  ExpectBad("short.raw", std::string(59, '\0'), "truncated data",
            {.format = std::nullopt,
             .raw = RawVolumeLayout{.dims = {5, 4, 3}, .type = VoxelType::kUint8}});
  ExpectBad(
      "huge.raw", std::string(60, '\0'), "over the limit",
      {.format = std::nullopt,
       .raw = RawVolumeLayout{.dims = {1000000, 1000000, 1000000}, .type = VoxelType::kUint8}});
}

// Lengths whose square underflows (a subnormal spacing read as positive) or
// whose squared extent overflows give no usable geometry; the bounds hold
// for every way a volume states its spacing.
TEST(ReadVolume, SpacingsWhoseSquareUnderflowsOrOverflowsAreRefused) {
  const std::string data(2 * 2 * 2, '\0');
  const RawVolumeLayout tiny{
      .dims = {2, 2, 2}, .spacing = {0.5, 0.75, 1e-309}, .type = VoxelType::kUint8};
  ExpectBad("subnormal.raw", data, "spacing 2 is 1e-309, outside",
            {.format = std::nullopt, .raw = tiny});
  ExpectBad("tiny.nrrd", Nrrd("sizes: 2 2 2\nspacings: 1e-200 1 1") + data,
            "spacings 0 is 1e-200, outside");
  ExpectBad("huge.nrrd", Nrrd("sizes: 2 2 2\nspace directions: (1,0,0) (0,1e150,0) (0,0,1)") + data,
            "space directions axis 1 is 1e+150, outside");
  ExpectBad("tiny.mha",
            "NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementSpacing = 1 1e-160 1\n"
            "ElementDataFile = LOCAL\n" +
                data,
            "ElementSpacing 1 is 1e-160, outside");
  // Just inside the bounds: read as given.
  const std::string path = ScratchPath("small_spacing.nrrd");
  WriteFile(path, Nrrd("sizes: 2 2 2\nspacings: 1e-150 1 1e140") + data);
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path);
  ASSERT_TRUE(info.ok()) << info.status();
  EXPECT_DOUBLE_EQ(info->geometry.Spacing().x(), 1e-150);
  EXPECT_DOUBLE_EQ(info->geometry.Spacing().z(), 1e140);
}

TEST(ReadVolume, MissingFileIsNotFound) {
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(ScratchPath("absent.nrrd"));
  ASSERT_FALSE(info.ok());
  EXPECT_EQ(info.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(info.status().message(), HasSubstr("absent.nrrd"));
}

}  // namespace
}  // namespace meshseg
