// The volume reader targets: bytes in, a volume header and its samples or a
// clean error out.
#include "fuzz/volume_targets.h"

#include <stdlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "fuzz/check.h"
#include "meshseg/voxel.h"

namespace meshseg::fuzz {
namespace {

// A private folder for this process's scratch file, removed at exit.
class ScratchDir {
 public:
  ScratchDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern =
        absl::StrCat(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp", "/meshseg_fuzz_volume_XXXXXX");
    Check(mkdtemp(pattern.data()) != nullptr, "scratch folder created", pattern);
    dir_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string Write(const std::string& name, std::string_view bytes) const {
    const std::string path = absl::StrCat(dir_, "/", name);
    FILE* file = std::fopen(path.c_str(), "wb");
    Check(file != nullptr, "scratch file opened", path);
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    Check(std::fclose(file) == 0 && written, "scratch file written", path);
    return path;
  }

 private:
  std::string dir_;
};

const ScratchDir& Scratch() {
  static const ScratchDir dir;
  return dir;
}

// A reader's error must be INVALID_ARGUMENT, start with
// `read_volume: "<name>": ` and stay short (a message quotes a token, never
// the input).
void CheckCleanError(const absl::Status& status, const std::string& name) {
  const std::string message(status.message());
  Check(status.code() == absl::StatusCode::kInvalidArgument, "error code is INVALID_ARGUMENT",
        status.ToString());
  Check(absl::StartsWith(message, absl::StrCat("read_volume: \"", name, "\": ")),
        "error names the operation and the file", message);
  Check(message.size() < 512, "error message is short", message);
}

// The range of values a sample of `type` converts to.
bool InRange(VoxelType type, double x) {
  switch (type) {
    case VoxelType::kUint8:
      return x >= 0 && x <= 255 && x == std::floor(x);
    case VoxelType::kUint16:
      return x >= 0 && x <= 65535 && x == std::floor(x);
    case VoxelType::kInt16:
      return x >= -32768 && x <= 32767 && x == std::floor(x);
    case VoxelType::kFloat32:
      return std::isfinite(x);
  }
  return false;
}

// Checks an accepted header against the limits the service reads with, then
// streams every slice.
void CheckVolume(const std::string& path, const std::string& name, size_t file_size,
                 const VolumeReadOptions& options) {
  const absl::StatusOr<VolumeInfo> info = ReadVolumeInfo(path, options);
  if (!info.ok()) return CheckCleanError(info.status(), name);
  const VolumeGeometry& g = info->geometry;
  for (int a = 0; a < 3; ++a) {
    Check(g.dims[a] >= 2, "accepted sizes are at least 2", absl::StrCat(g.dims[a]));
    Check(g.axes[a].allFinite() && g.axes[a].norm() > 0, "accepted axes are finite and non-zero");
  }
  Check(g.origin.allFinite(), "accepted origin is finite");
  Check(g.dims[0] <= options.max_slice_voxels / g.dims[1], "accepted slice is within the limit");
  Check(g.dims[0] * g.dims[1] <= options.max_voxels / g.dims[2],
        "accepted voxel count is within the limit");
  Check(info->data_path == path, "samples come from the one file read (attached_data_only)",
        info->data_path);
  Check(info->data_offset >= 0 && static_cast<size_t>(info->data_offset) <= file_size,
        "data offset is inside the file", absl::StrCat(info->data_offset, " of ", file_size));
  const int64_t slice_count = g.dims[0] * g.dims[1];
  if (!info->gzip) {
    Check(info->data_offset + g.VoxelCount() * VoxelTypeSize(info->type) ==
              static_cast<int64_t>(file_size),
          "accepted raw data holds exactly the declared samples");
  }

  absl::StatusOr<VolumeSlices> slices = VolumeSlices::Open(*info);
  if (!slices.ok()) return CheckCleanError(slices.status(), name);
  std::vector<double> values;
  for (int64_t k = 0; k < g.dims[2]; ++k) {
    const absl::Status next = slices->Next(values);
    if (!next.ok()) {
      // Raw integer data of the checked size cannot fail; float samples may
      // be NaN or infinite, gzip data corrupt or short.
      Check(info->gzip || info->type == VoxelType::kFloat32,
            "raw integer samples of the checked size read without error", next.ToString());
      return CheckCleanError(next, name);
    }
    Check(static_cast<int64_t>(values.size()) == slice_count, "a slice holds dims[0] * dims[1]");
    for (const double x : values) {
      Check(InRange(info->type, x), "samples are within their type's range", absl::StrCat(x));
    }
  }
  Check(slices->Next(values).code() == absl::StatusCode::kOutOfRange, "no slice past the last one");
}

// The service's read options for an upload (server/upload.cc CheckFormat).
VolumeReadOptions UploadReadOptions(FileFormat format) {
  VolumeReadOptions options;
  options.format = format;
  options.attached_data_only = true;
  return options;
}

template <typename T>
T LittleEndian(const char* p) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  T x;
  std::memcpy(&x, b, sizeof(T));
  return x;
}

}  // namespace

void FuzzVolumeFile(FileFormat format, std::string_view bytes) {
  Check(IsVolumeFormat(format), "FuzzVolumeFile called with a volume format",
        FileFormatName(format));
  const std::string name = absl::StrCat("fuzz.", FileFormatName(format));
  const std::string path = Scratch().Write(name, bytes);
  CheckVolume(path, name, bytes.size(), UploadReadOptions(format));
}

void FuzzRawVolume(std::string_view bytes) {
  if (bytes.size() < kRawLayoutBytes) return;  // no layout: the header's raw_* fields
  RawVolumeLayout layout;
  constexpr VoxelType kTypes[] = {VoxelType::kUint8, VoxelType::kUint16, VoxelType::kInt16,
                                  VoxelType::kFloat32};
  layout.type = kTypes[bytes[0] & 3];
  layout.big_endian = (bytes[0] & 4) != 0;
  for (int a = 0; a < 3; ++a) {
    layout.dims[a] = LittleEndian<int64_t>(bytes.data() + 1 + 8 * a);
    layout.spacing[a] = LittleEndian<double>(bytes.data() + 25 + 8 * a);
    layout.origin[a] = LittleEndian<double>(bytes.data() + 49 + 8 * a);
  }
  const std::string_view samples = bytes.substr(kRawLayoutBytes);
  const std::string name = "fuzz.raw";
  const std::string path = Scratch().Write(name, samples);
  VolumeReadOptions options = UploadReadOptions(FileFormat::kRaw);
  options.raw = layout;
  CheckVolume(path, name, samples.size(), options);
}

}  // namespace meshseg::fuzz
