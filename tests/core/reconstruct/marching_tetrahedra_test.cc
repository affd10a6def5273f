#include "reconstruct/marching_tetrahedra.h"

#include <map>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "grid_supports.h"
#include "reconstruct/graph_cut.h"

namespace meshseg::reconstruct_internal {
namespace {

TEST(MarchingTetrahedra, SphereFieldGivesAClosedOrientedSurfaceOnTheZeroSet) {
  const auto supports = test::GridSupports(11, 2.0);
  const PuFunction pu(supports);
  const TetMesh tets = *RegularTetrahedralization(supports, {});
  std::vector<Eigen::Vector3d> position;
  std::vector<double> f;
  for (const int s : tets.support) {
    position.push_back(supports[s].center);
    f.push_back(pu(supports[s].center));
  }
  const auto inside = SignLabels(tets, f);
  const std::vector<uint8_t> sparse(position.size(), 0);
  const auto surface = MarchingTetrahedra(tets, position, f, inside, sparse, pu, {});
  ASSERT_TRUE(surface.ok()) << surface.status();
  ASSERT_FALSE(surface->triangles.empty());
  // On the zero set of f, which is near the unit sphere.
  double worst = 0.0;
  for (const auto& v : surface->vertices) worst = std::max(worst, std::abs(pu(v)));
  EXPECT_LT(worst, 0.02);
  for (const auto& v : surface->vertices) EXPECT_NEAR(v.norm(), 1.0, 0.1);
  for (const uint8_t s : surface->to_smooth) EXPECT_EQ(s, 0);
  // Closed: every edge is used once in each direction.
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : surface->triangles) {
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  // Oriented outward: positive signed volume.
  double volume = 0.0;
  for (const auto& t : surface->triangles) {
    volume +=
        surface->vertices[t[0]].dot(surface->vertices[t[1]].cross(surface->vertices[t[2]])) / 6;
  }
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI, 0.4);
}

// The orientation of each triangle comes from its tet's vertex order, not
// from its coordinates. Points that are coplanar in exact arithmetic but not
// after rounding (a tilted grid: p = o + i u + j v in doubles) make tets of
// almost no volume; the exact predicates still order each one positively,
// while a floating-point side test on its edge midpoints can come out either
// way, so one triangle would run against its neighbours (an edge traversed
// twice the same way: a non-manifold mesh). Every labelling must give a
// closed surface with each edge traversed once each way.
TEST(MarchingTetrahedra, NearlyFlatTetsGiveTrianglesOrientedLikeTheirNeighbours) {
  const Eigen::Vector3d origin(0.3407288825617591, -7.970800255012037, -11.44618516366402);
  const Eigen::Vector3d u = Eigen::Vector3d(-17.78, 0.0, 2.54).normalized() * 3.1;
  const Eigen::Vector3d v = Eigen::Vector3d(0.1, 1.0, 0.7 / 7.0).normalized() * 2.3;
  const Eigen::Vector3d normal = u.cross(v).normalized();
  std::vector<reconstruct_internal::Support> supports;
  const auto add = [&](const Eigen::Vector3d& c) {
    supports.emplace_back();
    supports.back().center = c;
    supports.back().radius = 1.0;
  };
  for (int i = -3; i <= 3; ++i) {
    for (int j = -3; j <= 3; ++j) add(origin + i * u + j * v);
  }
  // Off the plane on both sides, so the grid's points are interior vertices.
  for (int i = -4; i <= 4; i += 2) {
    for (int j = -4; j <= 4; j += 2) {
      add(origin + i * u + j * v + 5.0 * normal);
      add(origin + i * u + j * v - 5.0 * normal);
    }
  }
  const std::vector<double> zero(supports.size(), 0.0);
  const auto tets = RegularTetrahedralization(supports, zero, {});
  ASSERT_TRUE(tets.ok()) << tets.status();
  std::vector<Eigen::Vector3d> position;
  for (const int s : tets->support) position.push_back(supports[s].center);
  const PuFunction pu(test::GridSupports(3, 1.0));
  const std::vector<uint8_t> sparse(position.size(), 0);
  std::mt19937 rng(7);
  int64_t checked_triangles = 0;
  for (int draw = 0; draw < 200; ++draw) {
    // A random labelling; f of one sign, so no vertex needs f's zero.
    std::vector<uint8_t> inside(position.size());
    for (size_t k = 0; k < inside.size(); ++k) inside[k] = !tets->on_hull[k] && rng() % 2;
    const std::vector<double> f(position.size(), 1.0);
    const auto surface = MarchingTetrahedra(*tets, position, f, inside, sparse, pu, {});
    ASSERT_TRUE(surface.ok()) << surface.status();
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : surface->triangles) {
      for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
    }
    for (const auto& [e, count] : directed) {
      ASSERT_EQ(count, 1) << "draw " << draw << ": edge " << e.first << "-" << e.second
                          << " traversed " << count << " times the same way";
      ASSERT_EQ(directed.count({e.second, e.first}), 1u)
          << "draw " << draw << ": edge " << e.first << "-" << e.second << " open";
    }
    checked_triangles += static_cast<int64_t>(surface->triangles.size());
  }
  EXPECT_GT(checked_triangles, 0);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
