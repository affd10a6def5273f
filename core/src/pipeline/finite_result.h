// Numbers a job can return are finite and computed within double's range.
// Fits form sums of fourth powers of coordinates, so coordinates beyond
// kMaxCoordinate (input_size.h) overflow to Inf and their results to NaN:
// the mesh readers refuse such vertices, a cloud's points are checked here
// before any work, and every number of the result is checked before it is
// returned, so a job never succeeds with NaN in it.
#ifndef MESHSEG_PIPELINE_FINITE_RESULT_H_
#define MESHSEG_PIPELINE_FINITE_RESULT_H_

#include <Eigen/Core>
#include <span>
#include <string_view>

#include "absl/status/status.h"
#include "meshseg/pipeline.h"

namespace meshseg::pipeline_internal {

// Returns OK if every coordinate of a cloud's `points` has magnitude <=
// kMaxCoordinate. Errors: INVALID_ARGUMENT `pipeline: "<name>": point 5 has
// coordinate 1e+300, beyond the +-1e+75 ...`.
absl::Status CheckCoordinateRange(std::string_view name, std::span<const Eigen::Vector3d> points);

// Returns OK if every number of `result` is finite. Errors: INTERNAL naming
// the first non-finite value and where it is (`region 3 (cylinder) radius
// is nan`): the input passed CheckCoordinateRange, so it is a fault of ours.
absl::Status CheckResultFinite(std::string_view name, const PipelineResult& result);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_FINITE_RESULT_H_
