#include "reconstruct/local_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace meshseg::reconstruct_internal {
namespace {

// The points within some radius of a support's centre, gathered once per
// query so that the repeated fits of the radius search read contiguous
// memory: distance to the centre, position, normal.
struct Neighborhood {
  std::vector<double> dist;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Vector3d> n;

  // Gathers the points with |p − center| < radius (any order).
  void Gather(const Eigen::Vector3d& center, double radius, const FitInput& in) {
    thread_local std::vector<std::pair<uint32_t, double>> found;
    in.index.WithinRadiusUnordered(center, radius, &found);
    dist.resize(found.size());
    p.resize(found.size());
    n.resize(found.size());
    for (size_t j = 0; j < found.size(); ++j) {
      dist[j] = std::sqrt(found[j].second);
      p[j] = in.points[found[j].first];
      n[j] = in.normals[found[j].first];
    }
  }

  // Drops the points at distance ≥ r (they lie outside every later fit).
  void KeepWithin(double r) {
    size_t kept = 0;
    for (size_t j = 0; j < dist.size(); ++j) {
      if (!(dist[j] < r)) continue;
      dist[kept] = dist[j];
      p[kept] = p[j];
      n[kept] = n[j];
      ++kept;
    }
    dist.resize(kept);
    p.resize(kept);
    n.resize(kept);
  }
};

// Fits g over the points of `nb` inside radius r (eqs. 2, 3); returns
// max |g(p_j)| over them (eq. 6), or, once that exceeds `stop`, the first
// value over it.
double FitAt(double r, const Neighborhood& nb, Support* s,
             double stop = std::numeric_limits<double>::infinity()) {
  Eigen::Vector3d sum_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_p = Eigen::Vector3d::Zero();
  double sum_w = 0.0;
  int inside = 0;
  for (size_t j = 0; j < nb.dist.size(); ++j) {
    if (!(nb.dist[j] < r)) continue;
    const double w = B2(1.5 * nb.dist[j] / r);  // SupportWeight
    sum_n += w * nb.n[j];
    sum_p += w * nb.p[j];
    sum_w += w;
    ++inside;
  }
  s->radius = r;
  s->point_count = inside;
  if (sum_w <= 0.0 || sum_n.norm() <= 1e-12 * sum_w) {
    // No weighted point or normals cancelling out: nothing to fit to.
    s->m = Eigen::Vector3d::UnitZ();
    s->d = s->center;
    return inside == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  s->m = sum_n.normalized();
  s->d = sum_p / sum_w;
  const double offset = s->m.dot(s->d);
  double err = 0.0;
  for (size_t j = 0; j < nb.dist.size(); ++j) {
    if (!(nb.dist[j] < r)) continue;
    err = std::max(err, std::abs(s->m.dot(nb.p[j]) - offset));
    if (err > stop) return err;
  }
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
  // Each query reaches exactly the radius about to be fitted: a doubling
  // queries 4× the points of the last (on a surface), so all of them cost
  // 4/3 of the last.
  thread_local Neighborhood nb;
  nb.Gather(center, r_good, in);
  if (FitAt(r_good, nb, &s, in.epsilon) > in.epsilon || r_good >= in.max_radius) {
    FitAt(r_good, nb, &s);
    return s;
  }
  // Grow by doubling until the error exceeds ε, then bisect.
  double r_bad = -1.0;
  while (r_good < in.max_radius) {
    const double r_try = std::min(2.0 * r_good, in.max_radius);
    nb.Gather(center, r_try, in);
    if (FitAt(r_try, nb, &s, in.epsilon) > in.epsilon) {
      r_bad = r_try;
      break;
    }
    r_good = r_try;
  }
  if (r_bad > 0) {
    constexpr int kBisections = 8;
    for (int i = 0; i < kBisections; ++i) {
      const double r_mid = 0.5 * (r_good + r_bad);
      if (FitAt(r_mid, nb, &s, in.epsilon) > in.epsilon) {
        r_bad = r_mid;
        nb.KeepWithin(r_bad);
      } else {
        r_good = r_mid;
      }
    }
  }
  FitAt(r_good, nb, &s);
  return s;
}

}  // namespace meshseg::reconstruct_internal
