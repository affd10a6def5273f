#include "meshseg/topology.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "labelled_meshes.h"
#include "topology_checks.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing::CappedCylinder;
using testing::GriddedBox;

constexpr double kExact = 1e-9;  // model units, for exact ground truth

TEST(ExtractTopology, BoxHasTwelveLineCurvesEightSnappedCornersSixOuterLoops) {
  const testing::LabelledMesh box = GriddedBox({2.0, 3.0, 4.0}, 4);
  const absl::StatusOr<Topology> topo = ExtractTopology(box.mesh, box.face_labels, box.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  testing::ExpectConsistent(box.mesh.tri, box.face_labels, *topo);
  EXPECT_EQ(topo->curves.size(), 12u);
  EXPECT_EQ(topo->corners.size(), 8u);
  EXPECT_EQ(topo->adjacency.size(), 12u);
  ASSERT_EQ(topo->loops.size(), 6u);
  for (const Loop& loop : topo->loops) {
    EXPECT_EQ(loop.kind, LoopKind::kOuter) << "loop " << loop.id;
    EXPECT_EQ(loop.curves.size(), 4u) << "loop " << loop.id;
    // Counterclockwise about the side's outward normal: positive vector area.
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    for (const CurveUse& use : loop.curves) {
      std::vector<int> v = topo->curves[use.curve].vertices;
      if (use.reversed) std::reverse(v.begin(), v.end());
      for (size_t i = 0; i + 1 < v.size(); ++i) {
        area += ToEigen(box.mesh.tri.point(OpenMesh::VertexHandle(v[i])))
                    .cross(ToEigen(box.mesh.tri.point(OpenMesh::VertexHandle(v[i + 1]))));
      }
    }
    const int side = loop.region;
    const Eigen::Vector3d outward = (side % 2 == 0 ? -1.0 : 1.0) * Eigen::Vector3d::Unit(side / 2);
    EXPECT_GT(area.dot(outward), 0.0) << "loop " << loop.id;
  }
  for (const BoundaryCurve& c : topo->curves) {
    EXPECT_EQ(c.geometry.type, CurveGeometryType::kLine) << "curve " << c.id;
    EXPECT_TRUE(c.geometry.analytic) << "curve " << c.id;
    EXPECT_LT(c.geometry.max_deviation, kExact) << "curve " << c.id;
    EXPECT_TRUE(c.sharp) << "curve " << c.id;
    EXPECT_NEAR(c.normal_angle_deg, 90.0, 1e-6) << "curve " << c.id;
    EXPECT_EQ(c.convexity, CurveConvexity::kConvex) << "curve " << c.id;
    // The line runs along the curve.
    const Eigen::Vector3d a = ToEigen(box.mesh.tri.point(OpenMesh::VertexHandle(c.vertices.front())));
    const Eigen::Vector3d b = ToEigen(box.mesh.tri.point(OpenMesh::VertexHandle(c.vertices.back())));
    EXPECT_NEAR((b - a).normalized().dot(c.geometry.direction), 1.0, kExact) << "curve " << c.id;
  }
  for (const Corner& corner : topo->corners) {
    EXPECT_TRUE(corner.snapped) << "corner " << corner.id;
    EXPECT_EQ(corner.regions.size(), 3u);
    EXPECT_EQ(corner.curves.size(), 3u);
    const Eigen::Vector3d v = ToEigen(box.mesh.tri.point(OpenMesh::VertexHandle(corner.vertex)));
    EXPECT_LT((corner.position - v).norm(), kExact) << "corner " << corner.id;
  }
  // Planes 1, 3, 5 were given inward normals.
  for (const RegionTopology& r : topo->regions) {
    EXPECT_EQ(r.normal_sign, r.region % 2 == 1 ? -1 : 1) << "region " << r.region;
    EXPECT_EQ(r.patch_count, 1);
  }
}

TEST(ExtractTopology, CappedCylinderHasTwoAnalyticCirclesAndTwoAxialLoops) {
  const double radius = 2.0;
  const testing::LabelledMesh cyl = CappedCylinder(radius, 3.0, 48, 6, 3);
  const absl::StatusOr<Topology> topo = ExtractTopology(cyl.mesh, cyl.face_labels, cyl.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  testing::ExpectConsistent(cyl.mesh.tri, cyl.face_labels, *topo);
  ASSERT_EQ(topo->curves.size(), 2u);
  EXPECT_TRUE(topo->corners.empty());
  for (const BoundaryCurve& c : topo->curves) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.geometry.type, CurveGeometryType::kCircle) << "curve " << c.id;
    EXPECT_TRUE(c.geometry.analytic);
    EXPECT_NEAR(c.geometry.radius, radius, kExact);
    EXPECT_NEAR(c.geometry.point.head<2>().norm(), 0.0, kExact);
    EXPECT_TRUE(c.sharp);
    EXPECT_EQ(c.convexity, CurveConvexity::kConvex);
    EXPECT_NEAR(std::abs(c.geometry.direction.z()), 1.0, kExact);
  }
  int axial = 0;
  int outer = 0;
  for (const Loop& loop : topo->loops) {
    if (loop.kind == LoopKind::kAxial) {
      EXPECT_EQ(loop.region, 1);
      ++axial;
    }
    if (loop.kind == LoopKind::kOuter) ++outer;
  }
  EXPECT_EQ(axial, 2);
  EXPECT_EQ(outer, 2);
}

