// Planes of a binary-occupancy surface fitted by the samples the binary data
// consist of, not by the marching-cubes vertices between them.
//
// A binary volume says, for every grid edge the surface crosses, only that
// one end is material and the other air. The vertices (edge midpoints) lie
// up to half a voxel off a slanted plane in a quasi-periodic staircase, and
// a least-squares plane through them keeps the part of that pattern that a
// small face does not average out (a disc ~8 voxels in radius tilted 11
// degrees: 0.35 degrees off). The planes consistent with the data are those
// with every material sample on one side and every air sample on the other
// (digital plane recognition, Reveilles 1991): their normals converge like
// 1/N^2 in the face's extent N voxels, not like the staircase's average.
// This takes the one of them farthest from every sample (the maximal-margin
// separator, the centre of the consistent set).
#ifndef MESHSEG_PIPELINE_SEPARATING_PLANES_H_
#define MESHSEG_PIPELINE_SEPARATING_PLANES_H_

#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {

// The maximal-margin plane separating `inside` (material samples) from
// `outside` (air samples), searched from `start` (a plane whose normal points
// to the air, up to sign); nullopt when no plane within kMaxTurnDeg of
// `start` separates them (noise, or samples of another surface).
struct SeparatingPlane {
  Plane plane;
  double margin = 0.0;  // distance from the plane to the nearest sample
};
inline constexpr double kMaxTurnDeg = 5.0;
std::optional<SeparatingPlane> MaxMarginPlane(std::span<const Eigen::Vector3d> inside,
                                              std::span<const Eigen::Vector3d> outside,
                                              const Plane& start);

// Per vertex of `mesh`: the region whose label all faces around the vertex
// and around its neighbours carry (two rings inside the region), else -1.
std::vector<int> InteriorRegionOfVertex(const TriMesh& mesh, std::span<const int> face_labels);

// Refits every plane region of a binary-occupancy `mesh` (labels one per
// face) as the MaxMarginPlane of the samples of its interior vertices (those
// whose faces, and their neighbours' faces, all carry the region's label: a
// vertex on the rim may belong to the neighbour's crossing). A region keeps
// its least-squares plane when the samples cannot be separated. rms / max
// distances are then those of the region's vertices.
void RefitPlanesBySeparation(const TriMesh& mesh, std::span<const int> face_labels,
                             const BinaryVertices& binary, std::vector<Region>* regions);

}  // namespace meshseg::pipeline_internal

#endif  // MESHSEG_PIPELINE_SEPARATING_PLANES_H_
