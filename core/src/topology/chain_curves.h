// Seed 002 STB3: boundary edges (the two faces carry different labels, the
// mesh border and unlabelled faces counting as label -1) chained into curves
// that end at corners: vertices where three or more labels meet or where the
// boundary does not pass straight through (more than two boundary edges).
#ifndef MESHSEG_SRC_TOPOLOGY_CHAIN_CURVES_H_
#define MESHSEG_SRC_TOPOLOGY_CHAIN_CURVES_H_

#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/topology.h"

namespace meshseg::topology_internal {

// Label of the face on the left of `h`, -1 for a border halfedge.
int LeftLabel(const TriMesh& mesh, std::span<const int> face_labels, OpenMesh::HalfedgeHandle h);

// True if the faces on the two sides of `h` carry different labels.
bool IsBoundaryHalfedge(const TriMesh& mesh, std::span<const int> face_labels,
                        OpenMesh::HalfedgeHandle h);

struct CurveChains {
  // vertices, left_region, right_region, closed, start/end_corner set.
  std::vector<BoundaryCurve> curves;
  // Corner k sits at mesh vertex corner_vertices[k].
  std::vector<int> corner_vertices;
  // Per halfedge index: the curve it runs along in the curve's direction,
  // else -1 (also for the opposite halfedge of a curve edge).
  std::vector<int> halfedge_curve;
};

// Returns the curves of the labelling. Every boundary edge lies on exactly
// one curve; curves run with left_region on their left, left_region being
// the smaller label of the pair unless that is -1.
CurveChains ChainCurves(const TriMesh& mesh, std::span<const int> face_labels);

}  // namespace meshseg::topology_internal

#endif  // MESHSEG_SRC_TOPOLOGY_CHAIN_CURVES_H_
