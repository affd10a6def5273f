#include "reconstruct/outliers.h"

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

struct Grid {
  std::vector<Eigen::Vector3d> points, normals;
};

// A 20 × 20 grid on z = 0 (spacing 1, normals +z) and the extra points.
Grid PlaneWith(const std::vector<Eigen::Vector3d>& extra) {
  Grid g;
  for (int x = 0; x < 20; ++x) {
    for (int y = 0; y < 20; ++y) {
      g.points.emplace_back(x, y, 0.0);
      g.normals.emplace_back(0, 0, 1);
    }
  }
  for (const auto& p : extra) {
    g.points.push_back(p);
    g.normals.emplace_back(0, 0, 1);
  }
  return g;
}

std::vector<uint8_t> Flags(const Grid& g) {
  const mesh_internal::PointIndex index(g.points);
  return OutlierFlags(g.points, g.normals, index, MeanNeighborDistances(g.points, index), 10,
                      /*isolated_distance=*/2.0 * 1.2, /*off_surface_distance=*/1.0);
}

TEST(OutlierFlags, FlagIsolatedAndOffSurfacePointsOnly) {
  const Grid g = PlaneWith({{10.2, 10.3, 9.0}, {5.5, 5.5, 1.8}, {12.3, 4.6, 0.2}});
  const auto flags = Flags(g);
  EXPECT_EQ(flags[400], 1);  // far above the plane: isolated
  EXPECT_EQ(flags[401], 1);  // 1.8 above: off the surface
  EXPECT_EQ(flags[402], 0);  // 0.2 above: noise
  int flagged = 0;
  for (int i = 0; i < 400; ++i) flagged += flags[i];
  EXPECT_EQ(flagged, 0);
}

TEST(OutlierFlags, FlagNormalsAgainstTheirNeighbours) {
  Grid g = PlaneWith({});
  g.normals[210] = Eigen::Vector3d(1, 0, 0.2).normalized();
  g.normals[230] = -g.normals[230];
  const auto flags = Flags(g);
  EXPECT_EQ(flags[210], 1);
  EXPECT_EQ(flags[230], 1);
  EXPECT_EQ(flags[250], 0);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
