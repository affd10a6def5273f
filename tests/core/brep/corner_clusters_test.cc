// ClusterCorners: a junction-artifact curve that leaves one of its surfaces
// is a label zig-zag, contracted with its corners into one vertex; one whose
// every vertex lies on both its surfaces is a real edge, however short, and
// its corners stay apart.
#include "brep/corner_clusters.h"

#include <Geom_Plane.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gtest/gtest.h>

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

// Planes z = 0 (region 0) and x = 0 (region 1), meeting on the y axis. Two
// curves the topology marked junction artifacts, each between two corners of
// its own cluster: curve 0 runs along the y axis; curve 1 from the axis to a
// point 0.3 off the plane x = 0.
struct TwoArtifacts {
  TriMesh mesh;
  Topology topology;
  std::vector<Handle(Geom_Surface)> surfaces;

  TwoArtifacts() {
    for (const Vector3d& p : {Vector3d(0, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 5, 0),
                              Vector3d(0.3, 5.4, 0)}) {
      mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z()));
    }
    surfaces = {new Geom_Plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)),
                new Geom_Plane(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))};
    for (int k = 0; k < 2; ++k) {
      BoundaryCurve c;
      c.id = k;
      c.vertices = {2 * k, 2 * k + 1};
      c.left_region = 0;
      c.right_region = 1;
      c.start_corner = 2 * k;
      c.end_corner = 2 * k + 1;
      c.junction_artifact = true;
      topology.curves.push_back(c);
    }
    for (int k = 0; k < 4; ++k) {
      Corner c;
      c.id = k;
      c.vertex = k;
      c.cluster = k < 2 ? 0 : 2;
      c.position = Vector3d(0.1, k < 2 ? 0.5 : 5.2, 0.1);  // the cluster's mean, snapped or not
      c.regions = {0, 1};
      topology.corners.push_back(c);
    }
  }
};

TEST(ClusterCorners, ACurveOnBothSurfacesIsAnEdgeAndItsCornersStayApart) {
  const TwoArtifacts input;
  const CornerClusters clusters =
      ClusterCorners(input.mesh, input.topology, input.surfaces, 1e-6);
  ASSERT_EQ(clusters.cluster.size(), 4u);
  EXPECT_EQ(clusters.artifact[0], 0);
  EXPECT_EQ(clusters.cluster[0], 0);
  EXPECT_EQ(clusters.cluster[1], 1);
  // A cluster the topology did not have starts at its corners' mesh vertex.
  EXPECT_EQ(clusters.start.at(0), Vector3d(0, 0, 0));
  EXPECT_EQ(clusters.start.at(1), Vector3d(0, 1, 0));
  EXPECT_EQ(clusters.regions.at(1), (std::vector<int>{0, 1}));
}

TEST(ClusterCorners, ACurveOffASurfaceIsContractedWithItsCorners) {
  const TwoArtifacts input;
  const CornerClusters clusters =
      ClusterCorners(input.mesh, input.topology, input.surfaces, 1e-6);
  EXPECT_EQ(clusters.artifact[1], 1);
  EXPECT_EQ(clusters.cluster[2], 2);
  EXPECT_EQ(clusters.cluster[3], 2);
  EXPECT_EQ(clusters.start.count(3), 0u);
  // The topology's cluster, unchanged, keeps its position.
  EXPECT_EQ(clusters.start.at(2), Vector3d(0.1, 5.2, 0.1));
}

TEST(ClusterCorners, AWiderSurfaceOffsetTakesTheCurveOnBothSurfaces) {
  const TwoArtifacts input;
  const CornerClusters clusters = ClusterCorners(input.mesh, input.topology, input.surfaces, 0.5);
  EXPECT_EQ(clusters.artifact[1], 0);
  EXPECT_NE(clusters.cluster[2], clusters.cluster[3]);
}

}  // namespace
}  // namespace meshseg::brep_internal
