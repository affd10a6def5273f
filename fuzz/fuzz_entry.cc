#include "fuzz/fuzz_entry.h"

#include <array>

#include "fuzz/reader_targets.h"
#include "fuzz/upload_target.h"
#include "fuzz/volume_targets.h"

namespace meshseg::fuzz {
namespace {

std::string_view Bytes(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

template <FileFormat kFormat>
int Mesh(const uint8_t* data, size_t size) {
  FuzzMeshReader(kFormat, Bytes(data, size));
  return 0;
}

template <FileFormat kFormat>
int Cloud(const uint8_t* data, size_t size) {
  FuzzCloudReader(kFormat, Bytes(data, size));
  return 0;
}

int PlyBoth(const uint8_t* data, size_t size) {
  FuzzMeshReader(FileFormat::kPly, Bytes(data, size));
  FuzzCloudReader(FileFormat::kPly, Bytes(data, size));
  return 0;
}

int Sniffed(const uint8_t* data, size_t size) {
  FuzzSniffedFile(Bytes(data, size));
  return 0;
}

template <FileFormat kFormat>
int Volume(const uint8_t* data, size_t size) {
  FuzzVolumeFile(kFormat, Bytes(data, size));
  return 0;
}

int RawVolume(const uint8_t* data, size_t size) {
  FuzzRawVolume(Bytes(data, size));
  return 0;
}

int Upload(const uint8_t* data, size_t size) {
  FuzzUploadHeader(Bytes(data, size));
  return 0;
}

// ASCII and binary variants share a reader (it decides by content) but not
// a seed corpus, so each variant's parser is reached from the start.
constexpr std::array kTargets = {
    FuzzTarget{"stl_ascii", Mesh<FileFormat::kStl>},
    FuzzTarget{"stl_binary", Mesh<FileFormat::kStl>},
    FuzzTarget{"obj", Mesh<FileFormat::kObj>},
    FuzzTarget{"off", Mesh<FileFormat::kOff>},
    FuzzTarget{"ply_ascii", PlyBoth},
    FuzzTarget{"ply_binary", PlyBoth},
    FuzzTarget{"xyz", Cloud<FileFormat::kXyz>},
    FuzzTarget{"pwn", Cloud<FileFormat::kPwn>},
    FuzzTarget{"sniffed", Sniffed},
    FuzzTarget{"upload_header", Upload},
    FuzzTarget{"nrrd", Volume<FileFormat::kNrrd>},
    FuzzTarget{"mha", Volume<FileFormat::kMha>},
    FuzzTarget{"mhd", Volume<FileFormat::kMhd>},
    FuzzTarget{"raw", RawVolume},
};

}  // namespace

std::span<const FuzzTarget> FuzzTargets() { return kTargets; }

const FuzzTarget* FindFuzzTarget(std::string_view name) {
  for (const FuzzTarget& target : kTargets) {
    if (target.name == name) return &target;
  }
  return nullptr;
}

}  // namespace meshseg::fuzz
