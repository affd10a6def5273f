// ExtractTopology on CT-like generated parts with their ground-truth
// segmentation (surfaces refitted by the fit stage).
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "ground_truth_regions.h"
#include "meshseg/generate.h"
#include "meshseg/topology.h"
#include "topology_checks.h"

namespace meshseg {
namespace {

constexpr double kRadiusTol = 0.2;       // x voxel size h
constexpr double kDirectionTolDeg = 0.5;

struct PartTopology {
  GeneratedPart part;
  testing::TruthSegmentation truth;
  Topology topology;
};

PartTopology Extract(const std::string& name, double h) {
  PartTopology out;
  absl::StatusOr<GeneratedPart> part = GeneratePart(name, {.voxel_size = h, .noise = 0.1});
  EXPECT_TRUE(part.ok()) << part.status();
  if (!part.ok()) return out;
  out.part = *std::move(part);
  out.truth = testing::TruthOf(out.part);
  absl::StatusOr<Topology> topo =
      ExtractTopology(out.part.mesh, out.truth.face_labels, out.truth.regions);
  EXPECT_TRUE(topo.ok()) << topo.status();
  if (topo.ok()) out.topology = *std::move(topo);
  return out;
}

// Curves between the primitives called a and b, junction artifacts left out.
std::vector<const BoundaryCurve*> CurvesBetween(const PartTopology& p, const std::string& a,
                                                const std::string& b) {
  const int ia = testing::PrimitiveId(p.part, a);
  const int ib = testing::PrimitiveId(p.part, b);
  std::vector<const BoundaryCurve*> out;
  for (const BoundaryCurve& c : p.topology.curves) {
    if (std::minmax(c.left_region, c.right_region) == std::minmax(ia, ib) &&
        !c.junction_artifact) {
      out.push_back(&c);
    }
  }
  return out;
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::abs(a.normalized().dot(b.normalized()));
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

TEST(ExtractTopologyOnParts, TestPieceHoleCirclesAndPlaneLines) {
  const double h = 1.0;
  const PartTopology p = Extract("test_piece", h);
  ASSERT_FALSE(p.topology.curves.empty());
  testing::ExpectConsistent(p.part.mesh.tri, p.truth.face_labels, p.topology);
  // Closed surface of genus 1 (the bore): V - E + 2F - L = 2 - 2g.
  EXPECT_EQ(testing::BrepEulerCharacteristic(p.topology), 0);

  struct ExpectedCircle {
    std::string a, b;
    double radius;
  };
  for (const ExpectedCircle& e : {ExpectedCircle{"bore", "bottom", 8.0},
                                  ExpectedCircle{"bore", "countersink", 8.0},
                                  ExpectedCircle{"countersink", "top", 12.0},
                                  ExpectedCircle{"boss_cone", "boss_top", 5.0}}) {
    const auto curves = CurvesBetween(p, e.a, e.b);
    ASSERT_EQ(curves.size(), 1u) << e.a << "/" << e.b;
    const CurveGeometry& g = curves[0]->geometry;
    EXPECT_EQ(g.type, CurveGeometryType::kCircle) << e.a << "/" << e.b;
    EXPECT_TRUE(g.analytic) << e.a << "/" << e.b;
    EXPECT_NEAR(g.radius, e.radius, kRadiusTol * h) << e.a << "/" << e.b;
    EXPECT_TRUE(curves[0]->closed) << e.a << "/" << e.b;
  }
  // Every plane/plane curve is a line along the true edge direction.
  int plane_lines = 0;
  for (const BoundaryCurve& c : p.topology.curves) {
    if (c.right_region < 0) continue;
    const auto* pa = std::get_if<Plane>(&p.part.primitives[c.left_region].surface);
    const auto* pb = std::get_if<Plane>(&p.part.primitives[c.right_region].surface);
    if (!pa || !pb) continue;
    ++plane_lines;
    EXPECT_EQ(c.geometry.type, CurveGeometryType::kLine) << "curve " << c.id;
    EXPECT_LE(AngleDeg(c.geometry.direction, pa->normal.cross(pb->normal)), kDirectionTolDeg)
        << "curve " << c.id << " " << p.part.primitives[c.left_region].name << "/"
        << p.part.primitives[c.right_region].name;
    EXPECT_TRUE(c.sharp) << "curve " << c.id;
  }
  EXPECT_GE(plane_lines, 8);
  // The bore is a cylinder through the block: two axial loops, no outer.
  const int bore = testing::PrimitiveId(p.part, "bore");
  ASSERT_EQ(p.topology.regions[bore].loops.size(), 2u);
  for (const int l : p.topology.regions[bore].loops) {
    EXPECT_EQ(p.topology.loops[l].kind, LoopKind::kAxial);
  }
  // The top plane has one outer loop and holes (countersink, groove edges).
  const int top = testing::PrimitiveId(p.part, "top");
  int outer = 0;
  for (const int l : p.topology.regions[top].loops) {
    outer += p.topology.loops[l].kind == LoopKind::kOuter;
  }
  EXPECT_EQ(outer, p.topology.regions[top].patch_count);
}

TEST(ExtractTopologyOnParts, BlendBlockFilletEdgesAreSmoothLines) {
  const double h = 0.8;
  const PartTopology p = Extract("blend_block", h);
  testing::ExpectConsistent(p.part.mesh.tri, p.truth.face_labels, p.topology);
  EXPECT_EQ(testing::BrepEulerCharacteristic(p.topology), 2);
  for (const auto& [fillet, plane] : {std::pair<std::string, std::string>{"inner_fillet", "base_top"},
                                      {"inner_fillet", "upright_face"},
                                      {"end_round", "end"},
                                      {"top_round", "upright_top"}}) {
    const auto curves = CurvesBetween(p, fillet, plane);
    ASSERT_EQ(curves.size(), 1u) << fillet << "/" << plane;
    EXPECT_FALSE(curves[0]->sharp) << fillet << "/" << plane << " "
                                   << curves[0]->normal_angle_deg << " deg";
    EXPECT_EQ(curves[0]->geometry.type, CurveGeometryType::kLine) << fillet << "/" << plane;
  }
  const auto inner = CurvesBetween(p, "inner_fillet", "base_top");
  ASSERT_EQ(inner.size(), 1u);
  EXPECT_EQ(inner[0]->convexity, CurveConvexity::kConcave);
  const auto outer = CurvesBetween(p, "end_round", "end");
  ASSERT_EQ(outer.size(), 1u);
  EXPECT_EQ(outer[0]->convexity, CurveConvexity::kConvex);
  // Corners of three planes snap to their common point.
  int snapped = 0;
  for (const Corner& c : p.topology.corners) snapped += c.snapped;
  EXPECT_GE(snapped, 4);
}

TEST(ExtractTopologyOnParts, PlateBossLoopsAndEulerCharacteristic) {
  const double h = 1.0;
  const PartTopology p = Extract("plate_boss", h);
  testing::ExpectConsistent(p.part.mesh.tri, p.truth.face_labels, p.topology);
  // Genus 2: the bore through boss and plate, and the plate hole.
  EXPECT_EQ(testing::BrepEulerCharacteristic(p.topology), -2);
  // Cylinders and tori around their axes: only axial loops.
  for (const std::string name : {"bore", "plate_hole", "boss", "boss_fillet", "boss_edge_round"}) {
    const RegionTopology& r = p.topology.regions[testing::PrimitiveId(p.part, name)];
    EXPECT_EQ(r.loops.size(), 2u) << name;
    for (const int l : r.loops) EXPECT_EQ(p.topology.loops[l].kind, LoopKind::kAxial) << name;
  }
  // The plate top: one outer loop, two holes (fillet root and plate hole),
  // both analytic circles.
  const RegionTopology& top = p.topology.regions[testing::PrimitiveId(p.part, "plate_top")];
  ASSERT_EQ(top.patch_count, 1);
  int outer = 0;
  int inner = 0;
  for (const int l : top.loops) {
    const Loop& loop = p.topology.loops[l];
    if (loop.kind == LoopKind::kOuter) ++outer;
    if (loop.kind != LoopKind::kInner) continue;
    ++inner;
    ASSERT_EQ(loop.curves.size(), 1u);
    const BoundaryCurve& c = p.topology.curves[loop.curves[0].curve];
    EXPECT_EQ(c.geometry.type, CurveGeometryType::kCircle);
    EXPECT_TRUE(c.geometry.analytic);
  }
  EXPECT_EQ(outer, 1);
  EXPECT_EQ(inner, 2);
  const auto root = CurvesBetween(p, "boss_fillet", "plate_top");
  ASSERT_EQ(root.size(), 1u);
  EXPECT_NEAR(root[0]->geometry.radius, 14.0, kRadiusTol * h);
  EXPECT_FALSE(root[0]->sharp);
  const auto hole = CurvesBetween(p, "plate_hole", "plate_top");
  ASSERT_EQ(hole.size(), 1u);
  EXPECT_NEAR(hole[0]->geometry.radius, 4.0, kRadiusTol * h);
  EXPECT_TRUE(hole[0]->sharp);
  EXPECT_EQ(hole[0]->convexity, CurveConvexity::kConvex);
}

// A segmentation is never as clean as the truth: faces near boundaries take
// a neighbour's label or none. The complex must stay consistent and the main
// circles analytic.
TEST(ExtractTopologyOnParts, JaggedLabelsKeepTheComplexConsistent) {
  const double h = 1.0;
  absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece", {.voxel_size = h, .noise = 0.1});
  ASSERT_TRUE(part.ok()) << part.status();
  testing::TruthSegmentation truth = testing::TruthOf(*part);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coin(0.0, 1.0);
  const TriMesh& tri = part->mesh.tri;
  int changed = 0;
  for (auto f : tri.faces()) {
    if (!part->face_near_boundary[f.idx()]) continue;
    const double u = coin(rng);
    if (u < 0.02) {
      truth.face_labels[f.idx()] = -1;
      ++changed;
    } else if (u < 0.3) {
      for (auto g : tri.ff_range(f)) {
        if (part->face_primitive[g.idx()] != part->face_primitive[f.idx()]) {
          truth.face_labels[f.idx()] = part->face_primitive[g.idx()];
          ++changed;
          break;
        }
      }
    }
  }
  ASSERT_GT(changed, 100);
  const absl::StatusOr<Topology> topo = ExtractTopology(part->mesh, truth.face_labels, truth.regions);
  ASSERT_TRUE(topo.ok()) << topo.status();
  testing::ExpectConsistent(tri, truth.face_labels, *topo);
  const int bore = testing::PrimitiveId(*part, "bore");
  const int bottom = testing::PrimitiveId(*part, "bottom");
  const BoundaryCurve* longest = nullptr;
  for (const BoundaryCurve& c : topo->curves) {
    if (std::minmax(c.left_region, c.right_region) != std::minmax(bore, bottom)) continue;
    if (!longest || c.length > longest->length) longest = &c;
  }
  ASSERT_NE(longest, nullptr);
  EXPECT_EQ(longest->geometry.type, CurveGeometryType::kCircle);
  EXPECT_NEAR(longest->geometry.radius, 8.0, kRadiusTol * h);
}

}  // namespace
}  // namespace meshseg
