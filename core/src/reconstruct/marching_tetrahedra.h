// The triangle surface between inside- and outside-labelled vertices of the
// tetrahedralization. Seed 001 §2.3.
#ifndef MESHSEG_RECONSTRUCT_MARCHING_TETRAHEDRA_H_
#define MESHSEG_RECONSTRUCT_MARCHING_TETRAHEDRA_H_

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/pu_function.h"
#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

struct IsoSurface {
  std::vector<Eigen::Vector3d> vertices;      // one per cut tet edge
  // Oriented inside → outside by each tet's vertex order (a closed surface
  // is consistently oriented however flat its tets).
  std::vector<std::array<int, 3>> triangles;
  // Per vertex: 1 if placed on an edge whose ends have the same sign of f or
  // whose ends include a sparse support; these get smoothed.
  std::vector<uint8_t> to_smooth;
};

// Returns the surface of marching tetrahedra on the labels `inside`: one
// vertex per edge with differently labelled ends, at the zero of f on it when
// the signs of f at the ends differ, else at the fraction |f_a| / (|f_a| +
// |f_b|) from end a (nearer the end of smaller |f|, never on it, so that no
// triangle collapses).
// Closed and manifold when no hull vertex is inside. `position`, `f`,
// `inside` and `sparse` have one entry per tet vertex.
// Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<IsoSurface> MarchingTetrahedra(const TetMesh& tets,
                                              const std::vector<Eigen::Vector3d>& position,
                                              const std::vector<double>& f,
                                              const std::vector<uint8_t>& inside,
                                              const std::vector<uint8_t>& sparse,
                                              const PuFunction& pu, const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_MARCHING_TETRAHEDRA_H_
