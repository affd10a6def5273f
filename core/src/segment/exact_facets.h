// Segmentation of coarse exact meshes (our addition for CAD exports such as
// ABC's abc_00007974_5.obj): every vertex lies on its surface to rounding
// error, but a cylinder of radius 0.5–2 is tessellated with edges of 1.4, so
// 37 % of the vertices are sharp and no curvature seed starts on a curved
// face. Seeds 000 and 002 assume a dense scan; here the exactness is used
// instead:
//  1. faces are grouped into exact planes (every vertex within the tolerance
//     of the seed face's plane), which also splits each curved face into its
//     flat facets (a quad between two rulings of a cylinder is planar);
//  2. chains of at least kMinFacets facets meeting at less than
//     kMaxFacetAngleDeg are fitted with cylinder, cone, sphere and torus; the
//     first one that every facet corner meets exactly grows over the
//     neighbouring facets that meet it too, refitted as it grows. (Only the
//     corners of a facet's outline must be exact: a tessellator adds vertices
//     on a facet's edges to meet the next face, under the arc on a chord.)
//     Cylinder and cone seeds whose facets step evenly around the axis are
//     taken in a first pass (kMaxEvenStepRatio), all others in a second;
//  3. the facets left are planes.
// The pipeline also takes this path for CAD exports too fine to remesh
// (remesh.h, SegmentParams::exact_facets), such as tray_bottom_1002.stl, a
// plate 3.175 thick with holes of radius 1.13 to 4.56.
#ifndef MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_
#define MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_

#include <vector>

#include "absl/status/statusor.h"
#include "meshseg/curvature.h"
#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "segment/segment_internal.h"

namespace meshseg::segment_internal {

// A mesh is exact when the estimated noise is below this fraction of l_avg
// (CAD exports and noise-free generated parts: 0 to 1e-15 l_avg; the
// cleanest scan in shared/data, fandisk, 2.5e-4).
inline constexpr double kExactNoise = 1e-9;
// ... and coarse when this share of its vertices is sharp (abc_00007974_5:
// 0.37; the generated parts 0.02–0.15; fandisk 0.18).
inline constexpr double kCoarseSharpShare = 0.3;
// Distance within which a vertex lies on a surface, in l_avg.
inline constexpr double kExactTolerance = 1e-4;
// Facets of one curved face meet at less than this; the faces of a part
// mostly meet at 90°. A regular prism with more than 6 sides is a
// tessellated cylinder to this test, as it is to the eye.
inline constexpr double kMaxFacetAngleDeg = 60.0;
// A facet whose vertices all lie on a curved surface is one of its facets
// if its normal is within this of the surface normal at each vertex (half
// the arc it spans, under 90°); the flat bottom of a half round, a chord
// across it, is at 90°.
inline constexpr double kMaxChordAngleDeg = 80.0;
// A facet's vertices between its corners (on its straight edges) lie on
// its surface or under it on a chord by at most this, in l_avg: the
// tessellator's chordal deviation (tray_bottom_1002.stl: 0.0097, 9e-4 l_avg,
// under 10-degree facets of small holes), far less than the cut of a flat
// face across a cylinder (abc_00007974_5.obj: 1.2 l_avg).
inline constexpr double kMaxSagitta = 0.01;
// A curved region holds at least this many facets: three parallel lines lie
// on a cylinder whatever they are, four do not. (A curved face tessellated
// with two facets is two planes to us: nothing tells it from a crease.)
inline constexpr int kMinFacets = 3;
// A tessellator steps an arc evenly: seeds whose facets span angles around
// the axis within this ratio of each other are tried first (measured: 1.000
// to 1.001 on tray_bottom_1002.stl; single-triangle CAD fans 1.5 to 6).
inline constexpr double kMaxEvenStepRatio = 1.2;
// Seed sets with more vertices than this hold a large plane and are not fitted.
inline constexpr std::size_t kMaxSeedVertices = 200;
// A curved region is grown and refitted at most this many times.
inline constexpr int kMaxGrowRounds = 4;

// True if `estimates` and `curvature` say the mesh is coarse and exact.
bool IsCoarseExact(const CurvatureField& curvature, const SegmentEstimates& estimates);

struct FaceRegions {
  std::vector<int> face_labels;      // one per face, into `regions`
  std::vector<RegionState> regions;  // vertices: the corners of the region's facets
};

// Segments `mesh` (the mesh of `c`) face by face as above.
// Errors: CANCELLED on stop.
absl::StatusOr<FaceRegions> SegmentExactFacets(const SegmentContext& c, const TriMesh& mesh);

// An exact tessellation has at least this share of its faces in curved
// regions or in planes of more than one face. On a noisy mesh no two
// triangles are coplanar to kExactTolerance and no chain of them fits a
// surface exactly: nearly every face is a plane of its own.
inline constexpr double kMinExactShare = 0.5;

// OK if `regions` (SegmentExactFacets of `mesh`) say the mesh is exact;
// else FAILED_PRECONDITION naming the mesh and the share.
absl::Status ExpectExactTessellation(const Mesh& mesh, const FaceRegions& regions);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_EXACT_FACETS_H_
