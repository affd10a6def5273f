#include "subdiv/control_topology.h"

#include <limits>

#include "control_meshes.h"

namespace meshseg::subdiv_internal {
namespace {

using ::testing::HasSubstr;

TEST(BuildControlTopology, ClassifiesVerticesBySharpEdges) {
  auto topo = BuildControlTopology(testing::CreasedOctahedron());
  ASSERT_TRUE(topo.ok()) << topo.status();
  EXPECT_EQ(topo->edges.size(), 12u);
  int sharp = 0;
  for (char s : topo->sharp) sharp += s;
  EXPECT_EQ(sharp, 5);
  EXPECT_EQ(topo->kind[0], VertexKind::kSmooth);  // dart
  EXPECT_EQ(topo->kind[1], VertexKind::kCorner);  // tagged
  EXPECT_EQ(topo->kind[2], VertexKind::kCrease);
  EXPECT_EQ(topo->kind[3], VertexKind::kCorner);  // three sharp edges
  EXPECT_EQ(topo->kind[4], VertexKind::kCrease);
  EXPECT_EQ(topo->kind[5], VertexKind::kSmooth);
}

TEST(BuildControlTopology, BoundaryEdgesAreSharp) {
  ControlMesh m = testing::Lattice(2, 2, [](int, int) { return 0.0; });
  m.corners.clear();
  auto topo = BuildControlTopology(m);
  ASSERT_TRUE(topo.ok()) << topo.status();
  int sharp = 0;
  for (char s : topo->sharp) sharp += s;
  EXPECT_EQ(sharp, 8);
  EXPECT_EQ(topo->kind[1], VertexKind::kCrease);  // middle of the bottom side
  EXPECT_EQ(topo->kind[4], VertexKind::kSmooth);  // the centre
}

TEST(BuildControlTopology, RejectsEdgeOfThreeFaces) {
  ControlMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  auto topo = BuildControlTopology(m);
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(topo.status().message(), HasSubstr("more than 2 faces"));
}

TEST(BuildControlTopology, RejectsCreaseThatIsNoEdge) {
  ControlMesh m = testing::CreasedOctahedron();
  m.creases.push_back({0, 5});
  auto topo = BuildControlTopology(m);
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(topo.status().message(), HasSubstr("crease (0, 5) is not an edge"));
}

TEST(BuildControlTopology, RejectsBadIndicesAndCoordinates) {
  ControlMesh m = testing::CreasedOctahedron();
  m.faces.push_back({0, 1, 6});
  EXPECT_THAT(BuildControlTopology(m).status().message(), HasSubstr("vertex 6 outside [0, 6)"));
  m = testing::CreasedOctahedron();
  m.faces.push_back({0, 0, 1});
  EXPECT_THAT(BuildControlTopology(m).status().message(), HasSubstr("repeats a vertex"));
  m = testing::CreasedOctahedron();
  m.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(BuildControlTopology(m).status().message(), HasSubstr("control vertex 2 has a NaN"));
  m = testing::CreasedOctahedron();
  m.corners.push_back(-1);
  EXPECT_THAT(BuildControlTopology(m).status().message(), HasSubstr("corner vertex -1 outside"));
  EXPECT_THAT(BuildControlTopology(ControlMesh{}).status().message(), HasSubstr("no faces"));
}

}  // namespace
}  // namespace meshseg::subdiv_internal
