// Inside/outside labels of the tetrahedralization's vertices by a minimum
// s-t cut (Boykov–Kolmogorov max-flow). Seed 001 §2.2.2, eqs. (7)-(10).
#ifndef MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
#define MESHSEG_RECONSTRUCT_GRAPH_CUT_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/point_index.h"
#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

// What the graph cut weighs, per tet vertex and per tet edge.
struct CutInput {
  const std::vector<Eigen::Vector3d>& position;  // per tet vertex
  // Per tet vertex: the inside evidence w − 1/2 of the winding number
  // (winding_number.h); clamped to [−1/2, 1/2].
  const std::vector<double>& evidence;
  const std::vector<double>& f;           // per tet vertex: the PU implicit
  const std::vector<uint8_t>& supported;  // per tet edge (TetMesh::edges order)
  double k = 10.0;                        // seed 001's terminal weight ratio
  double h = 1.0;                         // point spacing, model units
};

// Returns 1 (inside, source side) or 0 (outside) per tet vertex: the minimum
// of an energy in the form of seed 001 eqs. (7)-(10), data on the volume
// inside and outside plus a cost on the area of the surface between them.
//   data (eqs. 8-9): k |e(v)| V(v) / h³ ties v to the source if e(v) ≥ 0, else
//     to the sink; e is the winding number's evidence, global where the seed's
//     f is local (f extrapolates each face's plane into unsampled space and
//     turns over near sharp edges), and V(v) a quarter of the volume of v's
//     tets, so evidence counts by volume.
//   edge (eq. 10): (l / h)² × ρ, about the area in h² the cut adds there; ρ is
//     the seed's |f(v_i) + f(v_j)| / l, kept in [kMinAreaCost, 1], on a
//     supported edge (points near it, where f describes them), and 1 on an
//     unsupported one: a surface across a gap in the sampling costs its full
//     area, so the cut closes gaps with the least area rather than following
//     f's extrapolation (flaps), and points near a surface make it cheap.
// Hull vertices are tied to the sink with a weight no cut can pay, so the
// inside is enclosed by the tetrahedralization and the surface is closed.
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<uint8_t>> GraphCutLabels(const TetMesh& tets, const CutInput& in,
                                                    const RunContext& ctx);

// Least area cost ρ of a supported edge: the surface the points describe
// still costs a little, so noise does not fold it for free.
inline constexpr double kMinAreaCost = 0.05;

// Returns, per tet edge, 1 if an input point lies within 2h plus half the
// edge's length of its midpoint (`index` over the non-outlier points).
std::vector<uint8_t> SupportedEdges(const TetMesh& tets,
                                    const std::vector<Eigen::Vector3d>& position,
                                    const PointIndex& index, double h);

// Returns 1 where f ≥ 0 and 0 elsewhere, with hull vertices outside: the
// labels of the partition of unity alone.
std::vector<uint8_t> SignLabels(const TetMesh& tets, const std::vector<double>& f);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_GRAPH_CUT_H_
