// Where the points say nothing, the surface is closed minimally: the
// vertices far from every point are placed where the membrane energy
// Σ |x_v − x_w|² over the edges is least, the others held fixed (a discrete
// harmonic surface spanning the supported rim; for a planar rim, the plane).
// Seed 001 §2.3 smooths such vertices (bi-Laplacian); the membrane is the
// least-area choice issue 38 asks for, and is solved exactly rather than by
// a number of smoothing steps that would depend on the size of the gap.
#ifndef MESHSEG_RECONSTRUCT_FAIR_UNSUPPORTED_H_
#define MESHSEG_RECONSTRUCT_FAIR_UNSUPPORTED_H_

#include <cstdint>
#include <vector>

#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// Moves the vertices with `free[v]` set to the minimum of the membrane energy
// with the other vertices fixed (uniform graph Laplacian, conjugate
// gradients). A connected set of free vertices with no fixed neighbour stays
// where it is. Returns the number of vertices moved.
int64_t FairFreeVertices(const std::vector<uint8_t>& free, TriMesh* mesh);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_FAIR_UNSUPPORTED_H_
