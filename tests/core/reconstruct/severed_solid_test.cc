#include "reconstruct/severed_solid.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "grid_supports.h"
#include "reconstruct/graph_cut.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kEpsilon = 0.1;

// The tets of a 9³ grid over [−2, 2]³ (step 0.5). The solid is the cube of
// interior nodes |x|, |y|, |z| ≤ 1 (f = 1, 5³ nodes); the rest is outside
// (f = −1). `inside` starts as f's sign; each test turns some nodes.
struct Grid {
  TetMesh tets;
  std::vector<Eigen::Vector3d> position;
  std::vector<double> f;
  std::vector<uint8_t> by_sign;
  std::vector<uint8_t> sparse;
  std::vector<uint8_t> inside;
  // Nodes of the solid by their x: the slices x = −1, −0.5, 0, 0.5, 1.
  std::vector<int> Slice(double x) const {
    std::vector<int> out;
    for (size_t v = 0; v < position.size(); ++v) {
      if (by_sign[v] && std::abs(position[v].x() - x) < 1e-9) out.push_back(static_cast<int>(v));
    }
    return out;
  }
  void Set(const std::vector<int>& nodes, double value) {
    for (const int v : nodes) f[v] = value;
  }
  void Label(const std::vector<int>& nodes, uint8_t label) {
    for (const int v : nodes) inside[v] = label;
  }
  // RejoinSeveredSolid on `inside`, with the set the cut ties inside.
  int64_t Rejoin(const std::vector<uint8_t>& seen_outside = {}) {
    return RejoinSeveredSolid(tets, f, by_sign, sparse, seen_outside,
                              ResolvedInside(tets, f, sparse, kEpsilon), kEpsilon, &inside);
  }
};

Grid CubeGrid() {
  Grid g;
  const std::vector<Support> supports = test::GridSupports(9, 2.0);
  g.tets = *RegularTetrahedralization(supports, {});
  for (const int s : g.tets.support) {
    const Eigen::Vector3d& c = supports[s].center;
    g.position.push_back(c);
    g.f.push_back(c.cwiseAbs().maxCoeff() < 1.0 + 1e-9 ? 1.0 : -1.0);
  }
  g.by_sign = SignLabels(g.tets, g.f);
  g.sparse.assign(g.f.size(), 0);
  g.inside = g.by_sign;
  return g;
}

// The cut turned the slice x = 0.5 outside (f ≥ 0 there), severing the slice
// x = 1, whose nodes the points resolve inside (f = 1 ≥ ε, not sparse): the
// slice goes back inside and the solid is whole again.
TEST(RejoinSeveredSolid, GivesBackTheRowTheCutTurnedBetweenAResolvedPieceAndTheSolid) {
  Grid g = CubeGrid();
  const std::vector<int> row = g.Slice(0.5), piece = g.Slice(1.0);
  ASSERT_EQ(row.size(), 25u);
  ASSERT_EQ(piece.size(), 25u);
  g.Label(row, 0);
  const int64_t rejoined =
      g.Rejoin();
  EXPECT_EQ(rejoined, 25);
  EXPECT_EQ(g.inside, g.by_sign);
}

// Only the row between them: a layer the cut turned elsewhere on the solid
// (its face x = −1, not between the piece and the rest) stays outside.
TEST(RejoinSeveredSolid, LeavesTheCutsOtherDecisions) {
  Grid g = CubeGrid();
  g.Label(g.Slice(0.5), 0);
  g.Label(g.Slice(-1.0), 0);
  g.Rejoin();
  for (const int v : g.Slice(0.5)) EXPECT_EQ(g.inside[v], 1) << v;
  for (const int v : g.Slice(-1.0)) EXPECT_EQ(g.inside[v], 0) << v;
}

// Two layers turned (x = 0 and 0.5) between the piece and the rest: both
// go back.
TEST(RejoinSeveredSolid, CrossesAGapSeveralLayersWide) {
  Grid g = CubeGrid();
  g.Label(g.Slice(0.0), 0);
  g.Label(g.Slice(0.5), 0);
  EXPECT_EQ(g.Rejoin(), 50);
  EXPECT_EQ(g.inside, g.by_sign);
}

