// Crease bands (our addition to ALGORITHMS.md S1 and S2): where two surfaces
// meet at a crease the sharp test misses (45 degrees at sigma = 0.15 h),
// n'_i turns across the crease, so the vertices there meet test (6) for
// neither side and can form a region of their own: a torus of tube radius
// 2 h along the crease between a shaft's cylinder and a 45-degree cone.
// Their distances still say where they belong.
#ifndef MESHSEG_SRC_SEGMENT_DISSOLVE_CREASE_BANDS_H_
#define MESHSEG_SRC_SEGMENT_DISSOLVE_CREASE_BANDS_H_

#include <vector>

#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Dissolves every curved region of which more than alpha of the vertices,
// or at least as many as lie within th_dis of its own surface, lie within
// th_dis (test (5) alone) of the surface of a neighbouring region (one an
// edge leads to), and whose distances to the nearest of those surfaces are
// no larger (root mean square) than to its own or meet the noise
// (ModelErrorOfMeanSquare under kMinModelError sigma), into those
// neighbours: each vertex goes to the one it is nearest. (The second share:
// a quadric over a crease at sigma = 0.15 h had 89.7 % of its vertices near
// its neighbours and 85.9 % near itself, and fitted them worse. The noise: a
// torus band three rows wide along a crease at sigma = 0.15 h fitted its
// noise, sum of squares 0.52 against its neighbours' 0.66 and n sigma^2
// 0.70.) A true fillet is not dissolved: the middle of its arc lies
// r (1 - cos(theta / 2)) off both tangent surfaces, which its own surface
// fits better (on an exact CAD remesh, corner tori fit to 1e-5, while their
// neighbours, a plane, a cylinder and a sphere, pass within th_dis of 90 %
// of them).
// Regions are taken in id order, each against the labels left by the ones
// before; the regions that grew are refitted. Returns the number dissolved.
int DissolveCreaseBands(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_DISSOLVE_CREASE_BANDS_H_
