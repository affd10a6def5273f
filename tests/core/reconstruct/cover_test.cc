#include "reconstruct/cover.h"

#include <cmath>
#include <random>

#include "reconstruct/pu_function.h"
#include "reconstruct/regular_triangulation.h"

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

TEST(CoverBySupports, EveryLeafLiesInsideASupportAndTheOrderFollowsTheSeed) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    points.push_back(0.4 * n);
    normals.push_back(-n);
  }
  const mesh_internal::PointIndex index(points);
  const Eigen::Vector3d origin = Eigen::Vector3d::Constant(-0.5);
  const auto leaves = *BalancedOctreeLeaves(points, origin, 1.0, 5, {});
  const FitInput in{points, normals, index, 0.01, 2.0};
  const auto a = CoverBySupports(leaves, in, /*seed=*/1, {});
  const auto b = CoverBySupports(leaves, in, /*seed=*/2, {});
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_LT(a->size(), leaves.size());  // a ball covers several cells
  for (const auto& leaf : leaves) {
    bool covered = false;
    for (const auto& s : *a) {
      const Eigen::Vector3d far = (leaf.center - s.center).cwiseAbs().array() + 0.5 * leaf.size;
      covered = covered || far.norm() <= s.radius;
    }
    ASSERT_TRUE(covered) << leaf.center.transpose();
  }
  EXPECT_NE(a->front().center, b->front().center);
  for (const auto& s : *a) EXPECT_GE(s.radius, 0.75 * std::sqrt(3.0) / 32 - 1e-12);
}

// The covering of `points` on the level-6 octree of the cube of edge `cube`
// centred at the origin, its inner supports after it, and their tet weights.
struct Sampled {
  std::vector<Support> covering;
  std::vector<Support> all;  // the covering, then the inner supports
  std::vector<double> weights;
};

Sampled CoverWithInner(const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector3d>& normals, double spacing,
                       double cube) {
  const mesh_internal::PointIndex index(points);
  const auto leaves =
      *BalancedOctreeLeaves(points, Eigen::Vector3d::Constant(-cube / 2), cube, 6, {});
  const FitInput in{points, normals, index, 0.1 * spacing, std::sqrt(3.0) * cube};
  Sampled out;
  out.covering = *CoverBySupports(leaves, in, /*seed=*/1, {});
  out.all = out.covering;
  const std::vector<Support> inner = InnerSupports(out.covering, in, spacing);
  out.all.insert(out.all.end(), inner.begin(), inner.end());
  out.weights = TetWeights(out.all, RadiiSquared(out.covering));
  return out;
}

// A slab 40 × 40 × 10 (z in [-10, 0]) sampled every 0.5 on its top and its
// four sides, not on its bottom (the side it stood on), exact points with
// inward normals. A support whose ball holds its plane reads the solid
// under it as deep as its radius, so each support on the top near its
// middle (its foot among its own points, its disc fully sampled) has an
// inner support centred a radius below the top, along its m, and f of the
// covering is positive there where it lies in the slab. Those that get a
// weight are tet vertices.
TEST(InnerSupports, ASupportOnAPlaneHasAnInnerSupportARadiusInsideIt) {
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = -40; i <= 40; ++i) {
    const double x = 0.5 * i;
    for (int j = -40; j <= 40; ++j) {
      points.emplace_back(x, 0.5 * j, 0.0);
      normals.emplace_back(0, 0, -1);
    }
    for (int k = 1; k <= 20; ++k) {
      for (const double side : {-20.0, 20.0}) {
        points.emplace_back(x, side, -0.5 * k);
        normals.emplace_back(0, -side / 20, 0);
        if (std::abs(i) < 40) {
          points.emplace_back(side, x, -0.5 * k);
          normals.emplace_back(-side / 20, 0, 0);
        }
      }
    }
  }
  const Sampled sampled = CoverWithInner(points, normals, 0.5, 64.0);
  const auto tets = RegularTetrahedralization(sampled.all, sampled.weights, {});
  ASSERT_TRUE(tets.ok());
  std::vector<uint8_t> vertex(sampled.all.size(), 0);
  for (const int s : tets->support) vertex[s] = 1;
  const PuFunction f(sampled.covering);
  int parents = 0;
  for (const Support& s : sampled.covering) {
    const double height = s.g(s.center);
    if (!(s.point_count > 0 && std::abs(s.center.z()) < 1 && s.center.head<2>().norm() < 10)) {
      continue;
    }
    ++parents;
    const Eigen::Vector3d at = s.center + (s.radius - height) * s.m;
    ASSERT_NEAR(at.z(), -s.radius, 1e-6);
    size_t inner = sampled.all.size();
    for (size_t k = sampled.covering.size(); k < sampled.all.size(); ++k) {
      if ((sampled.all[k].center - at).norm() < 1e-9) inner = k;
    }
    ASSERT_LT(inner, sampled.all.size()) << "no inner support below " << s.center.transpose();
    if (at.z() > -10) {
      EXPECT_GT(f(at), 0.0);
    }
    if (sampled.weights[inner] >= 0) {
      EXPECT_TRUE(vertex[inner]) << at.transpose();
    }
  }
  EXPECT_GT(parents, 0);
}

