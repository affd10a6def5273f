// Inside/outside labels of the tetrahedralization's vertices by a minimum
// s-t cut (Boykov–Kolmogorov max-flow). Seed 001 §2.2.2, eqs. (7)-(10).
#ifndef MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
#define MESHSEG_RECONSTRUCT_GRAPH_CUT_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

// Returns 1 (inside, source side) or 0 (outside) per tet vertex. Terminal
// weights k|f(v)|/ave(v) tie v to the source if f(v) ≥ 0, else to the sink
// (eqs. 8-9); an edge weighs |f(v_i) + f(v_j)| / |v_i v_j| (eq. 10). Hull
// vertices are tied to the sink with a weight no cut can pay, so the inside
// is enclosed by the tetrahedralization and the surface is closed.
// `position` and `f` have one entry per tet vertex.
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<uint8_t>> GraphCutLabels(const TetMesh& tets,
                                                    const std::vector<Eigen::Vector3d>& position,
                                                    const std::vector<double>& f, double k,
                                                    const RunContext& ctx);

// Returns 1 where f ≥ 0 and 0 elsewhere, with hull vertices outside: the
// labels of the partition of unity alone.
std::vector<uint8_t> SignLabels(const TetMesh& tets, const std::vector<double>& f);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
