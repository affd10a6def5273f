// Selective bi-Laplacian smoothing of the reconstructed surface. Seed 001 §2.3
// (Kobbelt et al. 1998; Taubin 1995).
#ifndef MESHSEG_RECONSTRUCT_SMOOTHING_H_
#define MESHSEG_RECONSTRUCT_SMOOTHING_H_

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace meshseg::reconstruct_internal {

// Moves the vertices with `selected` set, `iterations` times by
// v ← v + λU then v ← v − λU' (U the umbrella vector: the mean of the
// neighbours weighted by 1 / edge length (edges under 0.05 of the mean length
// weigh as if that long), minus v; Fujiwara 1995, as
// Desbrun et al. 1999 for irregular meshes); the other vertices stay where
// they are.
void SmoothSelected(const std::vector<std::array<int, 3>>& triangles,
                    const std::vector<uint8_t>& selected, double lambda, int iterations,
                    std::vector<Eigen::Vector3d>* vertices);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_SMOOTHING_H_
