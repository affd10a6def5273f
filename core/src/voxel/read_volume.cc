// ReadVolumeInfo (format, header, sizes) and VolumeSlices (streamed samples,
// zlib's gzread for gzip data).
#include <unistd.h>
#include <zlib.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"
#include "voxel/volume_header.h"

namespace meshseg {

using voxel_internal::BadVolume;

const char* VoxelTypeName(VoxelType type) {
  switch (type) {
    case VoxelType::kUint8:
      return "uint8";
    case VoxelType::kUint16:
      return "uint16";
    case VoxelType::kInt16:
      return "int16";
    case VoxelType::kFloat32:
      return "float32";
  }
  return "unknown";
}

int VoxelTypeSize(VoxelType type) {
  switch (type) {
    case VoxelType::kUint8:
      return 1;
    case VoxelType::kUint16:
    case VoxelType::kInt16:
      return 2;
    case VoxelType::kFloat32:
      return 4;
  }
  return 1;
}

namespace {

absl::StatusOr<std::string> ReadHead(const std::string& path, const std::string& name) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return absl::NotFoundError(absl::StrCat("read_volume: \"", name, "\": cannot open"));
  }
  std::string head(voxel_internal::kMaxHeaderBytes, '\0');
  head.resize(std::fread(head.data(), 1, head.size(), file));
  std::fclose(file);
  return head;
}

absl::StatusOr<VolumeInfo> RawInfo(const std::string& path, const VolumeReadOptions& options) {
  VolumeInfo info;
  info.name = std::filesystem::path(path).filename().string();
  info.format = FileFormat::kRaw;
  if (!options.raw) {
    return BadVolume(info.name,
                     "a .raw volume needs its dims, spacing and type (meshseg: --dims X,Y,Z "
                     "--spacing SX,SY,SZ --type T; upload: UploadHeader raw_dims, raw_spacing, "
                     "raw_voxel_type)");
  }
  const RawVolumeLayout& raw = *options.raw;
  info.geometry.dims = raw.dims;
  info.geometry.origin = raw.origin;
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(raw.spacing[a]) || raw.spacing[a] <= 0.0) {
      return BadVolume(info.name, absl::StrCat("spacing ", a, " is ", raw.spacing[a],
                                               ", not positive and finite"));
    }
    MESHSEG_RETURN_IF_ERROR(
        voxel_internal::CheckAxisLength(info.name, absl::StrCat("spacing ", a), raw.spacing[a]));
    info.geometry.axes[a] = raw.spacing[a] * Eigen::Vector3d::Unit(a);
  }
  if (!raw.origin.allFinite()) return BadVolume(info.name, "origin is not finite");
  info.type = raw.type;
  info.big_endian = raw.big_endian;
  info.data_path = path;
  return info;
}

