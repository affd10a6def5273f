// The answer key of a generated part: which primitive each vertex and face
// lies on, and which faces lie near a boundary between primitives.
#ifndef MESHSEG_GENERATE_GROUND_TRUTH_H_
#define MESHSEG_GENERATE_GROUND_TRUTH_H_

#include <cstdint>
#include <vector>

#include "generate/csg.h"
#include "generate/marching_cubes.h"
#include "meshseg/generate.h"

namespace meshseg::generate_internal {

// Per vertex: the primitive of its active leaf; where that leaf is auxiliary
// (only on tangent lines), the primitive whose leaf is nearest.
std::vector<int> VertexPrimitives(const Csg& solid, const RawSurface& surface);

// Per triangle: among the primitives of its corners, the one whose surface is
// nearest to the centroid; -1 if that is farther than h.
std::vector<int> FacePrimitives(const RawSurface& surface, const std::vector<int>& vertex_primitive,
                                const std::vector<PrimitiveTruth>& primitives, double h);

// Per triangle: 1 if a corner lies within geodesic distance h (along mesh
// edges) of a triangle whose corners lie on different primitives.
std::vector<uint8_t> NearBoundary(const RawSurface& surface, const std::vector<int>& vertex_primitive,
                                  double h);

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_GROUND_TRUTH_H_
