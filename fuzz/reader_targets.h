// The reader targets' checks, shared by the per-format targets (fuzz_entry.cc).
#ifndef MESHSEG_FUZZ_READER_TARGETS_H_
#define MESHSEG_FUZZ_READER_TARGETS_H_

#include <string_view>

#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"

namespace meshseg::fuzz {

// Reads `bytes` as a `format` mesh file (stl, obj, off, ply) through the
// reader and mesh building ReadMesh uses; aborts unless the outcome is a
// consistent mesh or a clean INVALID_ARGUMENT naming the file.
void FuzzMeshReader(FileFormat format, std::string_view bytes);

// The same for point clouds (xyz, pwn, ply) and ReadPointCloud.
void FuzzCloudReader(FileFormat format, std::string_view bytes);

// Detects the format from the content alone (an upload without extension)
// and runs the reader it selects; PLY through both the mesh and the cloud
// reader, a volume header (NRRD, MetaImage) through FuzzVolumeFile.
void FuzzSniffedFile(std::string_view bytes);

}  // namespace meshseg::fuzz

#endif  // MESHSEG_FUZZ_READER_TARGETS_H_
