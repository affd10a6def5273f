// ReadMesh: map the file, pick the reader by format, build the mesh.
#include "absl/strings/str_cat.h"
#include "meshseg/mesh.h"
#include "meshseg/status_macros.h"
#include "mesh/file_format.h"
#include "mesh/raw_mesh.h"

namespace meshseg {

using mesh_internal::BadInput;
using mesh_internal::BuildFromRaw;
using mesh_internal::FileName;
using mesh_internal::InputFile;
using mesh_internal::OpenInput;
using mesh_internal::RawMesh;
using mesh_internal::ReadObj;
using mesh_internal::ReadOff;
using mesh_internal::ReadPlyMesh;
using mesh_internal::ReadStl;
using mesh_internal::Source;

absl::StatusOr<Mesh> ReadMesh(const std::string& path, const ReadMeshOptions& options) {
  const Source src{"read_mesh", FileName(path)};
  MESHSEG_ASSIGN_OR_RETURN(const InputFile input, OpenInput(path, options, src));
  const std::string_view bytes = input.bytes();
  const FileFormat format = input.format;
  absl::StatusOr<RawMesh> raw;
  switch (format) {
    case FileFormat::kStl: raw = ReadStl(bytes, src, options.max_elements); break;
    case FileFormat::kObj: raw = ReadObj(bytes, src, options.max_elements); break;
    case FileFormat::kOff: raw = ReadOff(bytes, src, options.max_elements); break;
    case FileFormat::kPly: raw = ReadPlyMesh(bytes, src, options.max_elements); break;
    case FileFormat::kXyz:
    case FileFormat::kPwn:
      return BadInput(src, absl::StrCat("a ", FileFormatName(format),
                                        " point cloud is not a mesh; read it as a point cloud"));
    case FileFormat::kNrrd:
    case FileFormat::kMha:
    case FileFormat::kMhd:
    case FileFormat::kRaw:
      return BadInput(src, absl::StrCat("a ", FileFormatName(format),
                                        " volume is not a mesh; extract its surface first "
                                        "(meshseg/voxel.h)"));
    case FileFormat::kUnknown:
      return BadInput(src, "unknown format (extension and content match none of stl, obj, "
                           "off, ply)");
  }
  if (!raw.ok()) return raw.status();
  return BuildFromRaw(*std::move(raw), src);
}

}  // namespace meshseg
