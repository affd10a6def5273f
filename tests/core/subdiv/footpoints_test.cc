#include "subdiv/footpoints.h"

#include "shapes.h"

namespace meshseg::subdiv_internal {
namespace {

TEST(ClosestBarycentric, CoversInteriorEdgesAndCorners) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_TRUE(
      ClosestBarycentric({0.5, 0.5, 3}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.25, 0.25)));
  EXPECT_TRUE(ClosestBarycentric({1, -1, 0}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(ClosestBarycentric({2, 2, 0}, a, b, c).isApprox(Eigen::Vector3d(0, 0.5, 0.5)));
  EXPECT_TRUE(ClosestBarycentric({-1, -1, 1}, a, b, c).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(ClosestBarycentric({3, -1, 0}, a, b, c).isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(ClosestBarycentric({-1, 3, 0}, a, b, c).isApprox(Eigen::Vector3d(0, 0, 1)));
}

TEST(FootPoints, MatchesBruteForceOnASphere) {
  const testing::Triangles sphere = testing::UnitIcosphere(3);
  std::vector<Eigen::Vector3d> data;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d dir(std::sin(i * 1.7), std::cos(i * 2.3), std::sin(i * 0.61 + 1));
    data.push_back(dir.normalized() * (1.0 + 0.02 * std::sin(i * 5.1)));
  }
  const std::vector<FootPoint> feet = FootPoints(sphere.vertices, sphere.faces, data);
  ASSERT_EQ(feet.size(), data.size());
  for (size_t i = 0; i < data.size(); ++i) {
    double best = 1e300;
    for (const auto& f : sphere.faces) {
      const auto& v = sphere.vertices;
      const Eigen::Vector3d w = ClosestBarycentric(data[i], v[f[0]], v[f[1]], v[f[2]]);
      best = std::min(best, (w[0] * v[f[0]] + w[1] * v[f[1]] + w[2] * v[f[2]] - data[i]).norm());
    }
    EXPECT_NEAR(feet[i].distance, best, 1e-12) << "point " << i;
  }
}

}  // namespace
}  // namespace meshseg::subdiv_internal
