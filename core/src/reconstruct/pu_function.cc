#include "reconstruct/pu_function.h"

#include <algorithm>
#include <cmath>

namespace meshseg::reconstruct_internal {

PuFunction::PuFunction(const std::vector<Support>& supports) : supports_(supports) {
  if (supports.empty()) return;
  double smallest = supports[0].radius;
  for (const auto& s : supports) {
    smallest = std::min(smallest, s.radius);
    largest_radius_ = std::max(largest_radius_, s.radius);
  }
  const int count = static_cast<int>(std::floor(std::log2(largest_radius_ / smallest))) + 1;
  groups_.resize(count);
  for (size_t i = 0; i < supports.size(); ++i) {
    const int c =
        std::min(count - 1, static_cast<int>(std::floor(std::log2(supports[i].radius / smallest))));
    groups_[c].centers.push_back(supports[i].center);
    groups_[c].support.push_back(static_cast<int>(i));
    groups_[c].max_radius = std::max(groups_[c].max_radius, supports[i].radius);
  }
  std::erase_if(groups_, [](const Group& g) { return g.centers.empty(); });
  for (auto& g : groups_) g.index = std::make_unique<mesh_internal::PointIndex>(g.centers);
}

double PuFunction::operator()(const Eigen::Vector3d& x) const {
  thread_local std::vector<std::pair<uint32_t, double>> found;
  double sum_wg = 0.0;
  double sum_w = 0.0;
  for (const auto& g : groups_) {
    g.index->WithinRadius(x, g.max_radius, &found);
    for (const auto& [j, d2] : found) {
      const Support& s = supports_[g.support[j]];
      if (d2 >= s.radius * s.radius) continue;
      const double w = SupportWeight(d2, s.radius);
      sum_wg += w * s.g(x);
      sum_w += w;
    }
  }
  if (sum_w <= 0.0) return -largest_radius_;
  return sum_wg / sum_w;
}

}  // namespace meshseg::reconstruct_internal
