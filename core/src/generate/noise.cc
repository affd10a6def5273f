#include "generate/noise.h"

#include <cassert>
#include <random>

namespace meshseg::generate_internal {

void AddNormalNoise(std::vector<Eigen::Vector3d>& vertices,
                    const std::vector<Eigen::Vector3d>& normals, double sigma, uint64_t seed) {
  assert(vertices.size() == normals.size() && "one normal per vertex");
  if (sigma <= 0.0) return;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  for (size_t v = 0; v < vertices.size(); ++v) vertices[v] += gauss(rng) * normals[v];
}

}  // namespace meshseg::generate_internal
