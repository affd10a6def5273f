#include "meshseg/features.h"

#include <cmath>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace meshseg {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// Regions and a hand-made topology: arcs with one curve each, smooth or sharp.
struct Scene {
  std::vector<Region> regions;
  Topology topology;

  int Add(const Surface& s, int normal_sign = 1, double area = 1.0) {
    Region r;
    r.id = static_cast<int>(regions.size());
    r.type = TypeOf(s);
    r.surface = s;
    r.area = area;
    regions.push_back(r);
    RegionTopology t;
    t.region = r.id;
    t.normal_sign = normal_sign;
    topology.regions.push_back(t);
    return r.id;
  }
  // Joins a and b by one curve; `geometry` describes it.
  void Join(int a, int b, bool sharp, CurveGeometry geometry = {}) {
    BoundaryCurve c;
    c.id = static_cast<int>(topology.curves.size());
    c.left_region = std::min(a, b);
    c.right_region = std::max(a, b);
    c.sharp = sharp;
    c.geometry = geometry;
    topology.curves.push_back(c);
    for (int r : {a, b}) {
      Loop loop;
      loop.id = static_cast<int>(topology.loops.size());
      loop.region = r;
      loop.curves = {{c.id, r != c.left_region}};
      topology.loops.push_back(loop);
      topology.regions[r].loops.push_back(loop.id);
    }
    topology.adjacency.push_back({std::min(a, b), std::max(a, b), {c.id}});
    std::sort(topology.adjacency.begin(), topology.adjacency.end(),
              [](const Adjacency& x, const Adjacency& y) {
                return std::tie(x.region_a, x.region_b) < std::tie(y.region_a, y.region_b);
              });
  }
  Scene() { topology.mean_edge_length = 0.1; }
};

CurveGeometry Circle(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double r) {
  CurveGeometry g;
  g.type = CurveGeometryType::kCircle;
  g.point = center;
  g.direction = normal;
  g.radius = r;
  return g;
}

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

TEST(RecognizeFeatures, TorusBetweenCylinderAndPlaneIsFlt2) {
  Scene s;
  const int plane = s.Add(Plane{Eigen::Vector3d::Zero(), -kZ}, -1);
  const int torus = s.Add(Torus{4.0 * kZ, kZ, 14.0, 4.0}, -1);  // concave root fillet
  const int boss = s.Add(Cylinder{Eigen::Vector3d::Zero(), kZ, 10.0});
  s.Join(plane, torus, false);
  s.Join(torus, boss, false);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  ASSERT_FALSE(features->empty());
  const Feature& f = features->front();
  EXPECT_EQ(f.type, FeatureType::kFilletTorusCylinderPlane);
  EXPECT_THAT(f.regions, ElementsAre(torus, boss, plane));
  EXPECT_DOUBLE_EQ(f.radius, 4.0);
  EXPECT_FALSE(f.convex);
}

TEST(RecognizeFeatures, TorusBetweenSphereAndPlaneIsFlt1) {
  Scene s;
  const int plane = s.Add(Plane{Eigen::Vector3d::Zero(), kZ});
  const int torus = s.Add(Torus{-kZ, kZ, 5.0, 1.0});
  const int sphere = s.Add(Sphere{-5.0 * kZ, 7.0});
  s.Join(plane, torus, false);
  s.Join(torus, sphere, false);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  ASSERT_FALSE(features->empty());
  EXPECT_EQ(features->front().type, FeatureType::kFilletTorusSpherePlane);
  EXPECT_THAT(features->front().regions, ElementsAre(torus, sphere, plane));
  EXPECT_TRUE(features->front().convex);
}

TEST(RecognizeFeatures, SharpJoinIsNoFillet) {
  Scene s;
  const int plane = s.Add(Plane{Eigen::Vector3d::Zero(), kZ});
  const int torus = s.Add(Torus{-kZ, kZ, 5.0, 1.0});
  const int cylinder = s.Add(Cylinder{Eigen::Vector3d::Zero(), kZ, 5.0});
  s.Join(plane, torus, true);
  s.Join(torus, cylinder, false);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  for (const Feature& f : *features) EXPECT_NE(f.type, FeatureType::kFilletTorusCylinderPlane);
}

