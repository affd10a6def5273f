// The mesh data of each region the B-rep needs: its vertices (to frame and
// fit its surface) and a sample of its faces (to tell which side of the
// surface is outside).
#ifndef MESHSEG_SRC_BREP_REGION_SAMPLES_H_
#define MESHSEG_SRC_BREP_REGION_SAMPLES_H_

#include <span>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"

namespace meshseg::brep_internal {

struct RegionSamples {
  std::vector<Eigen::Vector3d> points;  // each vertex of the region's faces once
  // Up to kMaxFaceSamples faces spread over the region: centroid and unit
  // normal (the mesh's, pointing out of the solid).
  std::vector<Eigen::Vector3d> face_centroids;
  std::vector<Eigen::Vector3d> face_normals;
};

inline constexpr int kMaxFaceSamples = 64;

// Returns one RegionSamples per region id in [0, region_count).
std::vector<RegionSamples> SampleRegions(const TriMesh& mesh, std::span<const int> face_labels,
                                         int region_count);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_REGION_SAMPLES_H_
