#include "reconstruct/graph_cut.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "grid_supports.h"
#include "mesh/point_index.h"
#include "reconstruct/pu_function.h"

namespace meshseg::reconstruct_internal {
namespace {

struct Field {
  std::vector<Support> supports;
  TetMesh tets;
  std::vector<Eigen::Vector3d> position;
  std::vector<double> f;
};

// f ≈ 1 − |x| sampled on a 9³ grid over [−2, 2]³.
Field SphereField() {
  Field field;
  field.supports = test::GridSupports(9, 2.0);
  field.tets = *RegularTetrahedralization(field.supports, {});
  for (const int s : field.tets.support) {
    field.position.push_back(field.supports[s].center);
    field.f.push_back(1.0 - field.supports[s].center.norm());
  }
  return field;
}

TEST(GraphCutLabels, AgreeWithTheSignOfACleanFieldAwayFromTheSurface) {
  constexpr double kGridStep = 0.5;
  const Field field = SphereField();
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, {}, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  const auto sign = SignLabels(field.tets, field.f);
  int inside = 0;
  for (size_t v = 0; v < sign.size(); ++v) {
    inside += (*cut)[v];
    if (std::abs(field.f[v]) > kGridStep) {
      EXPECT_EQ((*cut)[v], sign[v]) << v;
    }
  }
  EXPECT_GT(inside, 0);
}

TEST(GraphCutLabels, RelabelAFalseInsideVertexFarFromTheSurface) {
  Field field = SphereField();
  // A node at (1.5, 1.5, 1.5) (f ≈ −1.6) that a bad local fit turned positive.
  int bad = -1;
  for (size_t v = 0; v < field.position.size(); ++v) {
    if ((field.position[v] - Eigen::Vector3d(1.5, 1.5, 1.5)).norm() < 1e-9) bad = v;
  }
  ASSERT_GE(bad, 0);
  field.f[bad] = 0.1;
  const auto sign = SignLabels(field.tets, field.f);
  EXPECT_EQ(sign[bad], 1);
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, {}, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  EXPECT_EQ((*cut)[bad], 0);
}

TEST(GraphCutLabels, HullVerticesAreOutside) {
  Field field = SphereField();
  for (double& f : field.f) f = 1.0;  // everything claims to be inside
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, {}, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  for (size_t v = 0; v < cut->size(); ++v) {
    if (field.tets.on_hull[v]) {
      EXPECT_EQ((*cut)[v], 0);
    }
  }
}

// A plate one grid layer thick (z = 0, f = 0.2 > ε: each vertex lies on the
// inside of a well-sampled fit, farther than the fit's error) with
// everything else outside (f = −1), and one lone inside vertex away from it.
// The cut alone prices a thin inside region by its area against the small
// |f| of its vertices and drops it: the seen plate would vanish. Tied by
// ResolvedInside, the plate stays; the lone vertex, not joined to the
// largest resolved region (a bubble of stray points), is still dropped.
TEST(GraphCutLabels, AThinPlateThePointsResolveStaysInside) {
  constexpr double kEpsilon = 0.1;
  Field field = SphereField();
  std::vector<int> plate;
  int lone = -1;
  for (size_t v = 0; v < field.position.size(); ++v) {
    const Eigen::Vector3d& p = field.position[v];
    field.f[v] = -1.0;
    if (field.tets.on_hull[v]) continue;
    if (std::abs(p.z()) < 1e-9) {
      field.f[v] = 0.2;
      plate.push_back(static_cast<int>(v));
    } else if ((p - Eigen::Vector3d(1.0, 1.0, 1.0)).norm() < 1e-9) {
      field.f[v] = 0.2;
      lone = static_cast<int>(v);
    }
  }
  ASSERT_EQ(plate.size(), 49u);  // the 7 × 7 interior nodes of the layer
  ASSERT_GE(lone, 0);
  const std::vector<uint8_t> no_points(field.f.size(), 0);  // no support is sparse
  const std::vector<uint8_t> resolved =
      ResolvedInside(field.tets, field.f, no_points, kEpsilon);
  for (const int v : plate) EXPECT_EQ(resolved[v], 1) << v;
  EXPECT_EQ(resolved[lone], 0);

  const auto plain = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, {}, {});
  ASSERT_TRUE(plain.ok()) << plain.status();
  int kept_plain = 0;
  for (const int v : plate) kept_plain += (*plain)[v];
  EXPECT_LT(kept_plain, 49) << "the plain cut keeps the thin plate: the test shows nothing";

  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, resolved, {}, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  for (const int v : plate) EXPECT_EQ((*cut)[v], 1) << v;
  EXPECT_EQ((*cut)[lone], 0);
}

// A vertex deep inside the sphere (f = 1) that the points see from outside
// is labelled outside; without the flag the cut keeps it inside.
TEST(GraphCutLabels, AVertexSeenFromOutsideIsOutsideWhateverF) {
  const Field field = SphereField();
  int centre = -1;
  for (size_t v = 0; v < field.position.size(); ++v) {
    if (field.position[v].norm() < 1e-9) centre = static_cast<int>(v);
  }
  ASSERT_GE(centre, 0);
  const auto plain = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, {}, {});
  ASSERT_TRUE(plain.ok()) << plain.status();
  EXPECT_EQ((*plain)[centre], 1);
  std::vector<uint8_t> seen_outside(field.f.size(), 0);
  seen_outside[centre] = 1;
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {}, seen_outside, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  EXPECT_EQ((*cut)[centre], 0);
}

