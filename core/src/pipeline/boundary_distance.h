// How far each vertex of a segmented mesh lies from its region's boundary.
#ifndef MESHSEG_PIPELINE_BOUNDARY_DISTANCE_H_
#define MESHSEG_PIPELINE_BOUNDARY_DISTANCE_H_

#include <limits>
#include <span>
#include <vector>

#include "meshseg/mesh.h"

namespace meshseg::pipeline_internal {

// Returns one distance per vertex of `mesh`: the length of the shortest edge
// path to a boundary vertex (one whose faces carry more than one label of
// `face_labels`, or one on an open border of the mesh), 0 on one; infinity
// on a component without any, and where the path is `limit` or longer (the
// search stops there). An edge path overestimates the distance along the
// surface by at most the triangles' zigzag (about 15 % on a regular mesh).
// `face_labels` has one entry per face.
std::vector<double> VertexBoundaryDistance(
    const TriMesh& mesh, std::span<const int> face_labels,
    double limit = std::numeric_limits<double>::infinity());

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_BOUNDARY_DISTANCE_H_
