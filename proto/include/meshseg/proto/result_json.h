// File: result_json.h
// -----------------------------------------------------------------------------
// The result JSON of the command-line contract (DESIGN.md "Result JSON"):
// protobuf's JSON printer, original snake_case field names, enums as names,
// zero values printed. Both `meshseg segment` paths (in-process and
// --server) print through this one function, so their bytes are identical.
// The flat arrays (labels per face / vertex / point, the mesh geometry) are
// printed directly in the printer's notation and spliced into its print of
// the rest: the same bytes as the printer's alone, over 10x faster on a
// 1M-face result.
#ifndef MESHSEG_PROTO_RESULT_JSON_H_
#define MESHSEG_PROTO_RESULT_JSON_H_

#include <string>
#include <string_view>

#include "absl/status/statusor.h"
#include "meshseg/v1/segmentation.pb.h"

namespace meshseg {

// Returns `result` as one line of JSON followed by a newline (compact:
// label arrays of large meshes stay one line).
// Errors: INTERNAL if the printer fails (never for a valid message).
absl::StatusOr<std::string> ResultJson(const v1::SegmentationResult& result);

// Returns the result a JSON document holds (as ResultJson prints it; field
// names in either case). Errors (INVALID_ARGUMENT): not such a document,
// with the parser's reason.
absl::StatusOr<v1::SegmentationResult> ParseResultJson(std::string_view json);

}  // namespace meshseg

#endif  // MESHSEG_PROTO_RESULT_JSON_H_
