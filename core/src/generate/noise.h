// Scanner noise: Gaussian displacement of vertices along their normals.
#ifndef MESHSEG_GENERATE_NOISE_H_
#define MESHSEG_GENERATE_NOISE_H_

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace meshseg::generate_internal {

// Moves vertices[v] by N(0, sigma^2) along normals[v] (unit), drawing in
// vertex order from a generator seeded with `seed`: same seed, same result.
void AddNormalNoise(std::vector<Eigen::Vector3d>& vertices,
                    const std::vector<Eigen::Vector3d>& normals, double sigma, uint64_t seed);

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_NOISE_H_
