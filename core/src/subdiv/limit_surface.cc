// EvaluateLimitSurface(): the public face of SampleLimitSurface.
#include "absl/strings/str_cat.h"
#include "meshseg/subdiv.h"
#include "subdiv/limit_positions.h"

namespace meshseg {

absl::StatusOr<LimitMesh> EvaluateLimitSurface(const ControlMesh& control, int level) {
  // Level 5 has 1024 triangles per control face (FitSubdivisionSurface's bound).
  if (level < 0 || level > 5) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: limit level ", level, " must be in [0, 5]"));
  }
  absl::StatusOr<subdiv_internal::LimitSurface> limit =
      subdiv_internal::SampleLimitSurface(control, level);
  if (!limit.ok()) return limit.status();
  return LimitMesh{std::move(limit->mesh.vertices), std::move(limit->mesh.faces)};
}

}  // namespace meshseg
