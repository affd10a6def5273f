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
#include "reconstruct/pu_function.h"
#include "reconstruct/regular_triangulation.h"

namespace meshseg::reconstruct_internal {

// Returns supports covering every leaf: in an order drawn from `seed`, each
// leaf centre not yet covered gets a support (FitSupport with the lower bound
// 0.75 × its cell diagonal), which covers the leaves whose 8 corners it
// contains. Errors: CANCELLED when ctx requests a stop.
absl::StatusOr<std::vector<Support>> CoverBySupports(const std::vector<OctreeLeaf>& leaves,
                                                     const FitInput& in, uint64_t seed,
                                                     const RunContext& ctx);

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
// (|g(c)| < r), holds that plane sampled over at least a quarter of its
// disc (point_count ≥ π (r² − g(c)²) / (4 spacing²): a ball centred at a
// right-angled corner of its sampled face holds a quarter; a small flat
// clump of stray points in a ball grown past it, a ghost sheet with no
// solid behind it, holds less) and whose centre's foot on it lies on its
// sampled part (the foot's nearest input point is in the ball; a foot on
// the plane run on past the ball's points, as below a wall from a support
// in the empty space under an unseen face, reads nothing) gives the point a
// radius inside that plane, along m from the foot. Returns one support
// fitted there (FitSupport with no lower bound) per such support, in their
// order; the fit gives it the point count that marks it sparse or not for
// the labels (graph_cut.h).
//
// They are tet vertices that sample f and no terms of it (the caller builds
// f from the covering alone): a fit grown to the parent's points reproduces
// the parent's plane, so as a term it put its own centre inside by
// construction (measured: bubbles around clumps of stray points grown past
// the small-component drop). For a centre on its plane the point lies on
// the parent's sphere, where the parent's weight in f is b2(3/2) = 0: f
// there is what the other supports read.
std::vector<Support> InnerSupports(const std::vector<Support>& supports, const FitInput& in,
                                   double spacing);

// The weight of each covering support as a vertex of the regular
// triangulation (ALGORITHMS.md S3 step 4): r², except 0 for a centre on the
// hull of `tets` (its first triangulation) where f > 0 (our addition, issue
// 38). The labels tie every hull vertex outside, so that the surface closes
// (graph_cut.h); there f and the tie disagree: the ball was grown in the
// empty space beyond an unseen face until it reached the points, and the
// fits there read its centre inside. With weight r² its power cell,
// labelled outside, takes in the solid its ball reaches (the power of a
// point p is |p − c|² − r², negative throughout the ball): it hides the
// centres and inner supports there, the tets join the seen face's vertices
// straight to it, and the surface closes a cell under the seen face, a
// hollow whether the draw of the covering (its order) grows such a ball or
// not. An extreme point of the set is a vertex at any weight, so with
// weight 0 the centre still closes the hull, tied outside, and hides no
// vertex (its power is ≥ 0 everywhere, no weight is negative).
//
// Only a support holding at least `sparse_points` input points (the sparse
// count, ReconstructParams::sparse_support_points) can disagree with the
// tie: as in the labels (graph_cut.h ResolvedInside), a fit on fewer points
// does not read which side its centre is on. Such a ball was grown in empty
// space until it held the fit's minimum (kMinFitPoints), a handful of points
// at its rim, one to several radii from the centre; its plane through them
// tilts by about the noise over their spread (on a real scanner's depth
// noise, tens of degrees), so the sign it extrapolates to the centre, tens of
// spacings away, is the noise's draw. Read as inside there, weight 0 freed
// the empty space in front of a seen face to the fits extrapolated the same
// way: a sheet beyond the face, with no points, that the support step
// removes and closes across (measured on a real scan: a hull centre beyond a
// seen face, r ≈ 20-40 spacings, 6 points, f = 13-28 spacings).
//
// The fit's plane is not the only reading of the side, though: each point
// carries its own normal, estimated from its own neighbourhood in the cloud
// (normals.h), which does not tilt with the handful of points the ball
// holds. A point stands for solid behind its tangent plane (the dual of
// graph_cut.h SeenFromOutside). So a sparse hull ball whose every point
// sees its centre from inside has its side read by the points themselves,
// independently of the fit: (c − p) · n_p > ε with n_p the point's inward
// normal, and the centre within 60° of n_p, so that a normal off by up to
// 30° (a noisy estimate, a point near an edge) still puts it on the same
// side; a centre nearly in some point's tangent plane is read by that
// point's noise. Such a ball grew in the empty space behind a plate's
// unseen far face until it reached the seen near face through the solid,
// whose points all face away from it. It gets weight 0 as a supported ball
// does; with r² its power cell takes in the plate's solid and the surface
// closes just under the seen face: a second sheet there, and the patch
// over the unseen face climbs to it through the solid (measured on a
// generated plate 8 thick scanned from above: centres 44-53 spacings under
// it, 6 points, f = 32-39 spacings, every point's normal within 48-57° of
// the centre). A ball in front of a seen face holds points whose normals
// face it and keeps r² (on the real scan above, 7 of the 8 centres have a
// point seeing them from outside; the eighth's points all see it from
// inside, one at 80° from its normal: r² as before). `in` gives the
// points, their normals and ε.
std::vector<double> CoveringWeights(const std::vector<Support>& covering, const TetMesh& tets,
                                    const PuFunction& f, int sparse_points, const FitInput& in);

// The weight of each of `supports` as a vertex of the regular triangulation:
// `covering_weight` for the covering (the first covering_weight.size()), and
// for each Steiner vertex after them (the inner supports) a weight that makes
// it a vertex without hiding any covering centre, or −1 (not a vertex) where
// no weight does both. A weighted point p lies in its own power cell when
// w ≥ w_i − |p − c_i|² for every covering centre i, and leaves centre c_j in
// its own when w < w_j + |p − c_j|²; the weight is the middle of that
// interval. A Steiner vertex so adds a sample of f and removes none. (With
// its fitted ball's weight r_in² it hid the covering's centres on both faces
// of a plate thinner than that ball, leaving no inside vertex there:
// through-holes in the surface.)
std::vector<double> TetWeights(const std::vector<Support>& supports,
                               const std::vector<double>& covering_weight);

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_COVER_H_