TEST(ExtractTopology, OpenBoxHasBorderCurvesAndBorderCorners) {
  testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 3);
  // Drop the top (label 5) by relabelling it -1: its edges become a border.
  for (int& l : box.face_labels) {
    if (l == 5) l = -1;
  }
  const absl::StatusOr<Topology> topo = ExtractTopology(box.mesh, box.face_labels, box.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  testing::ExpectConsistent(box.mesh.tri, box.face_labels, *topo);
  int border = 0;
  for (const BoundaryCurve& c : topo->curves) {
    if (c.right_region == -1) {
      ++border;
      EXPECT_EQ(c.convexity, CurveConvexity::kBorder);
      EXPECT_EQ(c.geometry.type, CurveGeometryType::kLine);
      EXPECT_FALSE(c.geometry.analytic);
    }
  }
  EXPECT_EQ(border, 4);
  EXPECT_EQ(topo->curves.size(), 12u);
  EXPECT_EQ(topo->corners.size(), 8u);
  EXPECT_EQ(topo->adjacency.size(), 8u);
}

TEST(ExtractTopology, ConcaveEdgeOfAnLShapeIsConcave) {
  // Two boxes' worth of labels are not needed: flip one plane pair of the box
  // inside out by mirroring its labels onto a concave configuration instead
  // (the inside of the box, faces reversed) — every edge becomes concave.
  testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 2);
  TriMesh& tri = box.mesh.tri;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector3d> vertices;
  for (auto v : tri.vertices()) vertices.push_back(ToEigen(tri.point(v)));
  for (auto f : tri.faces()) {
    std::array<int, 3> t{};
    int i = 0;
    for (auto v : tri.fv_range(f)) t[i++] = v.idx();
    triangles.push_back({t[0], t[2], t[1]});
  }
  Mesh inside = *BuildMesh(vertices, triangles, "inside_box");
  const absl::StatusOr<Topology> topo = ExtractTopology(inside, box.face_labels, box.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  testing::ExpectConsistent(inside.tri, box.face_labels, *topo);
  for (const BoundaryCurve& c : topo->curves) {
    EXPECT_EQ(c.convexity, CurveConvexity::kConcave) << "curve " << c.id;
  }
}

TEST(ExtractTopology, RejectsLabelCountMismatch) {
  const testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 1);
  const std::vector<int> labels(3, 0);
  const absl::StatusOr<Topology> topo = ExtractTopology(box.mesh, labels, box.regions);
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(topo.status().message(), HasSubstr("3 face labels for 12 faces"));
}

TEST(ExtractTopology, RejectsLabelOutOfRange) {
  testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 1);
  box.face_labels[5] = 9;
  const absl::StatusOr<Topology> topo = ExtractTopology(box.mesh, box.face_labels, box.regions);
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(topo.status().message(), HasSubstr("face 5 has label 9, outside [-1, 6)"));
}

TEST(ExtractTopology, RejectsBadParams) {
  const testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 1);
  const absl::StatusOr<Topology> topo = ExtractTopology(
      box.mesh, box.face_labels, box.regions, TopologyParams{.curve_tolerance = -1.0});
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(topo.status().message(), HasSubstr("curve_tolerance = -1"));
}

// The mean edge length measured once by the caller (MeshStatistics) is the
// value ExtractTopology sums itself: the same curves, corners and loops bit
// for bit. A length that is not finite and > 0 is refused, named.
TEST(ExtractTopology, GivenTheMeanEdgeLengthGivesTheSameTopology) {
  const testing::LabelledMesh box = GriddedBox({2.0, 3.0, 4.0}, 4);
  const absl::StatusOr<Topology> own = ExtractTopology(box.mesh, box.face_labels, box.regions);
  const absl::StatusOr<Topology> given = ExtractTopology(
      box.mesh, box.face_labels, box.regions, MeanEdgeLength(box.mesh.tri));
  ASSERT_TRUE(own.ok()) << own.status();
  ASSERT_TRUE(given.ok()) << given.status();
  EXPECT_EQ(given->mean_edge_length, own->mean_edge_length);
  ASSERT_EQ(given->curves.size(), own->curves.size());
  for (std::size_t i = 0; i < own->curves.size(); ++i) {
    EXPECT_EQ(given->curves[i].vertices, own->curves[i].vertices) << i;
    EXPECT_EQ(given->curves[i].length, own->curves[i].length) << i;
    EXPECT_EQ(given->curves[i].junction_artifact, own->curves[i].junction_artifact) << i;
  }
  ASSERT_EQ(own->corners.size(), 8u);
  ASSERT_EQ(given->corners.size(), own->corners.size());
  for (std::size_t i = 0; i < own->corners.size(); ++i) {
    EXPECT_EQ(given->corners[i].position, own->corners[i].position) << i;
  }
  ASSERT_EQ(given->loops.size(), own->loops.size());
  for (std::size_t i = 0; i < own->loops.size(); ++i) {
    EXPECT_EQ(given->loops[i].kind, own->loops[i].kind) << i;
    EXPECT_EQ(given->loops[i].patch, own->loops[i].patch) << i;
  }
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    const absl::StatusOr<Topology> refused =
        ExtractTopology(box.mesh, box.face_labels, box.regions, bad);
    EXPECT_EQ(refused.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(refused.status().message(), HasSubstr("mean edge length"));
  }
}

TEST(ExtractTopology, StopsWhenCancelled) {
  const testing::LabelledMesh box = GriddedBox({1.0, 1.0, 1.0}, 2);
  std::stop_source stop;
  stop.request_stop();
  RunContext ctx;
  ctx.stop = stop.get_token();
  const absl::StatusOr<Topology> topo = ExtractTopology(box.mesh, box.face_labels, box.regions, {}, ctx);
  EXPECT_EQ(topo.status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg
