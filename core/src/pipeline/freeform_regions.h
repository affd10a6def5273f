// Loop subdivision surfaces for the regions no analytic surface describes
// (issue #35, ALGORITHMS.md S5): FREEFORM regions, and QUADRIC regions whose
// quadric misses their vertices by more than the noise.
#ifndef MESHSEG_CORE_SRC_PIPELINE_FREEFORM_REGIONS_H_
#define MESHSEG_CORE_SRC_PIPELINE_FREEFORM_REGIONS_H_

#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/pipeline.h"

namespace meshseg::pipeline_internal {

// True if `region` gets a subdivision surface under `params`: FREEFORM, or
// QUADRIC with rms_distance over params.noise_factor * noise (model units);
// at least params.min_region_faces faces either way.
bool NeedsSubdivision(const Region& region, double noise, const FreeformFitParams& params);

// Returns the subdivision surface of each region of `regions` that
// NeedsSubdivision, fitted to its faces of `mesh` (`labels` one per face of
// `mesh`); empty when params.enabled is false. A region whose faces cannot
// be fitted (too few faces left after dropping non-manifold ones) is left
// without one: the segmentation stands. Errors: CANCELLED on stop.
absl::StatusOr<std::vector<RegionSubdivision>> FitFreeformRegions(
    const Mesh& mesh, std::span<const int> labels, std::span<const Region> regions, double noise,
    const FreeformFitParams& params, const RunContext& ctx);

// Sets result->subdivisions from its regions and estimates (noise: the
// larger of noise_sigma and exact_tolerance), `labels` one per face of
// `mesh`, the mesh the regions were grown on. Errors: CANCELLED on stop.
absl::Status FitFreeform(const Mesh& mesh, std::span<const int> labels,
                         const PipelineParams& params, const RunContext& ctx,
                         PipelineResult* result);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_CORE_SRC_PIPELINE_FREEFORM_REGIONS_H_
