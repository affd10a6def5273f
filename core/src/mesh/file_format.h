// Recognising a file's format from its name and first bytes.
#ifndef MESHSEG_MESH_FILE_FORMAT_H_
#define MESHSEG_MESH_FILE_FORMAT_H_

#include <cstdint>
#include <string>
#include <string_view>

#include "meshseg/mesh.h"

namespace meshseg::mesh_internal {

// Returns the format named by the extension of `path` (any case), else the
// one the content suggests: `head` is the start of the file (up to 4 KiB is
// enough), `size` the whole file size. kUnknown if neither tells.
FileFormat FormatOf(const std::string& path, std::string_view head, int64_t size);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_FILE_FORMAT_H_
