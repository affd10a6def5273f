// The type decision of seed 000 §3 steps 3 and 5: the first analytic type
// whose fit meets (5) and (6) at more than alpha of the region's vertices.
#ifndef MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_
#define MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_

#include <optional>
#include <span>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

struct TypedFit {
  SurfaceType type = SurfaceType::kQuadric;
  FitResult fit;
  double fraction = 0.0;  // of the vertices meeting (5) and (6)
};

// Returns the plane fit of `vertices` if it passes the alpha test.
std::optional<TypedFit> PlaneIfFits(const SegmentContext& c, std::span<const int> vertices,
                                    const Tolerance& tol);

// Returns the first of cylinder, sphere, cone, torus passing the alpha test
// (the cone replacing the cylinder only when clearly more accurate); if none
// passes, the one with the largest fitting fraction (earlier types winning
// near-ties), or the general quadric if no analytic type fits any vertex.
TypedFit DecideCurvedType(const SegmentContext& c, std::span<const int> vertices,
                          const Tolerance& tol);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_DECIDE_TYPE_H_
