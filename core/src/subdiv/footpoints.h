// Closest points of data points on a triangle mesh, as a face and the
// barycentric coordinates there: the footpoints of the least-squares fit.
#ifndef MESHSEG_SUBDIV_FOOTPOINTS_H_
#define MESHSEG_SUBDIV_FOOTPOINTS_H_

#include <array>
#include <vector>

#include <Eigen/Core>

namespace meshseg::subdiv_internal {

struct FootPoint {
  int face = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // weights of the face's vertices
  double distance = 0.0;                                  // from the data point
};

// Returns the closest point of triangle abc to p as barycentric weights
// (Ericson, Real-Time Collision Detection, section 5.1.5).
Eigen::Vector3d ClosestBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Returns, per point of `data`, its footpoint on the mesh (`vertices`,
// `faces`): the closest point among the faces around the mesh's `candidates`
// nearest vertices (a kd-tree search). Exact when the mesh's triangles are
// small against the distance between its sheets; the fit's limit meshes are.
std::vector<FootPoint> FootPoints(const std::vector<Eigen::Vector3d>& vertices,
                                  const std::vector<std::array<int, 3>>& faces,
                                  const std::vector<Eigen::Vector3d>& data, int candidates = 4);

}  // namespace meshseg::subdiv_internal

#endif  // MESHSEG_SUBDIV_FOOTPOINTS_H_
