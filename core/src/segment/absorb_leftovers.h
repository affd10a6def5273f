// Leftover absorption of ALGORITHMS.md S2 (STB3): free vertices (mostly
// near sharp edges) join a neighbouring region whose surface they meet with
// thresholds stepped up from the base ones; what is still free then joins
// its nearest labelled neighbour, and free islands without any region become
// regions.
#ifndef MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_
#define MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_

#include <vector>

#include "absl/status/status.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// Small general-quadric regions are mostly strips grown from seeds next to
// sharp edges; they are released (labels -1, alive = false) before
// absorption so the surfaces on either side take their vertices.
inline constexpr std::size_t kMinQuadricVertices = 60;
inline constexpr double kMinQuadricShare = 0.002;  // of all vertices
void ReleaseSmallQuadrics(const SegmentContext& c, std::vector<int>* labels,
                          std::vector<RegionState>* regions);

// After merging, regions of any type still this small are fragments grown
// from seeds on noisy rims (at high noise no neighbour's surface fits their
// bent normals well enough to merge them); they are released like the small
// quadrics and absorbed again. 60 vertices, as for quadrics: about 120 faces,
// below the 200-face primitives the segmentation must find. (A floor of 30
// let a 47-vertex cone survive on the 90-degree rim between a cylinder of
// r 15 and its plane bottom, at sigma = 0.15 h, and the boundary refinement
// then grew it to 148 on the rim's bent normals.)
// A small face stays: a plane of kMinInteriorVertices (retype_by_interior.h)
// vertices, flat (their rms distance to it at most twice the noise, or
// exact), that lies on no neighbour (fewer than a third of its vertices
// meet the surface of a region beside it within twice the base thresholds,
// the first leftover step). It is a face across a crease, and the region
// that absorbed it would bend (a small plane disc on top of a conical
// frustum, meshed at 1.5 times the part's voxel size without noise: 41
// vertices, none on the cone, which took them and became a sphere). A
// fragment on a rounded rim is not flat.
inline constexpr std::size_t kMinRegionVertices = kMinQuadricVertices;
inline constexpr double kMinRegionShare = 0.001;  // of all vertices
// Returns the number of regions released.
int ReleaseSmallRegions(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions);

// Releases (labels -1, alive = false), like the small regions above, every
// plane region with fewer than kMinInteriorVertices (retype_by_interior.h)
// interior vertices that is not a small face (above).
// A plane fits any strip of a curved face that narrow within the noise, and
// no later step can tell: RetypeByInterior and MergeSameSurface judge a
// region by its interior, which such a strip hardly has (a strip along a
// small round can keep a plane to the end while nearly all of its vertices
// meet the neighbour's surface). A narrow face across a crease
// is flat and lies on no neighbour's surface: released, it goes to a
// neighbour it does not fit, which may then bend toward it (a cone taking a
// narrow flat rim tilts its half-angle by several degrees). Curved regions
// that narrow stay: their type carries their curvature (a small corner blend
// fitted as a sphere of about a hundred vertices is one).
// Returns how many.
int ReleaseNarrowPlanes(const SegmentContext& c, std::vector<int>* labels,
                        std::vector<RegionState>* regions);

// Labels every vertex that has a face (labels[v] >= 0 afterwards) and
// updates the regions' vertex lists. Errors: CANCELLED on stop.
absl::Status AbsorbLeftovers(const SegmentContext& c, std::vector<int>* labels,
                             std::vector<RegionState>* regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_ABSORB_LEFTOVERS_H_