// The upper wall of a bore of radius 6 along z (z from 4 to 10, sampled
// every 0.5 round and along it), with inward normals pointing away from the
// axis (into the material). Below the bore's mouth, on its axis, a ball of
// radius 9 holds the wall's lowest rows all round: every one of them has
// the centre 6 in front of its tangent plane, so f > 0 there is no evidence
// of solid. A vertex in the material beside the wall, one under the
// material (behind the wall's plane extended down), one on the hull, one
// with f ≤ 0 and one whose ball holds no point are not flagged.
TEST(SeenFromOutside, FlagsAPositiveVertexInFrontOfEveryPointItReads) {
  constexpr double kRadius = 6.0;
  std::vector<Eigen::Vector3d> points, normals;
  for (double z = 4.0; z <= 10.0 + 1e-9; z += 0.5) {
    const int round = static_cast<int>(std::ceil(2.0 * M_PI * kRadius / 0.5));
    for (int k = 0; k < round; ++k) {
      const double a = 2.0 * M_PI * k / round;
      normals.emplace_back(std::cos(a), std::sin(a), 0.0);
      points.push_back(kRadius * normals.back() + Eigen::Vector3d(0.0, 0.0, z));
    }
  }
  const mesh_internal::PointIndex index(points);
  const FitInput in{points, normals, index, /*epsilon=*/0.05, /*max_radius=*/100.0};
  const auto ball = [](const Eigen::Vector3d& c, double r) {
    Support s;
    s.center = c;
    s.radius = r;
    return s;
  };
  const std::vector<Support> supports = {
      ball({0.0, 0.0, -2.0}, 9.0),   // under the mouth, f > 0: flagged
      ball({0.0, 0.0, -2.0}, 9.0),   // the same with f ≤ 0
      ball({8.0, 0.0, 6.0}, 3.0),    // in the material beside the wall
      ball({8.0, 0.0, -1.0}, 6.0),   // under the material, behind the wall's plane
      ball({0.0, 0.0, -2.0}, 9.0),   // on the hull
      ball({0.0, 0.0, 50.0}, 1.0)};  // no point in its ball
  TetMesh tets;
  tets.support = {0, 1, 2, 3, 4, 5};
  tets.on_hull = {0, 0, 0, 0, 1, 0};
  const std::vector<double> f = {1.0, -1.0, 1.0, 1.0, 1.0, 1.0};
  const std::vector<uint8_t> flagged = SeenFromOutside(tets, supports, f, in);
  EXPECT_THAT(flagged, ::testing::ElementsAre(1, 0, 0, 0, 0, 0));
}

// A sparse support's vertex (few points) or one within ε of its fit's plane
// is left to the cut.
TEST(ResolvedInside, LeavesSparseAndNearSurfaceVerticesToTheCut) {
  Field field = SphereField();
  std::vector<uint8_t> sparse(field.f.size(), 0);
  int centre = -1;
  for (size_t v = 0; v < field.position.size(); ++v) {
    if (field.position[v].norm() < 1e-9) centre = static_cast<int>(v);
  }
  ASSERT_GE(centre, 0);
  sparse[centre] = 1;  // f = 1 there
  const std::vector<uint8_t> resolved = ResolvedInside(field.tets, field.f, sparse, 0.1);
  EXPECT_EQ(resolved[centre], 0);
  int inside = 0;
  for (size_t v = 0; v < field.f.size(); ++v) {
    if (field.f[v] < 0.1 || field.tets.on_hull[v]) {
      EXPECT_EQ(resolved[v], 0) << v;
    } else if (static_cast<int>(v) != centre) {
      EXPECT_EQ(resolved[v], 1) << v;  // the 26 nodes round the centre, joined
      ++inside;
    }
  }
  EXPECT_EQ(inside, 26);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
