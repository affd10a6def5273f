// The surface-type decision on a scan region's points away from its
// boundary.
#ifndef MESHSEG_PIPELINE_INNER_POINTS_H_
#define MESHSEG_PIPELINE_INNER_POINTS_H_

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::pipeline_internal {

// The reconstruction rounds every crease over about one point spacing h,
// and the segmentation puts the boundary between two regions somewhere on
// that rounded band, or beyond it: a region typed more general than its
// surface bends toward its neighbours and grows into them (a torus on a
// 45-degree chamfer follows the cylinder below it and the plane above it).
// A point whose nearest face lies near a region boundary may belong to
// either surface, and is ambiguous evidence of the region's type: on a
// narrow region such points are a large share, and when the neighbours
// beyond both edges bend the same way they decide it (the chamfer's points
// with those crease bands are followed better by a torus than by its cone).
// So the type is decided on the points whose nearest mesh vertex lies at
// least this many spacings from a region boundary (along the mesh's edges).
// Measured on simulated scans (5 generated parts, 2 draws each, 40K
// points), of the points a region holds from its neighbours along its
// boundary (whole areas in a wrong region, 6 h and more inside, left out):
// 98 % lie within 2 h of the boundary, 99.5 % within 3 h; most of those
// beyond 2 h are in a torus region on a chamfer.
inline constexpr double kAmbiguousSpacings = 3.0;

// A type decided on the inner points must explain the region's band points
// but this share, the others lying on a neighbour's surface (within the
// band): the band is 3 sigma wide or more, which holds all but 0.3 % of a
// surface's points.
inline constexpr double kMaxUnexplainedShare = 0.05;

struct InnerPointParams {
  double spacing = 0.0;             // h, the cloud's median point spacing
  double noise = 0.0;               // sigma of the cloud's points about the surface
  double band = 0.0;                // a region's own points lie this close to its surface
  double distance_tolerance = 0.0;  // th_dis, as RefitToPoints takes it
};

// The type decision of RetypeToPoints, first on each region's band points
// (`points_of_region`: those whose nearest face it holds, within params.band
// of its surface), then, to a curved type only, on its inner points: those
// of its band points whose nearest vertex lies at least kAmbiguousSpacings *
// spacing from a region boundary of `face_labels` (after the own type's
// refit on them, RefitToPoints). A plane is not decided on inner points: it
// fits any narrow enough strip of a curved face within the noise, and the
// inner points of a narrow region are such a strip. A region with fewer
// inner points than kMinRetypePoints is decided on its band points only. A
// region that keeps its type keeps its surface; one that takes another
// type on its inner points is refitted on every point of its nearest faces
// within params.band of the new surface (the ambiguous points it keeps).
// Regions go by id: `points_of_region` has one list per id, and
// `nearest_label` and `nearest_vertex` one entry per point of `cloud`, as
// PointLabels returns them. Returns how many regions changed type.
int RetypeOnInnerPoints(const TriMesh& mesh, std::span<const int> face_labels,
                        std::span<const Eigen::Vector3d> cloud,
                        std::span<const int> nearest_label,
                        std::span<const uint32_t> nearest_vertex, const InnerPointParams& params,
                        std::span<const std::vector<Eigen::Vector3d>> points_of_region,
                        std::vector<Region>* regions, std::vector<SharedSurface>* surfaces);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_INNER_POINTS_H_
