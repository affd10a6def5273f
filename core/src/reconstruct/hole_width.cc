#include "reconstruct/hole_width.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace meshseg::reconstruct_internal {

namespace {

// Distance from `q` to the closed polygon `loop`.
double DistanceToLoop(const std::vector<Eigen::Vector3d>& loop, const Eigen::Vector3d& q) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d& a = loop[i];
    const Eigen::Vector3d e = loop[(i + 1) % loop.size()] - a;
    const double e2 = e.squaredNorm();
    const double t = e2 > 0 ? std::clamp((q - a).dot(e) / e2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * e - q).norm());
  }
  return best;
}

}  // namespace

std::vector<std::array<int, 3>> LeastAreaDisc(const std::vector<Eigen::Vector3d>& loop) {
  const int n = static_cast<int>(loop.size());
  std::vector<std::array<int, 3>> triangles;
  if (n < 3) return triangles;
  // area[i * n + j]: least area of the polygon i, i + 1, ..., j closed by the
  // chord j → i; apex[i * n + j] the third vertex of the triangle on it.
  std::vector<double> area(static_cast<size_t>(n) * n, 0.0);
  std::vector<int> apex(static_cast<size_t>(n) * n, -1);
  for (int span = 2; span < n; ++span) {
    for (int i = 0; i + span < n; ++i) {
      const int j = i + span;
      double best = std::numeric_limits<double>::infinity();
      for (int k = i + 1; k < j; ++k) {
        const double a = area[i * n + k] + area[k * n + j] +
                         0.5 * (loop[k] - loop[i]).cross(loop[j] - loop[i]).norm();
        if (a < best) {
          best = a;
          apex[i * n + j] = k;
        }
      }
      area[i * n + j] = best;
    }
  }
  std::vector<std::array<int, 2>> chords = {{0, n - 1}};
  while (!chords.empty()) {
    const auto [i, j] = chords.back();
    chords.pop_back();
    if (j - i < 2) continue;
    const int k = apex[i * n + j];
    triangles.push_back({i, k, j});
    chords.push_back({i, k});
    chords.push_back({k, j});
  }
  return triangles;
}

double HoleWidth(const std::vector<Eigen::Vector3d>& loop, double step, double stop,
                 const Clearance& clearance) {
  if (loop.size() < 3 || !(step > 0)) return 0.0;
  const double slack = 0.5 * std::sqrt(5.0) * step;
  // Rows parallel to each triangle's longest side a b, from it to the apex
  // c, at most a step apart in height; samples at most a step apart along
  // each row. c's foot lies on a b (the angles at a and b are not obtuse), so
  // each row's orthogonal projection onto the row below lies inside it: every
  // point is within a step of the row below it and half a step along it of a
  // sample, √5 / 2 steps in all.
  double radius = 0.0;
  for (const auto& triangle : LeastAreaDisc(loop)) {
    int longest = 0;
    for (int k = 1; k < 3; ++k) {
      const double side = (loop[triangle[(k + 1) % 3]] - loop[triangle[k]]).squaredNorm();
      if (side > (loop[triangle[(longest + 1) % 3]] - loop[triangle[longest]]).squaredNorm()) {
        longest = k;
      }
    }
    const Eigen::Vector3d& a = loop[triangle[longest]];
    const Eigen::Vector3d& b = loop[triangle[(longest + 1) % 3]];
    const Eigen::Vector3d& c = loop[triangle[(longest + 2) % 3]];
    const double base = (b - a).norm();
    const double height = base > 0 ? (b - a).cross(c - a).norm() / base : 0.0;
    const int rows = std::max(1, static_cast<int>(std::ceil(height / step)));
    for (int r = 0; r <= rows; ++r) {
      const double t = static_cast<double>(r) / rows;
      const Eigen::Vector3d p = a + t * (c - a), q = b + t * (c - b);
      const int samples = static_cast<int>(std::ceil((q - p).norm() / step));
      for (int s = 0; s <= samples; ++s) {
        const double u = samples > 0 ? static_cast<double>(s) / samples : 0.0;
        const Eigen::Vector3d x = p + u * (q - p);
        double free = DistanceToLoop(loop, x);
        if (clearance && free > radius) free = std::min(free, clearance(x));
        radius = std::max(radius, free);
        if (2.0 * (radius + slack) > stop) return 2.0 * (radius + slack);
      }
    }
  }
  return 2.0 * (radius + slack);
}

}  // namespace meshseg::reconstruct_internal
