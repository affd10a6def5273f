// File: input_size.h
// -----------------------------------------------------------------------------
// Part of the `mesh` stage: the size of an input file (mesh or point cloud)
// as its header declares it, known before the file is read, for admission
// control (pipeline.h's EstimateJobMemory). Reads a few KiB of header, or
// streams the lines of formats without counts in a header.
#ifndef MESHSEG_INPUT_SIZE_H_
#define MESHSEG_INPUT_SIZE_H_

#include <cstdint>
#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"

namespace meshseg {

// Largest coordinate magnitude an input may have: the surface fits sum
// fourth powers of coordinates (the quadric's normal equations, seed 000
// eq. (7)), and 1e75^4 summed over millions of points stays below double's
// max (1.8e308). Readers refuse vertices beyond it (INVALID_ARGUMENT naming
// the vertex), as they refuse NaN.
inline constexpr double kMaxCoordinate = 1e75;

// The size of an input file as its header declares it (or, for OBJ, ASCII
// STL and XYZ, which have no counts in a header, as one pass over its lines
// counts it), known before the file is read: for admission control.
struct InputSize {
  FileFormat format = FileFormat::kUnknown;
  // A cloud: XYZ, PWN, or a PLY without faces.
  bool point_cloud = false;
  // Declared vertices (STL: 3 per triangle, before welding; a cloud: points).
  int64_t vertex_count = 0;
  // Declared faces, triangles where the format says (OBJ: fan triangles of
  // its polygons; OFF and PLY: polygons).
  int64_t face_count = 0;
  int64_t file_bytes = 0;
};

// Returns the size `path` declares, reading only its header or streaming
// its lines (memory use is a few MiB whatever the file's size). `format`
// overrides detection. Counts are what the file claims; the readers still
// check them against the data.
// Errors: NOT_FOUND if it cannot be opened; INVALID_ARGUMENT (naming the
// file) for an empty or unknown file, a header without counts, a negative
// count.
absl::StatusOr<InputSize> ProbeInput(const std::string& path,
                                     std::optional<FileFormat> format = std::nullopt);

}  // namespace meshseg

#endif  // MESHSEG_INPUT_SIZE_H_
