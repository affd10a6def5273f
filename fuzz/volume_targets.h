// The volume reader targets (fuzz_entry.cc): NRRD, MetaImage and headerless
// raw volumes, read as the upload path reads them.
#ifndef MESHSEG_FUZZ_VOLUME_TARGETS_H_
#define MESHSEG_FUZZ_VOLUME_TARGETS_H_

#include <string_view>

#include "meshseg/mesh.h"

namespace meshseg::fuzz {

// Writes `bytes` to a scratch file of this process named fuzz.<format>
// (nrrd, mha, mhd) and reads it as the service reads an upload
// (ReadVolumeInfo with attached_data_only, then every slice through
// VolumeSlices); aborts unless the outcome is a consistent header with
// finite samples of the declared count, or a clean INVALID_ARGUMENT naming
// the file. The volume readers take a path (the samples are streamed from
// the file, gzip through zlib), hence the file.
void FuzzVolumeFile(FileFormat format, std::string_view bytes);

// A headerless .raw volume: the layout an upload's header would give
// (RawVolumeLayout) comes from the first kRawLayoutBytes of `bytes`, the
// samples are the rest; read and checked as FuzzVolumeFile.
// Layout bytes: [0] voxel type (low 2 bits: uint8, uint16, int16, float32)
// and byte order (bit 2: big endian); [1, 25) three little-endian int64
// sizes; [25, 49) three little-endian float64 spacings; [49, 73) three
// float64 origin coordinates.
inline constexpr size_t kRawLayoutBytes = 73;
void FuzzRawVolume(std::string_view bytes);

}  // namespace meshseg::fuzz

#endif  // MESHSEG_FUZZ_VOLUME_TARGETS_H_
