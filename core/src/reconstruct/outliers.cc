#include "reconstruct/outliers.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// cos 60°: neighbours' normals within this agree with a point's normal.
constexpr double kMinCos = 0.5;
// A normal that fewer neighbours than this agree with is astray.
constexpr int kMinAgreeing = 2;
// Median absolute deviation → standard deviation of a Gaussian.
constexpr double kMadToSigma = 1.4826;
// Fewer neighbours than this fit no plane; the point is not judged by it.
constexpr size_t kMinFitPoints = 3;
// The spread of a point is its mean distance to this many nearest others.
constexpr int kSpreadNeighbors = 6;

// How point i sits against the least-squares plane of `neighbors`.
struct LocalFit {
  double residual = 0.0;   // distance of point i to the plane
  double thickness = 0.0;  // RMS distance of the neighbours to it
  bool astray = false;     // normal i > 60° from all but one neighbour's
};

LocalFit FitAround(size_t i, const std::vector<uint32_t>& neighbors,
                   const std::vector<Eigen::Vector3d>& points,
                   const std::vector<Eigen::Vector3d>& normals) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const uint32_t j : neighbors) mean += points[j];
  mean /= static_cast<double>(neighbors.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const uint32_t j : neighbors) cov += (points[j] - mean) * (points[j] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  LocalFit fit;
  fit.residual = std::abs(eig.eigenvectors().col(0).dot(points[i] - mean));
  fit.thickness =
      std::sqrt(std::max(0.0, eig.eigenvalues()(0)) / static_cast<double>(neighbors.size()));
  // A normal is astray when hardly any neighbour's normal lies within 60° of
  // it: next to a crease a point's neighbours are mostly on the other face,
  // and on a thin sheet on the other side, but a few share its own.
  if (!normals.empty()) {
    const Eigen::Vector3d n = normals[i].normalized();
    int agreeing = 0;
    for (const uint32_t j : neighbors) agreeing += n.dot(normals[j].normalized()) >= kMinCos;
    fit.astray = agreeing < kMinAgreeing;
  }
  return fit;
}

// The first `k` of `found` that are not `i` and not flagged in `excluded`
// (nullptr: none is).
std::vector<uint32_t> FirstOthers(size_t i, const std::vector<uint32_t>& found, size_t k,
                                  const std::vector<uint8_t>* excluded) {
  std::vector<uint32_t> out;
  for (const uint32_t j : found) {
    if (out.size() == k) break;
    if (j != i && !(excluded && (*excluded)[j])) out.push_back(j);
  }
  return out;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// True if `p` lies farther from its kept neighbours `nb` than `ratio` times
// their own spacing: a gap that sampling of their surface does not leave
// (beyond the edge of a scanned patch, in the plane of the patch).
bool Detached(const Eigen::Vector3d& p, const std::vector<uint32_t>& nb,
              const std::vector<Eigen::Vector3d>& points, const std::vector<double>& spreads,
              double ratio) {
  double sum = 0.0;
  const size_t m = std::min<size_t>(kSpreadNeighbors, nb.size());
  std::vector<double> theirs;
  for (size_t a = 0; a < nb.size(); ++a) {
    if (a < m) sum += (points[nb[a]] - p).norm();
    theirs.push_back(spreads[nb[a]]);
  }
  return sum / static_cast<double>(m) > ratio * Median(std::move(theirs));
}

}  // namespace

Outliers FindOutliers(const std::vector<Eigen::Vector3d>& points,
                      const std::vector<Eigen::Vector3d>& normals,
                      const mesh_internal::PointIndex& index, const NeighborTable& nearest,
                      const std::vector<double>& spread, const OutlierTest& test) {
  const size_t n = points.size();
  const size_t k = static_cast<size_t>(std::clamp(test.neighbors, 1, nearest.k));
  std::vector<LocalFit> fits(n);
  std::vector<uint8_t> fitted(n, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const std::vector<uint32_t> nb =
          FirstOthers(i, std::vector<uint32_t>(nearest.Row(i), nearest.Row(i) + k), k, nullptr);
      if (nb.size() < kMinFitPoints) continue;
      fits[i] = FitAround(i, nb, points, normals);
      fitted[i] = 1;
    }
  });
  Outliers out;
  {
    std::vector<double> residuals;
    residuals.reserve(n);
    for (size_t i = 0; i < n; ++i) {
      if (fitted[i]) residuals.push_back(fits[i].residual);
    }
    out.noise = kMadToSigma * Median(std::move(residuals));
  }
  out.band = std::max(test.min_band, test.noise_sigmas * out.noise);
  // Sparse: farther from its neighbours than the sparse distance (or NaN).
  const auto sparse = [&](size_t i) { return !(spread[i] <= test.sparse_distance); };
  const auto condemned = [&](size_t i, const LocalFit& fit) -> uint8_t {
    return fit.residual > out.band || (sparse(i) && fit.thickness > out.band) || fit.astray;
  };
  std::vector<uint8_t> first(n, 0);
  for (size_t i = 0; i < n; ++i) first[i] = fitted[i] && condemned(i, fits[i]);

  // Second pass: flagged and sparse points against neighbours the first kept.
  out.flags = first;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (!fitted[i] || !(first[i] || sparse(i))) continue;
      index.Nearest(points[i], 2 * static_cast<int>(k) + 1, &idx, &d2);
      // Fewer than k kept among the 2k + 1 nearest: it lies among outliers
      // (and a plane through fewer points says nothing).
      const std::vector<uint32_t> nb = FirstOthers(i, idx, k, &first);
      if (nb.size() < std::min(k, idx.size() - 1) || nb.size() < kMinFitPoints) {
        out.flags[i] = 1;
        continue;
      }
      out.flags[i] = condemned(i, FitAround(i, nb, points, normals)) ||
                     Detached(points[i], nb, points, spread, test.detached_ratio);
    }
  });
  return out;
}

Outliers OutliersOfCloud(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals,
                         const mesh_internal::PointIndex& index, const ReconstructParams& params) {
  // One k-NN pass serves the spread, the plane fits and (via Outliers) the
  // normals.
  NeighborTable nearest =
      NearestOthers(points, index, std::max(params.normal_neighbors, kSpreadNeighbors));
  const std::vector<double> spread = MeanNeighborDistances(points, nearest);
  const double h = Median(spread);
  const OutlierTest test{params.normal_neighbors, params.outlier_distance * h,
                         params.off_surface_distance * h, params.outlier_noise_sigmas};
  Outliers out = FindOutliers(points, normals, index, nearest, spread, test);
  out.spacing = h;
  out.nearest = std::move(nearest);
  return out;
}

std::vector<double> MeanNeighborDistances(const std::vector<Eigen::Vector3d>& points,
                                          const NeighborTable& nearest) {
  std::vector<double> mean(points.size(), 0.0);
  const int m = std::min(nearest.k, kSpreadNeighbors);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      double sum = 0.0;
      int count = 0;
      for (int j = 0; j < m; ++j) {
        const uint32_t o = nearest.Row(i)[j];
        if (o == i) continue;  // padding: fewer others than m
        sum += (points[o] - points[i]).norm();
        ++count;
      }
      mean[i] = count > 0 ? sum / count : 0.0;
    }
  });
  return mean;
}

}  // namespace meshseg::reconstruct_internal
