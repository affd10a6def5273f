#include "curvature/sharp_threshold.h"

#include <algorithm>
#include <cstddef>

namespace meshseg::curvature_internal {
namespace {

// Seed 000 uses th_sv in [4, 8] on CT meshes several times finer than the
// features; 3 keeps fillets of radius >= 3 l_i,avg out of the sharp set on
// coarser meshes while folds (radius ~ l) stay sharp.
constexpr double kCleanThreshold = 3.0;
// Below this th_sv only folds (radius of curvature ~ one edge) count as sharp.
constexpr double kMinThreshold = 1.5;
// Pass-1 curvature noise is about kappa_noise * l ~ 2 * rho for relative
// noise rho = sigma / l (second derivative of a 6-coefficient fit over a
// radius of 2 l). Keeping 3 of those sigmas below the threshold gives
// th_sv <= 1 / (6 rho).
constexpr double kNoiseFactor = 1.0 / 6.0;

}  // namespace

double DeriveSharpThreshold(const std::vector<double>& residual,
                            const std::vector<double>& edge_length) {
  std::vector<double> rho;
  rho.reserve(residual.size());
  for (std::size_t v = 0; v < residual.size(); ++v) {
    if (edge_length[v] > 0.0) rho.push_back(residual[v] / edge_length[v]);
  }
  if (rho.empty()) return kCleanThreshold;
  const auto mid = rho.begin() + rho.size() / 2;
  std::nth_element(rho.begin(), mid, rho.end());
  const double median = *mid;
  if (!(median > 0.0)) return kCleanThreshold;
  return std::clamp(kNoiseFactor / median, kMinThreshold, kCleanThreshold);
}

}  // namespace meshseg::curvature_internal
