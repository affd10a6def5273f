// The random covering of the octree's cube by support balls. Seed 001
// §2.1.2 steps (2)-(3).
#ifndef MESHSEG_RECONSTRUCT_COVER_H_
#define MESHSEG_RECONSTRUCT_COVER_H_

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/run_context.h"
#include "reconstruct/local_fit.h"
#include "reconstruct/octree.h"

namespace meshseg::reconstruct_internal {

// Returns supports covering every leaf: in an order drawn from `seed`, each
// leaf centre not yet covered gets a support (FitSupport with the lower bound
// 0.75 × its cell diagonal), which covers the leaves whose 8 corners it
// contains; then the inner supports below (at most one per support, after
// them). Errors: CANCELLED when ctx requests a stop.
//
// Inner supports (our addition to ALGORITHMS.md S3 step 3). Marching
// tetrahedra (step 6) puts the surface only on tet edges between an inside
// and an outside vertex, so the tets find a solid only where their vertices
// sample its inside. The covering gives one vertex per support, at the
// centre of a leaf next to the points, and the regular triangulation (step
// 4, weights r²) hides every centre inside a larger ball. On a plane the
// balls grow to about 15 spacings, so under a large flat support the solid
// has no vertex deeper than a few cells: the tets there join the vertices
// along the seen face to ones beyond the solid (the hull, outside). The
// surface then closes a few cells under the seen face, a cavity whose ceiling the
// refinement pulls onto the points (a second sheet on them, facing in);
// where the far side is unseen, the patch that closes it runs through the
// solid up to that ceiling.
//
// A support's ball reads the inside of its sheet as deep as its radius, and
// only where its points are. So each support whose ball holds its plane
// (|g(c)| < r) and whose centre's foot on it lies on its sampled part (the
// foot's nearest input point is in the ball; a foot on the plane run on past
// the ball's points, as below a wall from a support in the empty space
// under an unseen face, reads nothing) adds the support fitted at the point
// a radius inside that plane, along m from the foot (FitSupport with no
// lower bound: its ball grows to its points). For a centre on its plane
// that point lies on the ball's sphere: the ball does not hide it (the
// point's power to the ball is 0, its own weight's is −r_in² < 0) and gives
// it no weight in f (b2(3/2) = 0). So f there is what the other supports
// and its own fit read, and it is a tet vertex on the inside in a solid at
// least that thick, on the outside beyond the far face of a thinner one.
// (At half a radius the ball hid it wherever the inner ball came out small,
// beside a thin wall.)
absl::StatusOr<std::vector<Support>> CoverBySupports(const std::vector<OctreeLeaf>& leaves,
                                                     const FitInput& in, uint64_t seed,
                                                     const RunContext& ctx);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_COVER_H_
