// WriteNrrd: a NRRD0004 header and the samples, raw or gzip (zlib).
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "meshseg/voxel.h"

namespace meshseg {
namespace {

// NRRD spells the integer types as VoxelTypeName does, and float32 "float".
const char* NrrdTypeName(VoxelType type) {
  return type == VoxelType::kFloat32 ? "float" : VoxelTypeName(type);
}

template <typename T>
void Put(double v, unsigned char* out) {
  T x;
  if constexpr (std::is_floating_point_v<T>) {
    x = static_cast<T>(v);
  } else {
    x = static_cast<T>(std::clamp(std::round(v), double(std::numeric_limits<T>::min()),
                                  double(std::numeric_limits<T>::max())));
  }
  std::memcpy(out, &x, sizeof(T));
}

// Little-endian bytes of samples [begin, end).
std::vector<unsigned char> Encode(const VolumeData& volume, size_t begin, size_t end) {
  const int size = VoxelTypeSize(volume.type);
  std::vector<unsigned char> out((end - begin) * size);
  for (size_t v = begin; v < end; ++v) {
    unsigned char* b = out.data() + (v - begin) * size;
    switch (volume.type) {
      case VoxelType::kUint8:
        Put<uint8_t>(volume.values[v], b);
        break;
      case VoxelType::kUint16:
        Put<uint16_t>(volume.values[v], b);
        break;
      case VoxelType::kInt16:
        Put<int16_t>(volume.values[v], b);
        break;
      case VoxelType::kFloat32:
        Put<float>(volume.values[v], b);
        break;
    }
  }
  return out;
}

std::string Vec(const Eigen::Vector3d& v) {
  return absl::StrFormat("(%.17g,%.17g,%.17g)", v.x(), v.y(), v.z());
}

}  // namespace

absl::Status WriteNrrd(const VolumeData& volume, const std::string& path, bool gzip) {
  const auto& d = volume.geometry.dims;
  if (d[0] <= 0 || d[1] <= 0 || d[2] <= 0 ||
      static_cast<int64_t>(volume.values.size()) != volume.geometry.VoxelCount()) {
    return absl::InvalidArgumentError(
        absl::StrCat("write_nrrd: \"", path, "\": ", volume.values.size(), " values for sizes ",
                     d[0], " x ", d[1], " x ", d[2]));
  }
  const std::string header = absl::StrCat(
      "NRRD0004\n# meshseg\ntype: ", NrrdTypeName(volume.type),
      "\ndimension: 3\nspace: 3D-right-handed\n", "sizes: ", d[0], " ", d[1], " ", d[2],
      "\nspace directions: ", Vec(volume.geometry.axes[0]), " ", Vec(volume.geometry.axes[1]), " ",
      Vec(volume.geometry.axes[2]),
      "\nkinds: domain domain domain\nendian: little\nencoding: ", gzip ? "gzip" : "raw",
      "\nspace origin: ", Vec(volume.geometry.origin), "\n\n");
  const auto fail = [&] {
    return absl::InternalError(absl::StrCat("write_nrrd: \"", path, "\": cannot write"));
  };
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) return fail();
  bool ok = std::fwrite(header.data(), 1, header.size(), file) == header.size();
  const size_t n = volume.values.size();
  const size_t slab = static_cast<size_t>(d[0] * d[1]);
  if (ok && gzip) {
    ok = std::fflush(file) == 0;
    const int fd = dup(fileno(file));
    gzFile gz = fd >= 0 ? gzdopen(fd, "ab6") : nullptr;
    if (gz == nullptr) {
      if (fd >= 0) close(fd);
      ok = false;
    }
    for (size_t v = 0; ok && v < n; v += slab) {
      const std::vector<unsigned char> bytes = Encode(volume, v, std::min(n, v + slab));
      ok = gzwrite(gz, bytes.data(), static_cast<unsigned>(bytes.size())) ==
           static_cast<int>(bytes.size());
    }
    if (gz != nullptr && gzclose(gz) != Z_OK) ok = false;
  } else {
    for (size_t v = 0; ok && v < n; v += slab) {
      const std::vector<unsigned char> bytes = Encode(volume, v, std::min(n, v + slab));
      ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    }
  }
  if (std::fclose(file) != 0) ok = false;
  return ok ? absl::OkStatus() : fail();
}

}  // namespace meshseg
