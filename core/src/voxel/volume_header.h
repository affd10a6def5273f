// The headers of the volume formats: NRRD (teem's NRRD0001-5: "key: value"
// fields up to a blank line, data attached after it or in a "data file") and
// MetaImage ("Key = Value" lines up to ElementDataFile, LOCAL = attached).
// Each fills a VolumeInfo; ReadVolumeInfo (read_volume_info.cc) checks sizes.
#ifndef MESHSEG_VOXEL_VOLUME_HEADER_H_
#define MESHSEG_VOXEL_VOLUME_HEADER_H_

#include <string>
#include <string_view>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "meshseg/voxel.h"

namespace meshseg::voxel_internal {

// Header text longer than this is not a volume header.
inline constexpr size_t kMaxHeaderBytes = 1 << 16;

// Returns INVALID_ARGUMENT "read_volume: \"<name>\": <problem>".
absl::Status BadVolume(std::string_view name, std::string_view problem);

// Parses an NRRD header that starts `text`; `path` locates detached data.
// Sets data_offset to the byte after the blank line (attached data).
absl::StatusOr<VolumeInfo> ParseNrrdHeader(std::string_view text, const std::string& path);

// Parses a MetaImage header (.mha or .mhd) that starts `text`.
absl::StatusOr<VolumeInfo> ParseMetaImageHeader(std::string_view text, const std::string& path);

// Returns OK if `length` (a spacing, or the length of an axis vector) can
// place samples: the surface's squared distances, areas and normals are
// products of two such lengths, so its square must be a normal double (from
// sqrt(DBL_MIN) ~ 1.5e-154 up), and the squared extent of the longest axis
// the limits allow (2^33 samples) must stay finite (up to ~1.5e144).
// Otherwise INVALID_ARGUMENT naming `what` (e.g. "spacing 2") and the value.
absl::Status CheckAxisLength(std::string_view name, std::string_view what, double length);

// Checks dims against the options' limits (before anything is allocated).
absl::Status CheckDims(const VolumeInfo& info, const VolumeReadOptions& options);

}  // namespace meshseg::voxel_internal

#endif  // MESHSEG_VOXEL_VOLUME_HEADER_H_
