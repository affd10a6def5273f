#include "segment/estimate_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSigmas = 3.0;           // th_dis >= 3 sigma
constexpr double kMinAngleDeg = 5.0;      // seed 000 default for CT meshes
constexpr double kMaxAngleDeg = 30.0;
// Test (6) uses n'_i, whose noise is a fraction of the tilt of n_i against
// it; the median tilt of n_i is a generous bound for n'_i's scatter.
constexpr double kAngleSpread = 1.5;

double Median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  const auto mid = x.begin() + x.size() / 2;
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

}  // namespace

SegmentEstimates EstimateNoise(const CurvatureField& curvature, double l_avg,
                               const SegmentParams& params) {
  std::vector<double> residual;
  std::vector<double> tilt_deg;
  for (std::size_t v = 0; v < curvature.sharp.size(); ++v) {
    if (curvature.sharp[v]) continue;
    residual.push_back(curvature.fit_residual[v]);
    const double cosine = std::clamp(curvature.normal[v].dot(curvature.smooth_normal[v]), -1.0, 1.0);
    tilt_deg.push_back(std::acos(cosine) * 180.0 / kPi);
  }
  SegmentEstimates e;
  e.mean_edge_length = l_avg;
  e.noise_sigma = Median(residual);
  e.distance_tolerance = std::max(params.distance_tolerance * l_avg, kSigmas * e.noise_sigma);
  e.angle_tolerance_deg = params.angle_tolerance_deg.value_or(
      std::clamp(kAngleSpread * Median(tilt_deg), kMinAngleDeg, kMaxAngleDeg));
  e.sharp_threshold = curvature.sharp_threshold;
  return e;
}

}  // namespace meshseg::segment_internal
