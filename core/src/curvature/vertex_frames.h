// Per-vertex quantities both curvature passes start from: the area-weighted
// normal n_i, the mean incident edge length l_i,avg and the vertex area
// (a third of the incident triangle areas). Seed 000 §2 step 1.
#ifndef MESHSEG_SRC_CURVATURE_VERTEX_FRAMES_H_
#define MESHSEG_SRC_CURVATURE_VERTEX_FRAMES_H_

#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"

namespace meshseg::curvature_internal {

struct VertexFrames {
  std::vector<Eigen::Vector3d> normal;  // unit; zero for isolated vertices
  std::vector<double> mean_edge_length;
  std::vector<double> area;
};

// Returns the frames of every vertex of `mesh` (vectors indexed by vertex).
VertexFrames ComputeVertexFrames(const TriMesh& mesh);

}  // namespace meshseg::curvature_internal

#endif  // MESHSEG_SRC_CURVATURE_VERTEX_FRAMES_H_
