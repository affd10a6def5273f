// Outlier flags for the input points: points off the surface their
// neighbours describe, and points in sparse places whose neighbours describe
// no surface at all. Our addition to Nagai, Ohtake and Suzuki's reconstruction
// (ALGORITHMS.md S3): its linear local fits (eq. 3) tilt towards such points, most when their normals are random; the graph
// cut then only has to repair what remains.
//
// The tests are relative to the cloud itself, so that genuine points are
// kept however unevenly the scan samples the surface: the off-surface band is
// a multiple of the cloud's own noise (robustly estimated from the residuals
// of all points), and sparseness alone never condemns a point (a scanner
// samples surfaces seen at a grazing angle or from far away sparsely).
// Outliers spoil the neighbourhoods they fall in, so the test runs twice:
// the second pass judges the points the first flagged, and the sparse points
// it kept, against neighbours that passed the first (iterated rejection).
#ifndef MESHSEG_RECONSTRUCT_OUTLIERS_H_
#define MESHSEG_RECONSTRUCT_OUTLIERS_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "mesh/point_index.h"
#include "meshseg/reconstruct.h"
#include "reconstruct/neighbors.h"

namespace meshseg::reconstruct_internal {

// Returns, per point, the mean distance to its 6 nearest other points
// (≈ sqrt(area / count) on a uniformly sampled surface, large for isolated
// outliers), from the first 6 columns of `nearest`.
std::vector<double> MeanNeighborDistances(const std::vector<Eigen::Vector3d>& points,
                                          const NeighborTable& nearest);

struct OutlierTest {
  int neighbors = 10;  // k of the local plane fits
  // A point whose `spread` (MeanNeighborDistances) exceeds this is sparse:
  // its neighbours must also span a plane, not a 3-D scatter. Model units.
  double sparse_distance = 0.0;
  // The off-surface band: max(min_band, noise_sigmas × σ), σ the noise of
  // the cloud (1.4826 × median residual, the MAD estimate of a Gaussian's
  // standard deviation). Model units.
  double min_band = 0.0;
  double noise_sigmas = 4.0;
  // A sparse point whose mean distance to its 6 nearest kept neighbours
  // exceeds this many times their median spread is detached (second pass).
  double detached_ratio = 3.0;
};

struct Outliers {
  std::vector<uint8_t> flags;  // one per point: 1 = outlier
  double noise = 0.0;          // σ, model units
  double band = 0.0;           // the off-surface band used, model units
  double spacing = 0.0;        // h: median spread (OutliersOfCloud only)
  // The k-NN table of all the points, k = max(normal_neighbors, 6)
  // (OutliersOfCloud only; the normals reuse it).
  NeighborTable nearest;
};

// Flags a point whose distance to the least-squares plane of its k nearest
// other points exceeds the band; a sparse point also when those neighbours
// lie farther than the band from their own plane (RMS: they scatter in 3-D);
// with `normals` given, also a point whose normal is more than 60° from the
// normals of all but one of those neighbours. The first pass takes the k
// nearest from `nearest` (k ≤ nearest.k). The second pass takes the neighbours among
// the points the first kept, k of its 2k + 1 nearest (a point with fewer of
// them is flagged: it lies among outliers), and flags a sparse point also
// when it is detached from them (detached_ratio).
Outliers FindOutliers(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const mesh_internal::PointIndex& index, const NeighborTable& nearest,
                      const std::vector<double>& spread, const OutlierTest& test);

// The test Reconstruct() runs: spread and h (the median spread) of all the
// points, then FindOutliers with `params`' distances in h.
Outliers OutliersOfCloud(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals,
                         const mesh_internal::PointIndex& index, const ReconstructParams& params);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_OUTLIERS_H_
