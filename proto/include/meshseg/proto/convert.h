// File: convert.h
// -----------------------------------------------------------------------------
// Conversion between the core pipeline types (pipeline.h) and the public API
// messages (meshseg/v1/segmentation.proto). The only place both meet: core/
// never includes a .pb.h, server/ and client/ never build messages by hand.
#ifndef MESHSEG_PROTO_CONVERT_H_
#define MESHSEG_PROTO_CONVERT_H_

#include <optional>
#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/v1/segmentation.pb.h"
#include "meshseg/v1/service.pb.h"

namespace meshseg {

// Returns the wire form of `result`: mesh info, face and vertex labels in the
// same order, one Region message per region with its surface parameters, and
// the estimates.
v1::SegmentationResult ToProto(const PipelineResult& result);

// Returns the pipeline parameters `options` ask for, defaults where unset.
// Errors (INVALID_ARGUMENT, naming the field, its range and the value): a
// value outside its range, NaN or infinite. distance_tolerance in (0, 100]
// (x mean edge length), angle_tolerance_deg in (0, 90).
absl::StatusOr<PipelineParams> FromProto(const v1::SegmentOptions& options);

// Returns the core form of a result message (the inverse of ToProto; the
// features are not read back): labels, regions, estimates and topology,
// RegionTopology::patch_count from the loops, the mesh geometry when present
// and the length unit.
// Errors (INVALID_ARGUMENT): a region without surface type or parameters, a
// quadric without 10 coefficients, ids that are not their index, references
// to regions, curves or corners that do not exist, mesh geometry whose ids
// are out of range.
absl::StatusOr<PipelineResult> FromProto(const v1::SegmentationResult& result);

// Returns the format a wire format hint names: "" = unset (detect),
// "stl", "obj", "off", "ply", "xyz", "pwn" (any case).
// Errors (INVALID_ARGUMENT): any other hint.
absl::StatusOr<std::optional<FileFormat>> FormatFromHint(std::string_view hint);

// Sets params->volume.read.raw from the header's raw_* fields (a headerless
// .raw volume); leaves it unset when none is given.
// Errors (INVALID_ARGUMENT): as RawLayout.
absl::Status RawLayoutFromProto(const v1::UploadHeader& header, PipelineParams* params);

// Returns the layout of a headerless volume: 3 dims, 3 or no spacings, 3 or
// no origin coordinates, a voxel type name (voxel.h VoxelTypeName).
// Errors (INVALID_ARGUMENT): wrong counts or an unknown type.
absl::StatusOr<RawVolumeLayout> RawLayout(const std::vector<int64_t>& dims,
                                          const std::vector<double>& spacing,
                                          const std::vector<double>& origin,
                                          const std::string& voxel_type, bool big_endian);
// Returns an upload's length unit (UploadHeader.length_unit) in lowercase,
// "" for none. Errors (INVALID_ARGUMENT): a unit CanonicalLengthUnit
// (brep.h) does not know, naming `field`, the value and the units allowed.
absl::StatusOr<std::string> LengthUnitFromWire(std::string_view field, std::string_view unit);

// Returns the unit a STEP file declares for an upload: `step_unit` when set,
// else `length_unit`, else BrepParams' default ("mm").
// Errors (INVALID_ARGUMENT): either unit unknown (as LengthUnitFromWire,
// fields "step_unit" and "length_unit"); both set to different units (the
// STEP file's coordinates are written unscaled).
absl::StatusOr<std::string> StepUnitFromWire(std::string_view step_unit,
                                             std::string_view length_unit);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_CONVERT_H_
