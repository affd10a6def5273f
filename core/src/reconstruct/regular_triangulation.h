// The regular (weighted Delaunay) tetrahedralization of the support centres
// with weights r_i². Seed 001 §2.2.1. The only file that uses CGAL.
#ifndef MESHSEG_RECONSTRUCT_REGULAR_TRIANGULATION_H_
#define MESHSEG_RECONSTRUCT_REGULAR_TRIANGULATION_H_

#include <array>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/local_fit.h"

namespace meshseg::reconstruct_internal {

struct TetMesh {
  std::vector<int> support;               // per tet vertex: its support index
  // Finite tetrahedra, tet vertex indices, each in positive orientation as
  // the exact predicates decide it (also for a tet of almost no volume).
  std::vector<std::array<int, 4>> tets;
  std::vector<std::array<int, 2>> edges;  // finite edges, tet vertex indices, a < b
  std::vector<uint8_t> on_hull;           // per tet vertex: 1 on the convex hull
};

// Returns the regular triangulation of the support centres weighted by r²;
// supports hidden by larger ones are not vertices. Tet vertices are numbered
// in increasing support order.
// Errors: INVALID_ARGUMENT if the centres span no volume (fewer than 4
// vertices or no tetrahedron); CANCELLED when ctx requests a stop.
absl::StatusOr<TetMesh> RegularTetrahedralization(const std::vector<Support>& supports,
                                                  const RunContext& ctx);

// The power weights r_i² of the supports' balls (the weights above).
std::vector<double> RadiiSquared(const std::vector<Support>& supports);

// As above with the weight of each support given (one per support); a
// support with a negative weight is not a vertex.
absl::StatusOr<TetMesh> RegularTetrahedralization(const std::vector<Support>& supports,
                                                  const std::vector<double>& weights,
                                                  const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_REGULAR_TRIANGULATION_H_
