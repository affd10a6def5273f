#include "segment/estimate_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSigmas = 3.0;           // th_dis >= 3 sigma
constexpr double kMinAngleDeg = 5.0;      // ALGORITHMS.md S1 th_nm for CT meshes
constexpr double kMaxAngleDeg = 30.0;
// Test (6) uses n'_i, whose noise is a fraction of the tilt of n_i against
// it; the median tilt of n_i is a generous bound for n'_i's scatter.
constexpr double kAngleSpread = 1.5;
// A vertex whose local fit residual is within this factor of the most
// common residual sees noise only. The others' neighbourhoods leak over an
// edge that the sharp test missed (at high noise on a small part, half of
// them), and their residual measures the edge, not the noise.
constexpr double kCleanResidual = 1.5;
// Below this share of clean vertices the mode is not trusted and every
// vertex counts, as in ALGORITHMS.md S1.
constexpr double kMinCleanShare = 0.1;

double Median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  const auto mid = x.begin() + x.size() / 2;
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

// The mode of `x`: the middle of the shortest interval holding a quarter of
// the values.
double Mode(std::vector<double> x) {
  if (x.empty()) return 0.0;
  tbb::parallel_sort(x.begin(), x.end());
  const std::size_t k = std::max<std::size_t>(1, x.size() / 4);
  std::size_t best = 0;
  for (std::size_t i = 0; i + k <= x.size(); ++i) {
    if (x[i + k - 1] - x[i] < x[best + k - 1] - x[best]) best = i;
  }
  return x[best + k / 2];
}

}  // namespace

SegmentEstimates EstimateNoise(const CurvatureField& curvature, double l_avg,
                               const SegmentParams& params) {
  // Each vertex's tilt on its own (independent), then the non-sharp ones
  // in vertex order.
  const int n = static_cast<int>(curvature.sharp.size());
  std::vector<double> tilt_of(n, 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if (curvature.sharp[v]) continue;
      const double cosine =
          std::clamp(curvature.normal[v].dot(curvature.smooth_normal[v]), -1.0, 1.0);
      tilt_of[v] = std::acos(cosine) * 180.0 / kPi;
    }
  });
  std::vector<double> residual;
  std::vector<double> tilt_deg;
  for (int v = 0; v < n; ++v) {
    if (curvature.sharp[v]) continue;
    residual.push_back(curvature.fit_residual[v]);
    tilt_deg.push_back(tilt_of[v]);
  }
  const double limit = kCleanResidual * Mode(residual);
  std::vector<double> clean_residual;
  std::vector<double> clean_tilt_deg;
  for (std::size_t k = 0; k < residual.size(); ++k) {
    if (residual[k] > limit) continue;
    clean_residual.push_back(residual[k]);
    clean_tilt_deg.push_back(tilt_deg[k]);
  }
  if (clean_residual.size() >= kMinCleanShare * residual.size()) {
    residual = std::move(clean_residual);
    tilt_deg = std::move(clean_tilt_deg);
  }
  SegmentEstimates e;
  e.mean_edge_length = l_avg;
  // The two medians side by side (independent).
  double median_tilt_deg = 0.0;
  tbb::parallel_invoke([&] { e.noise_sigma = Median(residual); },
                       [&] { median_tilt_deg = Median(tilt_deg); });
  e.distance_tolerance = std::max(params.distance_tolerance * l_avg, kSigmas * e.noise_sigma);
  e.angle_tolerance_deg = params.angle_tolerance_deg.value_or(
      std::clamp(kAngleSpread * median_tilt_deg, kMinAngleDeg, kMaxAngleDeg));
  e.sharp_threshold = curvature.sharp_threshold;
  return e;
}

double DataUnitScale(const SegmentEstimates& estimates, std::optional<double> point_noise) {
  if (!point_noise || !(*point_noise > 0.0)) return 1.0;
  const double tolerance_unit = estimates.distance_tolerance / kSigmas;
  const double unit = estimates.noise_sigma;
  if (!(unit > 0.0) || !(unit < tolerance_unit)) return 1.0;
  const double ratio = tolerance_unit / unit;
  return ratio * ratio;
}

}  // namespace meshseg::segment_internal
