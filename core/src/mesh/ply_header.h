// The header of a PLY file: encoding, elements, their properties.
#ifndef MESHSEG_MESH_PLY_HEADER_H_
#define MESHSEG_MESH_PLY_HEADER_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "mesh/source.h"

namespace meshseg::mesh_internal {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

// Size of one binary value of `type`, in bytes.
int PlyTypeSize(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  // of the values (list items for a list)
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;  // of a list's length
};

struct PlyElement {
  std::string name;
  int64_t count = 0;
  std::vector<PlyProperty> properties;

  // Index of the property called `name`, or -1.
  int Find(std::string_view property_name) const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;  // first byte after "end_header\n"
  int64_t body_line = 1;   // line number of the first body line (ascii)
};

// Returns the header of the PLY file `bytes`. Errors name the header line.
absl::StatusOr<PlyHeader> ParsePlyHeader(std::string_view bytes, const Source& src);

}  // namespace meshseg::mesh_internal

#endif  // MESHSEG_MESH_PLY_HEADER_H_
