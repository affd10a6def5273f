// The vertices and edges of the B-rep: one vertex per corner cluster (at its
// CornerPoint; clusters at one point share it), one edge per boundary curve
// (junction artifacts and curves between corners at one point contracted
// into their vertex) on the curve ChooseEdgeCurve picks, a closed
// curve without corners getting a vertex of its own. Vertex tolerances grow
// to cover the distance between a vertex and its edges' ends.
#ifndef MESHSEG_SRC_BREP_BOUNDARY_EDGES_H_
#define MESHSEG_SRC_BREP_BOUNDARY_EDGES_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/mesh.h"
#include "meshseg/topology.h"

#include <span>
#include <string>
#include <vector>

#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>

namespace meshseg::brep_internal {

struct EdgeTolerances {
  double curve = 0.0;      // accepted deviation of an edge from its boundary, model units
  double exact_gap = 0.0;  // a curve this close to both surfaces lies on them
  double corner_move = 0.0;  // how far a corner may move onto its surfaces
  double l_avg = 0.0;
  // How far a fitted surface may lie off the true one (3 noise sigmas), model
  // units: it decides where an intersection of two surfaces can be trusted.
  double surface_offset = 0.0;
};

struct BoundaryEdges {
  std::vector<TopoDS_Edge> edges;    // per curve id; null when contracted or failed
  std::vector<std::string> failure;  // per curve id: why its edge failed ("" otherwise)
  // Per curve id: contracted into its vertex, as the junction artifacts and
  // the curves that leave a vertex and come back to it within the curve
  // tolerance (a zig-zag of labels where several regions meet).
  std::vector<char> contracted;
  int exact_count = 0;
  int fitted_count = 0;
};

// Returns the edges of every curve of `topology`; `surfaces` per region id
// (null where the region has none: its curves are fitted to the other side).
BoundaryEdges MakeBoundaryEdges(const TriMesh& mesh, const Topology& topology,
                                std::span<const Handle(Geom_Surface)> surfaces,
                                const EdgeTolerances& tolerances);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_BOUNDARY_EDGES_H_