// A box edge along y rounded by a cylinder, and the three fillets of a
// rounded box corner meeting in a sphere.
TEST(RecognizeFeatures, RoundedBoxCornerHasThreeFlt3AndOneSphericalFlt4) {
  Scene s;
  const int px = s.Add(Plane{kX, kX});
  const int py = s.Add(Plane{kY, kY});
  const int pz = s.Add(Plane{kZ, kZ});
  const Eigen::Vector3d c = 0.8 * Eigen::Vector3d::Ones();
  const int fxy = s.Add(Cylinder{c, kZ, 0.2});
  const int fyz = s.Add(Cylinder{c, kX, 0.2});
  const int fzx = s.Add(Cylinder{c, kY, 0.2});
  const int corner = s.Add(Sphere{c, 0.2});
  s.Join(px, fxy, false);
  s.Join(py, fxy, false);
  s.Join(py, fyz, false);
  s.Join(pz, fyz, false);
  s.Join(pz, fzx, false);
  s.Join(px, fzx, false);
  for (int f : {fxy, fyz, fzx}) s.Join(corner, f, false);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  int flt3 = 0;
  int flt4 = 0;
  for (const Feature& f : *features) {
    if (f.type == FeatureType::kFilletCylinderPlanes) {
      ++flt3;
      EXPECT_NEAR(f.opening_angle_deg, 90.0, 1e-9);
      EXPECT_DOUBLE_EQ(f.radius, 0.2);
      EXPECT_TRUE(f.convex);
    }
    if (f.type == FeatureType::kCornerBlendSphere) {
      ++flt4;
      EXPECT_THAT(f.regions, ElementsAre(corner, fxy, fyz, fzx));
    }
  }
  EXPECT_EQ(flt3, 3);
  EXPECT_EQ(flt4, 1);
}

TEST(RecognizeFeatures, CylinderBetweenParallelPlanesIsNoFlt3) {
  Scene s;  // a half-round slot end: opening angle 180
  const int a = s.Add(Plane{kY, kY});
  const int b = s.Add(Plane{-kY, -kY});
  const int c = s.Add(Cylinder{Eigen::Vector3d::Zero(), kZ, 1.0});
  s.Join(a, c, false);
  s.Join(b, c, false);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  for (const Feature& f : *features) EXPECT_NE(f.type, FeatureType::kFilletCylinderPlanes);
}

TEST(RecognizeFeatures, SquarePrismSidesAreOneExtrusion) {
  Scene s;
  std::vector<int> sides;
  for (const Eigen::Vector3d& n : {kX, kY, Eigen::Vector3d(-kX), Eigen::Vector3d(-kY)}) {
    sides.push_back(s.Add(Plane{n, n}));
  }
  for (int k = 0; k < 4; ++k) s.Join(sides[k], sides[(k + 1) % 4], true);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  ASSERT_EQ(features->size(), 1u);
  EXPECT_EQ(features->front().type, FeatureType::kLinearExtrusion);
  EXPECT_THAT(features->front().regions, ElementsAre(0, 1, 2, 3));
  EXPECT_NEAR(std::abs(features->front().direction.z()), 1.0, 1e-12);
}

TEST(RecognizeFeatures, CoaxialCylindersAndAnnulusAreOneRevolution) {
  Scene s;
  const int big = s.Add(Cylinder{Eigen::Vector3d::Zero(), kZ, 2.0}, 1, 10.0);
  const int step = s.Add(Plane{kZ, kZ});
  const int small = s.Add(Cylinder{Eigen::Vector3d(0, 0, 3), -kZ, 1.0});
  const int plate = s.Add(Plane{3.0 * kZ, kZ});  // bounded by a line too: not a member
  s.Join(big, step, true, Circle(kZ, kZ, 2.0));
  s.Join(step, small, true, Circle(kZ, kZ, 1.0));
  s.Join(small, plate, true, Circle(3.0 * kZ, kZ, 1.0));
  CurveGeometry line;
  line.type = CurveGeometryType::kLine;
  s.Join(plate, big, true, line);
  const auto features = RecognizeFeatures(s.topology, s.regions);
  ASSERT_TRUE(features.ok()) << features.status();
  ASSERT_EQ(features->size(), 1u);
  EXPECT_EQ(features->front().type, FeatureType::kRevolution);
  EXPECT_THAT(features->front().regions, ElementsAre(big, step, small));
}

TEST(RecognizeFeatures, RejectsRegionCountMismatch) {
  Scene s;
  s.Add(Plane{});
  std::vector<Region> more = s.regions;
  more.push_back(more.front());
  const auto features = RecognizeFeatures(s.topology, more);
  EXPECT_EQ(features.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(features.status().message(), HasSubstr("topology has 1 regions, expected 2"));
}

TEST(RecognizeFeatures, RejectsBadAngleTolerance) {
  Scene s;
  const auto features =
      RecognizeFeatures(s.topology, s.regions, FeatureParams{.angle_tolerance_deg = 90.0});
  EXPECT_EQ(features.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(features.status().message(), HasSubstr("angle_tolerance_deg = 90"));
}

}  // namespace
}  // namespace meshseg