// Raw data must hold exactly the declared samples.
absl::Status CheckDataSize(const VolumeInfo& info) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(info.data_path, ec);
  if (ec) {
    return absl::NotFoundError(
        absl::StrCat("read_volume: \"", info.name, "\": cannot open data file \"",
                     std::filesystem::path(info.data_path).filename().string(), "\""));
  }
  if (info.gzip) return absl::OkStatus();  // checked while streaming
  const int64_t have = static_cast<int64_t>(size) - info.data_offset;
  const int64_t need = info.geometry.VoxelCount() * VoxelTypeSize(info.type);
  if (have < need) {
    return BadVolume(info.name, absl::StrCat("truncated data: ", have, " bytes of samples, sizes ",
                                             info.geometry.dims[0], " x ", info.geometry.dims[1],
                                             " x ", info.geometry.dims[2], " ",
                                             VoxelTypeName(info.type), " need ", need));
  }
  if (have > need) {
    return BadVolume(info.name, absl::StrCat("wrong sizes: ", have, " bytes of samples, sizes ",
                                             info.geometry.dims[0], " x ", info.geometry.dims[1],
                                             " x ", info.geometry.dims[2], " ",
                                             VoxelTypeName(info.type), " need ", need));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<VolumeInfo> ReadVolumeInfo(const std::string& path,
                                          const VolumeReadOptions& options) {
  const std::string name = std::filesystem::path(path).filename().string();
  FileFormat format;
  if (options.format) {
    format = *options.format;
  } else {
    MESHSEG_ASSIGN_OR_RETURN(format, DetectFileFormat(path));
  }
  VolumeInfo info;
  if (format == FileFormat::kRaw) {
    MESHSEG_ASSIGN_OR_RETURN(info, RawInfo(path, options));
  } else {
    MESHSEG_ASSIGN_OR_RETURN(const std::string head, ReadHead(path, name));
    if (format == FileFormat::kNrrd) {
      MESHSEG_ASSIGN_OR_RETURN(info, voxel_internal::ParseNrrdHeader(head, path));
    } else if (format == FileFormat::kMha || format == FileFormat::kMhd) {
      MESHSEG_ASSIGN_OR_RETURN(info, voxel_internal::ParseMetaImageHeader(head, path));
    } else {
      return BadVolume(name, absl::StrCat("format ", FileFormatName(format),
                                          " is not a volume (nrrd, mha, mhd, raw)"));
    }
  }
  if (options.attached_data_only && info.data_path != path) {
    // The file name comes from the header: clipped and escaped, so a header
    // that names a long or binary "file" still gets a one-line error.
    const std::string file = std::filesystem::path(info.data_path).filename().string();
    return BadVolume(
        name, absl::StrCat("its samples are in a separate file \"",
                           absl::CHexEscape(file.substr(0, 64)),
                           file.size() > 64 ? "..." : "",
                           "\"; only one file is read here: send a .mha (or .mhd with "
                           "ElementDataFile = LOCAL) or an NRRD with attached data"));
  }
  MESHSEG_RETURN_IF_ERROR(voxel_internal::CheckDims(info, options));
  MESHSEG_RETURN_IF_ERROR(CheckDataSize(info));
  return info;
}

// ---------------------------------------------------------------- VolumeSlices

struct VolumeSlices::Stream {
  FILE* file = nullptr;
  gzFile gz = nullptr;
  ~Stream() {
    if (gz != nullptr) gzclose(gz);
    if (file != nullptr) std::fclose(file);
  }
};

VolumeSlices::VolumeSlices(const VolumeInfo& info) : info_(info) {}
VolumeSlices::VolumeSlices(VolumeSlices&& o) noexcept
    : info_(std::move(o.info_)), stream_(o.stream_), next_(o.next_), bytes_(std::move(o.bytes_)) {
  o.stream_ = nullptr;
}
VolumeSlices& VolumeSlices::operator=(VolumeSlices&& o) noexcept {
  std::swap(info_, o.info_);
  std::swap(stream_, o.stream_);
  std::swap(next_, o.next_);
  std::swap(bytes_, o.bytes_);
  return *this;
}
VolumeSlices::~VolumeSlices() { delete stream_; }

absl::StatusOr<VolumeSlices> VolumeSlices::Open(const VolumeInfo& info) {
  VolumeSlices slices(info);
  slices.stream_ = new Stream;
  FILE* file = std::fopen(info.data_path.c_str(), "rb");
  if (file == nullptr) {
    return absl::NotFoundError(
        absl::StrCat("read_volume: \"", info.name, "\": cannot open data file"));
  }
  slices.stream_->file = file;
  if (std::fseek(file, info.data_offset, SEEK_SET) != 0) {
    return BadVolume(info.name, absl::StrCat("cannot seek to the data at byte ", info.data_offset));
  }
  if (info.gzip) {
    // gzdopen reads from the descriptor's current position; it gets its own
    // descriptor so both can be closed.
    const int fd = dup(fileno(file));
    if (fd < 0 || lseek(fd, info.data_offset, SEEK_SET) < 0) {
      if (fd >= 0) close(fd);
      return BadVolume(info.name, "cannot open the gzip data");
    }
    slices.stream_->gz = gzdopen(fd, "rb");
    if (slices.stream_->gz == nullptr) {
      close(fd);
      return BadVolume(info.name, "cannot open the gzip data");
    }
    gzbuffer(slices.stream_->gz, 1 << 18);
  }
  return slices;
}

absl::Status VolumeSlices::Next(std::vector<double>& values) {
  const auto& d = info_.geometry.dims;
  if (next_ >= d[2]) {
    return absl::OutOfRangeError(absl::StrCat("read_volume: \"", info_.name, "\": no slice ", next_,
                                              " (", d[2], " slices)"));
  }
  const int size = VoxelTypeSize(info_.type);
  const size_t count = static_cast<size_t>(d[0] * d[1]);
  const size_t want = count * size;
  size_t got = 0;
  if (stream_->gz != nullptr) {
    // How much a gzip stream holds is known only once it is inflated, and a
    // header can claim far more than that: the buffer grows with the data
    // (doubling from 1 MiB), so a short stream costs what it holds, not what
    // its header claims. Raw data was checked against the file size.
    bytes_.resize(std::min<size_t>(want, size_t{1} << 20));
    while (got < want) {
      if (got == bytes_.size()) bytes_.resize(std::min(want, 2 * bytes_.size()));
      const unsigned chunk =
          static_cast<unsigned>(std::min<size_t>(bytes_.size() - got, 1u << 30));
      const int n = gzread(stream_->gz, bytes_.data() + got, chunk);
      if (n < 0) {
        int err = 0;
        const char* msg = gzerror(stream_->gz, &err);
        return BadVolume(info_.name, absl::StrCat("corrupt gzip data in slice ", next_, " of ",
                                                  d[2], ": ", msg));
      }
      if (n == 0) break;
      got += static_cast<size_t>(n);
    }
  } else {
    bytes_.resize(want);
    got = std::fread(bytes_.data(), 1, want, stream_->file);
  }
  if (got < want) {
    return BadVolume(info_.name, absl::StrCat("truncated data: slice ", next_, " of ", d[2],
                                              " has ", got, " of ", want, " bytes"));
  }
  values.resize(count);
  const bool swap = info_.big_endian != (std::endian::native == std::endian::big);
  const unsigned char* b = bytes_.data();
  for (size_t v = 0; v < count; ++v, b += size) {
    unsigned char s[4];
    for (int c = 0; c < size; ++c) s[c] = swap ? b[size - 1 - c] : b[c];
    switch (info_.type) {
      case VoxelType::kUint8:
        values[v] = s[0];
        break;
      case VoxelType::kUint16: {
        uint16_t x;
        std::memcpy(&x, s, 2);
        values[v] = x;
        break;
      }
      case VoxelType::kInt16: {
        int16_t x;
        std::memcpy(&x, s, 2);
        values[v] = x;
        break;
      }
      case VoxelType::kFloat32: {
        float x;
        std::memcpy(&x, s, 4);
        if (!std::isfinite(x)) {
          return BadVolume(info_.name, absl::StrCat("sample ", v, " of slice ", next_,
                                                    " is not a finite number"));
        }
        values[v] = x;
        break;
      }
    }
  }
  ++next_;
  return absl::OkStatus();
}

}  // namespace meshseg
