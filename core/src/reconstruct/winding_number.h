// The generalized winding number of an oriented point cloud (Jacobson et al.
// 2013; for points, Barill et al., "Fast winding numbers for soups and
// clouds", 2018): w(q) = Σ_j a_j n_j · (p_j − q) / (4π |p_j − q|³), the solid
// angle the sampled surface subtends at q over 4π, with a_j the area a point
// stands for and n_j its outward normal. It is about 1 inside a closed
// sampled surface and 0 outside, 1/2 on it, and it closes holes and gaps of
// the sampling smoothly (across an opening it passes 1/2 near the opening's
// span, as a soap film would). Our addition to seed 001: the inside/outside
// evidence of the graph cut (graph_cut.h), global where the partition of
// unity is local; f extrapolates each face's plane into unsampled space
// (flaps) and changes sign near sharp edges (tunnels, i.e. handles), w does
// neither.
//
// Evaluated by Barnes-Hut: a cluster of points far from q (farther than
// kFarRatio × its radius) acts as one dipole at its area-weighted centre.
#ifndef MESHSEG_RECONSTRUCT_WINDING_NUMBER_H_
#define MESHSEG_RECONSTRUCT_WINDING_NUMBER_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// A cluster counts as far when its centre lies farther than this many of its
// radii from the query; Barill et al. use 2 (error under 1 % of a unit jump).
inline constexpr double kFarRatio = 2.0;
// Points per leaf of the cluster tree.
inline constexpr int kLeafPoints = 16;

class WindingNumber {
 public:
  // `outward` are unit outward normals, `areas` the area per point, one each
  // per point. A point's dipole is smoothed over a disc of its own area
  // (|p − q|² + a/π in place of |p − q|²), so w stays finite at the points.
  WindingNumber(const std::vector<Eigen::Vector3d>& points,
                const std::vector<Eigen::Vector3d>& outward, const std::vector<double>& areas);

  // Returns w(q). Thread-safe.
  double operator()(const Eigen::Vector3d& q) const;

 private:
  struct Node {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();  // area-weighted
    Eigen::Vector3d dipole = Eigen::Vector3d::Zero();  // Σ a n
    double radius = 0.0;                               // of the points about center
    int first = 0, count = 0;                          // range in order_
    int child[2] = {-1, -1};
  };
  int Build(int first, int count);
  double Direct(int first, int count, const Eigen::Vector3d& q) const;

  std::vector<Eigen::Vector3d> points_;
  std::vector<Eigen::Vector3d> weighted_normals_;  // a n, in tree order
  std::vector<double> smoothing_;                  // a / π, in tree order
  std::vector<Node> nodes_;
};

// Returns, per point, the area it stands for, from the mean distance m to its
// 6 nearest neighbours (MeanNeighborDistances): on a plane sampled evenly at
// density σ the k-th neighbour lies at about sqrt(k / (π σ)), so
// m ≈ 1.805 / sqrt(π σ) and the area per point 1/σ ≈ π (m / 1.805)².
std::vector<double> PointAreas(const std::vector<double>& mean_neighbor_distance);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_WINDING_NUMBER_H_