// A flat clump of 21 stray points (a disc of radius 2 spacings, 0.5 apart)
// 3 units above a fully sampled plane, facing it (its "inside" above it,
// in empty space): the clump's supports grow past it until the plane's
// points stop their fits, so their discs hold the clump over far less than
// a quarter. No inner support comes from them (none lies above the plane),
// while the plane's own supports give theirs below it.
TEST(InnerSupports, AGhostSheetFarSmallerThanItsBallGivesNone) {
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = -40; i <= 40; ++i) {
    for (int j = -40; j <= 40; ++j) {
      points.emplace_back(0.5 * i, 0.5 * j, 0.0);
      normals.emplace_back(0, 0, -1);
    }
  }
  for (int x = -2; x <= 2; ++x) {
    for (int y = -2; y <= 2; ++y) {
      if (x * x + y * y > 4) continue;
      points.emplace_back(0.5 * x, 0.5 * y, 3.0);
      normals.emplace_back(0, 0, 1);  // facing the plane: "inside" above it
    }
  }
  const Sampled sampled = CoverWithInner(points, normals, 0.5, 64.0);
  int below = 0;
  for (size_t k = sampled.covering.size(); k < sampled.all.size(); ++k) {
    const Eigen::Vector3d& c = sampled.all[k].center;
    EXPECT_LT(c.z(), 0.0) << "an inner support above the plane, at " << c.transpose();
    below += c.z() < 0;
  }
  EXPECT_GT(below, 0);
}

// A plate 4 × 4 × 0.4 sampled every 0.05 on both faces and its rim, exact
// points with inward normals. Inner supports of the supports on one face
// lie about a radius inside it, near or past the other face; as tet
// vertices they sample f and hide none of the covering's centres: every
// centre that is a vertex of the covering's regular triangulation is one
// with the inner supports added, and each inner support given a weight is
// a vertex unless another inner support hides it.
TEST(TetWeights, InnerSupportsHideNoCentreOfTheCovering) {
  std::vector<Eigen::Vector3d> points, normals;
  for (int i = -40; i <= 40; ++i) {
    for (int j = -40; j <= 40; ++j) {
      for (const double z : {0.0, -0.4}) {
        points.emplace_back(0.05 * i, 0.05 * j, z);
        normals.emplace_back(0, 0, z == 0 ? -1 : 1);
      }
    }
    for (int k = 1; k < 8; ++k) {
      for (const double side : {-2.0, 2.0}) {
        points.emplace_back(0.05 * i, side, -0.05 * k);
        normals.emplace_back(0, -side / 2, 0);
        if (std::abs(i) < 40) {
          points.emplace_back(side, 0.05 * i, -0.05 * k);
          normals.emplace_back(-side / 2, 0, 0);
        }
      }
    }
  }
  const Sampled sampled = CoverWithInner(points, normals, 0.05, 5.0);
  const size_t n = sampled.covering.size();
  ASSERT_GT(sampled.all.size(), n);
  const auto before = RegularTetrahedralization(sampled.covering, {});
  const auto after = RegularTetrahedralization(sampled.all, sampled.weights, {});
  ASSERT_TRUE(before.ok() && after.ok());
  std::vector<uint8_t> vertex(sampled.all.size(), 0);
  for (const int s : after->support) vertex[s] = 1;
  for (const int s : before->support) {
    EXPECT_TRUE(vertex[s]) << "covering centre " << sampled.all[s].center.transpose()
                           << " hidden";
  }
  int weighted = 0;
  for (size_t k = n; k < sampled.all.size(); ++k) {
    if (sampled.weights[k] < 0 || vertex[k]) {
      weighted += sampled.weights[k] >= 0;
      continue;
    }
    bool by_inner = false;
    for (size_t q = n; q < sampled.all.size(); ++q) {
      const double power = (sampled.all[k].center - sampled.all[q].center).squaredNorm() -
                           sampled.weights[q];
      by_inner = by_inner || (q != k && sampled.weights[q] >= 0 && power < -sampled.weights[k]);
    }
    EXPECT_TRUE(by_inner) << "inner support " << sampled.all[k].center.transpose() << " hidden";
  }
  EXPECT_GT(weighted, 0);
}

// ReconstructParams::sparse_support_points' default.
constexpr int kSparsePoints = 10;

// 27 small balls (r 0.5) in the solid x > 0 behind a wall x = 0, each
// holding the sparse count and reading the wall (inward normal +x).
void AddSolidBalls(std::vector<Support>* covering) {
  for (double x : {0.5, 1.5, 2.5}) {
    for (double y : {-1.0, 0.0, 1.0}) {
      for (double z : {0.5, 1.5, 2.5}) {
        Support s;
        s.center = Eigen::Vector3d(x, y, z);
        s.radius = 0.5;
        s.m = Eigen::Vector3d::UnitX();
        s.d = Eigen::Vector3d::Zero();
        s.point_count = kSparsePoints;
        covering->push_back(s);
      }
    }
  }
}

// A wall x = 0 (the solid at x > 0) sampled every 0.25 for y in [-5, 5],
// z in [0, 5]; nothing below z = 0 (an unseen bottom). Ball B is fitted
// from (2, 0, -2), in the empty space under the bottom: it grows to the
// largest radius allowed (the wall is exactly flat), reads the wall and its
// fit puts its own centre inside (g = 2). Small balls of radius 0.5 sample
// the solid above the bottom. B is the lowest centre, so on the hull: tied
// outside against f > 0. With weight r² it hides the small centres in its
// ball; with CoveringWeights it keeps its place on the hull and hides none.
TEST(CoveringWeights, AHullCentreTiedOutsideAgainstFHidesNothing) {
  const auto run = [](std::vector<double>* weight, int* hidden_before,
                      int* hidden_after, bool* big_on_hull) {
    std::vector<Eigen::Vector3d> points, normals;
    for (int i = -20; i <= 20; ++i) {
      for (int k = 0; k <= 20; ++k) {
        points.emplace_back(0.0, 0.25 * i, 0.25 * k);
        normals.emplace_back(1, 0, 0);
      }
    }
    const mesh_internal::PointIndex index(points);
    const FitInput in{points, normals, index, 0.01, 6.0};
    std::vector<Support> covering = {FitSupport(Eigen::Vector3d(2, 0, -2), 0.0, in)};
    AddSolidBalls(&covering);
    const PuFunction f(covering);
    const std::vector<double> radius2 = RadiiSquared(covering);
    const auto before = RegularTetrahedralization(covering, TetWeights(covering, radius2), {});
    ASSERT_TRUE(before.ok());
    *weight = CoveringWeights(covering, *before, f, kSparsePoints, in);
    const auto after = RegularTetrahedralization(covering, TetWeights(covering, *weight), {});
    ASSERT_TRUE(after.ok());
    *hidden_before = static_cast<int>(covering.size() - before->support.size());
    *hidden_after = static_cast<int>(covering.size() - after->support.size());
    *big_on_hull = after->support[0] == 0 && after->on_hull[0];
    EXPECT_GT(f(covering[0].center), 0.0);
  };
  std::vector<double> weight;
  int hidden_before = 0, hidden_after = 0;
  bool big_on_hull = false;
  run(&weight, &hidden_before, &hidden_after, &big_on_hull);
  EXPECT_GT(hidden_before, 0);
  EXPECT_EQ(weight[0], 0.0);
  EXPECT_EQ(hidden_after, 0);
  EXPECT_TRUE(big_on_hull);
  // The small balls on the hull read f > 0 too; the others keep r².
  for (size_t i = 1; i < weight.size(); ++i) EXPECT_TRUE(weight[i] == 0.0 || weight[i] == 0.25);
}

// A seen wall x = 0 (the solid at x > 0) sampled by small balls (r 0.5) in
// the solid, and one ball B in the empty space in front of it, centre
// (-3, 0, 1), grown until it held a handful of points at the wall's edge
// (z ≈ 0). Their plane, tilted by the noise over their small spread, is
// here z = 0 with the solid above it: B's fit puts its own centre inside
// (g = +1), on the wrong side of the seen wall.
// B is the only centre at x < 0, so on the hull. With fewer points than the
// sparse count its reading is no evidence against the hull's tie: it keeps
// r² (so its power cell keeps the empty space in front of the wall
// outside); holding the sparse count, the same reading gets weight 0.
// Points of the wall x = 0 sampled every 0.25 for y in [-5, 5], z in
// [-2, 5], their inward normals `normal` (+x: the solid at x > 0).
std::vector<Eigen::Vector3d> WallPoints() {
  std::vector<Eigen::Vector3d> points;
  for (int i = -20; i <= 20; ++i) {
    for (int k = -8; k <= 20; ++k) points.emplace_back(0.0, 0.25 * i, 0.25 * k);
  }
  return points;
}

struct Wall {
  explicit Wall(const Eigen::Vector3d& normal)
      : points(WallPoints()), normals(points.size(), normal), index(points) {}
  std::vector<Eigen::Vector3d> points, normals;
  mesh_internal::PointIndex index;
  FitInput in{points, normals, index, 0.01, 6.0};
};

// The covering weight of ball `b` with the solid balls round it, after
// checking that f reads b's centre inside and that b is a hull vertex of
// the tetrahedralization (the case CoveringWeights decides); -1 if the
// tetrahedralization fails.
double HullBallWeight(const Support& b, const FitInput& in) {
  std::vector<Support> covering = {b};
  AddSolidBalls(&covering);
  const PuFunction f(covering);
  EXPECT_GT(f(b.center), 0.0);
  const auto tets =
      RegularTetrahedralization(covering, TetWeights(covering, RadiiSquared(covering)), {});
  EXPECT_TRUE(tets.ok());
  if (!tets.ok()) return -1.0;
  bool b_on_hull = false;
  for (size_t v = 0; v < tets->support.size(); ++v) {
    b_on_hull = b_on_hull || (tets->support[v] == 0 && tets->on_hull[v]);
  }
  EXPECT_TRUE(b_on_hull);
  return CoveringWeights(covering, *tets, f, kSparsePoints, in)[0];
}

TEST(CoveringWeights, AHullBallHoldingFewerThanTheSparseCountKeepsItsWeight) {
  const Wall wall(Eigen::Vector3d::UnitX());
  const auto weight_of_b = [&wall](int point_count) {
    Support b;
    b.center = Eigen::Vector3d(-3, 0, 1);
    b.radius = 3.2;
    b.m = Eigen::Vector3d::UnitZ();  // inward: its fit has the solid above z = 0
    b.d = Eigen::Vector3d::Zero();
    b.point_count = point_count;
    return HullBallWeight(b, wall.in);
  };
  EXPECT_EQ(weight_of_b(kMinFitPoints), 3.2 * 3.2);
  EXPECT_EQ(weight_of_b(kSparsePoints), 0.0);
}

// A plate seen from one side only: its near face x = 0 (the solid at x > 0,
// inward normal +x) is sampled, its far face is not. Ball B grew in the
// empty space beyond the far face, centre (6, 0, 1), until it reached the
// near face through the solid: a handful of points at its rim, all facing
// away from its centre (the centre straight behind their tangent plane).
// Its fit reads the centre inside (g = 6), and so does every point's own
// normal: it gets weight 0 at fewer points than the sparse count (with r²
// its power cell would take in the plate). If the points' normals were
// tilted so that the centre lay 75° off them, still behind their tangent
// plane, a normal error of 15° could flip that reading: B keeps r².
TEST(CoveringWeights, ASparseHullBallEveryPointSeesFromInsideGetsWeightZero) {
  const auto weight_of_b = [](const Eigen::Vector3d& point_normal) {
    const Wall wall(point_normal);
    Support b;
    b.center = Eigen::Vector3d(6, 0, 1);
    b.radius = 6.015;
    b.m = Eigen::Vector3d::UnitX();
    b.d = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : wall.points) b.point_count += (p - b.center).norm() < b.radius;
    EXPECT_GE(b.point_count, 3);
    EXPECT_LT(b.point_count, kSparsePoints);
    return HullBallWeight(b, wall.in);
  };
  EXPECT_EQ(weight_of_b(Eigen::Vector3d::UnitX()), 0.0);
  const double tilt = 75.0 * M_PI / 180.0;
  EXPECT_EQ(weight_of_b(Eigen::Vector3d(std::cos(tilt), 0.0, std::sin(tilt))), 6.015 * 6.015);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
