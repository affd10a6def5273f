#include "reconstruct/graph_cut.h"

#include <gtest/gtest.h>

#include "grid_supports.h"
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
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {});
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
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  EXPECT_EQ((*cut)[bad], 0);
}

TEST(GraphCutLabels, HullVerticesAreOutside) {
  Field field = SphereField();
  for (double& f : field.f) f = 1.0;  // everything claims to be inside
  const auto cut = GraphCutLabels(field.tets, field.position, field.f, 10.0, {});
  ASSERT_TRUE(cut.ok()) << cut.status();
  for (size_t v = 0; v < cut->size(); ++v) {
    if (field.tets.on_hull[v]) {
      EXPECT_EQ((*cut)[v], 0);
    }
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
