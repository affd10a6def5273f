// File: convert.h
// -----------------------------------------------------------------------------
// Conversion between the core pipeline types (pipeline.h) and the public API
// messages (meshseg/v1/segmentation.proto). The only place both meet: core/
// never includes a .pb.h, server/ and client/ never build messages by hand.
#ifndef MESHSEG_PROTO_CONVERT_H_
#define MESHSEG_PROTO_CONVERT_H_

#include <optional>
#include <string_view>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/pipeline.h"
#include "meshseg/v1/segmentation.pb.h"

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
// RegionTopology::patch_count from the loops.
// Errors (INVALID_ARGUMENT): a region without surface type or parameters, a
// quadric without 10 coefficients, ids that are not their index, references
// to regions, curves or corners that do not exist.
absl::StatusOr<PipelineResult> FromProto(const v1::SegmentationResult& result);

// Returns the format a wire format hint names: "" = unset (detect),
// "stl", "obj", "off", "ply", "xyz", "pwn" (any case).
// Errors (INVALID_ARGUMENT): any other hint.
absl::StatusOr<std::optional<FileFormat>> FormatFromHint(std::string_view hint);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_CONVERT_H_
