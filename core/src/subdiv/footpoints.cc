#include "subdiv/footpoints.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/point_index.h"

namespace meshseg::subdiv_internal {
Eigen::Vector3d ClosestBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

std::vector<FootPoint> FootPoints(const std::vector<Eigen::Vector3d>& vertices,
                                  const std::vector<std::array<int, 3>>& faces,
                                  const std::vector<Eigen::Vector3d>& data, int candidates) {
  // Faces around each vertex, as offsets into one array (CSR).
  std::vector<int> start(vertices.size() + 1, 0);
  for (const auto& f : faces) {
    for (int v : f) ++start[v + 1];
  }
  for (size_t v = 0; v < vertices.size(); ++v) start[v + 1] += start[v];
  std::vector<int> incident(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int v : faces[f]) incident[fill[v]++] = static_cast<int>(f);
  }
  const mesh_internal::PointIndex index(vertices);
  const int k = std::max(1, candidates);
  std::vector<FootPoint> out(data.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, data.size()), [&](const auto& range) {
    std::vector<uint32_t> nearest;
    std::vector<double> d2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const Eigen::Vector3d& p = data[i];
      index.Nearest(p, k, &nearest, &d2);
      double best = std::numeric_limits<double>::infinity();
      for (size_t j = 0; j < nearest.size(); ++j) {
        for (int s = start[nearest[j]]; s < start[nearest[j] + 1]; ++s) {
          const int f = incident[s];
          const auto& t = faces[f];
          const Eigen::Vector3d w =
              ClosestBarycentric(p, vertices[t[0]], vertices[t[1]], vertices[t[2]]);
          const Eigen::Vector3d q =
              w[0] * vertices[t[0]] + w[1] * vertices[t[1]] + w[2] * vertices[t[2]];
          const double dist = (q - p).squaredNorm();
          if (dist < best) {
            best = dist;
            out[i] = {f, w, 0.0};
          }
        }
      }
      out[i].distance = std::sqrt(best);
    }
  });
  return out;
}

}  // namespace meshseg::subdiv_internal
