#include "reconstruct/local_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace meshseg::reconstruct_internal {
namespace {

using Found = std::vector<std::pair<uint32_t, double>>;  // index, squared distance

// Fits g over the points of `found` (sorted by distance) inside radius r;
// returns max |g(p_j)| over them (eqs. 2, 3, 6).
double FitAt(double r, const Found& found, const FitInput& in, Support* s) {
  Eigen::Vector3d sum_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_p = Eigen::Vector3d::Zero();
  double sum_w = 0.0;
  const double r2 = r * r;
  size_t inside = 0;
  for (; inside < found.size() && found[inside].second < r2; ++inside) {
    const double w = SupportWeight(found[inside].second, r);
    sum_n += w * in.normals[found[inside].first];
    sum_p += w * in.points[found[inside].first];
    sum_w += w;
  }
  s->radius = r;
  s->point_count = static_cast<int>(inside);
  if (sum_w <= 0.0 || sum_n.norm() <= 1e-12 * sum_w) {
    // No weighted point or normals cancelling out: nothing to fit to.
    s->m = Eigen::Vector3d::UnitZ();
    s->d = s->center;
    return inside == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  s->m = sum_n.normalized();
  s->d = sum_p / sum_w;
  double err = 0.0;
  for (size_t j = 0; j < inside; ++j)
    err = std::max(err, std::abs(s->g(in.points[found[j].first])));
  return err;
}

}  // namespace

Support FitSupport(const Eigen::Vector3d& center, double min_radius, const FitInput& in) {
  Support s;
  s.center = center;
  std::vector<uint32_t> idx;
  std::vector<double> d2;
  in.index.Nearest(center, kMinFitPoints, &idx, &d2);
  const double r_pts = d2.empty() ? 0.0 : std::sqrt(d2.back()) * (1.0 + 1e-9);
  double r_good = std::min(std::max(min_radius, r_pts), std::max(min_radius, in.max_radius));
  Found found;
  double searched = 2.0 * r_good;
  in.index.WithinRadius(center, searched, &found);
  if (FitAt(r_good, found, in, &s) > in.epsilon || r_good >= in.max_radius) {
    FitAt(r_good, found, in, &s);
    return s;
  }
  // Grow by doubling until the error exceeds ε, then bisect.
  double r_bad = -1.0;
  while (r_good < in.max_radius) {
    const double r_try = std::min(2.0 * r_good, in.max_radius);
    if (r_try > searched) {
      searched = std::min(2.0 * r_try, in.max_radius);
      in.index.WithinRadius(center, searched, &found);
    }
    if (FitAt(r_try, found, in, &s) > in.epsilon) {
      r_bad = r_try;
      break;
    }
    r_good = r_try;
  }
  if (r_bad > 0) {
    constexpr int kBisections = 8;
    for (int i = 0; i < kBisections; ++i) {
      const double r_mid = 0.5 * (r_good + r_bad);
      if (FitAt(r_mid, found, in, &s) > in.epsilon) {
        r_bad = r_mid;
      } else {
        r_good = r_mid;
      }
    }
  }
  FitAt(r_good, found, in, &s);
  return s;
}

}  // namespace meshseg::reconstruct_internal