// The node at the centre of the face x = 1 of a plate-like solid, which
// the points resolve inside (f = 1 ≥ ε, not sparse), has only shallow
// neighbours (the rest of that face and the row x = 0.5, f below ε): the
// cut turned it outside with them. It goes back inside with the turned
// nodes between it and the solid, and the face's nodes farther off (its
// corners) stay as the cut left them.
TEST(RejoinSeveredSolid, GivesBackAResolvedVertexTheCutTurnedOutsideItself) {
  Grid g = CubeGrid();
  const std::vector<int> face = g.Slice(1.0), row = g.Slice(0.5);
  g.Set(face, 0.5 * kEpsilon);
  g.Set(row, 0.5 * kEpsilon);
  int centre = -1;
  for (const int v : face) {
    if (g.position[v].tail<2>().norm() < 1e-9) centre = v;
  }
  ASSERT_GE(centre, 0);
  g.f[centre] = 1.0;
  g.Label(face, 0);
  g.Label(row, 0);
  const int64_t rejoined =
      g.Rejoin();
  EXPECT_GT(rejoined, 1);  // the centre and the turned nodes joining it
  EXPECT_EQ(g.inside[centre], 1);
  for (const int v : face) {
    if (g.position[v].tail<2>().cwiseAbs().minCoeff() > 1.0 - 1e-9) {
      EXPECT_EQ(g.inside[v], 0) << v;
    }
  }
}

// The same lone resolved node behind a row the points show outside (f < 0,
// a second body beside the solid) stays outside.
TEST(RejoinSeveredSolid, LeavesAResolvedVertexBeyondAGapThePointsShow) {
  Grid g = CubeGrid();
  const std::vector<int> face = g.Slice(1.0), row = g.Slice(0.5);
  g.Set(face, 0.5 * kEpsilon);
  g.Set(row, -0.5);
  for (const int v : face) {
    if (g.position[v].tail<2>().norm() < 1e-9) g.f[v] = 1.0;
  }
  g.by_sign = SignLabels(g.tets, g.f);
  g.inside = g.by_sign;
  g.Label(face, 0);
  const std::vector<uint8_t> before = g.inside;
  EXPECT_EQ(g.Rejoin(), 0);
  EXPECT_EQ(g.inside, before);
}

// A piece with no vertex the points resolve (f below ε, or sparse
// supports) is a bubble the small-component drop judges: left apart.
TEST(RejoinSeveredSolid, LeavesAPieceThePointsDoNotResolve) {
  for (const bool sparse : {false, true}) {
    SCOPED_TRACE(sparse ? "sparse supports" : "f below epsilon");
    Grid g = CubeGrid();
    const std::vector<int> piece = g.Slice(1.0);
    if (sparse) {
      for (const int v : piece) g.sparse[v] = 1;
    } else {
      g.Set(piece, 0.5 * kEpsilon);
    }
    g.Label(g.Slice(0.5), 0);
    const std::vector<uint8_t> before = g.inside;
    EXPECT_EQ(g.Rejoin(), 0);
    EXPECT_EQ(g.inside, before);
  }
}

// Two bodies the points show apart: the row between them has f < 0, or
// its vertices are seen from outside by every point they read. Neither is
// crossed.
TEST(RejoinSeveredSolid, NeverCrossesAGapThePointsShow) {
  for (const bool negative : {true, false}) {
    SCOPED_TRACE(negative ? "f < 0 in the gap" : "gap seen from outside");
    Grid g = CubeGrid();
    const std::vector<int> row = g.Slice(0.5);
    std::vector<uint8_t> seen_outside(g.f.size(), 0);
    if (negative) {
      g.Set(row, -0.5);
      g.by_sign = SignLabels(g.tets, g.f);
    } else {
      for (const int v : row) seen_outside[v] = 1;
    }
    g.Label(row, 0);
    const std::vector<uint8_t> before = g.inside;
    EXPECT_EQ(
        g.Rejoin(seen_outside),
        0);
    EXPECT_EQ(g.inside, before);
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
