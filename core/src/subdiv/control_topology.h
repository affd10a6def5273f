// The edges, sharp edges and vertex kinds of a control mesh: what the Loop
// rules (loop_refine.h) and limit masks (limit_positions.h) are chosen by.
#ifndef MESHSEG_SUBDIV_CONTROL_TOPOLOGY_H_
#define MESHSEG_SUBDIV_CONTROL_TOPOLOGY_H_

#include <array>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/subdiv.h"

namespace meshseg::subdiv_internal {

// Hoppe et al. 1994 section 3.2: a vertex is classified by its sharp edges.
enum class VertexKind {
  kSmooth,  // no sharp edge, or one (a dart): Loop's vertex rule
  kCrease,  // exactly two sharp edges: the cubic B-spline rule along them
  kCorner,  // three or more sharp edges, or tagged: stays where it is
};

struct ControlTopology {
  // Unique edges (a < b) and, per edge, the vertex opposite it in each of its
  // faces (-1 for the missing face of a boundary edge).
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 2>> opposite;
  std::vector<char> sharp;  // per edge: tagged crease or boundary edge
  // Per face, the edge of (f[i], f[(i + 1) % 3]).
  std::vector<std::array<int, 3>> face_edges;
  // Per vertex, its incident edges.
  std::vector<std::vector<int>> vertex_edges;
  std::vector<VertexKind> kind;
};

// Returns the topology of `mesh`.
// Errors (INVALID_ARGUMENT): no faces, indices out of range, repeated
// indices in a face, NaN/Inf coordinates, an edge of more than two faces, a
// crease that is not an edge of the mesh.
absl::StatusOr<ControlTopology> BuildControlTopology(const ControlMesh& mesh);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_CONTROL_TOPOLOGY_H_
