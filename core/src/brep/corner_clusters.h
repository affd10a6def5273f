// Which corners of the topology are one B-rep vertex. The topology stage
// joins the corners at the ends of a short curve into a cluster (a junction
// artifact: labels zig-zagging where three regions meet, contracted into a
// vertex). A zig-zag crosses the edge it stands for, so its mesh vertices
// leave at least one of its two surfaces; a curve whose every vertex lies on
// both its surfaces (within the surface offset) runs along their
// intersection: a real edge, however short, as a coarse CAD tessellation
// gives (a few long triangles make l_avg, and so "short", large).
#ifndef MESHSEG_SRC_BREP_CORNER_CLUSTERS_H_
#define MESHSEG_SRC_BREP_CORNER_CLUSTERS_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/mesh.h"
#include "meshseg/topology.h"

#include <map>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Geom_Surface.hxx>

namespace meshseg::brep_internal {

struct CornerClusters {
  std::vector<int> cluster;  // per corner id: its cluster, named by its smallest corner id
  // Per curve id: a junction artifact contracted into its cluster's vertex.
  std::vector<char> artifact;
  // Per cluster: where its vertex search starts (the topology's position for
  // an unchanged cluster, else the mean of its corners' mesh vertices) and
  // the regions around it (>= 0).
  std::map<int, Eigen::Vector3d> start;
  std::map<int, std::vector<int>> regions;
};

// Returns the clusters of `topology`'s corners, keeping as edges the
// junction-artifact curves whose mesh vertices lie within `on_surface` of
// both their regions' `surfaces` (per region id; null = no surface).
CornerClusters ClusterCorners(const TriMesh& mesh, const Topology& topology,
                              std::span<const Handle(Geom_Surface)> surfaces, double on_surface);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_CORNER_CLUSTERS_H_
