#include "reconstruct/project_to_points.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kSpacing = 0.5;
constexpr double kRadius = 2.5 * kSpacing;  // the ReconstructParams default

// Points on z = 0 at kSpacing over [-10, 10]², none within `hole` of the
// origin, z perturbed by Gaussian noise of `noise` × kSpacing.
std::vector<Eigen::Vector3d> PlanePoints(double noise, double hole) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points;
  for (double x = -10; x <= 10; x += kSpacing) {
    for (double y = -10; y <= 10; y += kSpacing) {
      if (std::hypot(x, y) < hole) continue;
      points.emplace_back(x, y, noise * kSpacing * g(rng));
    }
  }
  return points;
}

TriMesh VerticesAt(const std::vector<Eigen::Vector3d>& at) {
  TriMesh mesh;
  for (const auto& p : at) mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z()));
  return mesh;
}

// A vertex 0.6 spacings off a plane sampled with noise 0.2 spacings lands on
// the plane to within the noise averaged over the ~10 points the Gaussian
// weights count (0.2 / √10 ≈ 0.06 spacings rms).
TEST(ProjectToPoints, AveragesTheNoiseOfAPlane) {
  const std::vector<Eigen::Vector3d> points = PlanePoints(0.2, 0.0);
  const mesh_internal::PointIndex index(points);
  std::vector<Eigen::Vector3d> at;
  for (double x = -5; x <= 5; x += 0.7) {
    for (double y = -5; y <= 5; y += 0.7) at.emplace_back(x, y, 0.3);
  }
  TriMesh mesh = VerticesAt(at);
  ProjectToPoints(points, index, kRadius, 3, &mesh);
  double sum2 = 0.0, worst = 0.0;
  for (const auto v : mesh.vertices()) {
    const double z = mesh.point(v)[2];
    sum2 += z * z;
    worst = std::max(worst, std::abs(z));
  }
  const double rms = std::sqrt(sum2 / static_cast<double>(mesh.n_vertices()));
  EXPECT_LT(rms, 0.1 * kSpacing);
  EXPECT_LT(worst, 0.3 * kSpacing);
}

// No points within the radius (a hole of radius 6 spacings in the scan): the
// nearest kMinProjectionPoints, on the rim within kFallbackReach radii, still
// give the plane.
TEST(ProjectToPoints, AVertexOverAHoleUsesTheNearestPoints) {
  const std::vector<Eigen::Vector3d> points = PlanePoints(0.0, 3.0);
  const mesh_internal::PointIndex index(points);
  TriMesh mesh = VerticesAt({{0.2, -0.1, 0.8}});
  ProjectToPoints(points, index, kRadius, 3, &mesh);
  const auto p = mesh.point(TriMesh::VertexHandle(0));
  EXPECT_NEAR(p[2], 0.0, 1e-9);
  EXPECT_NEAR(p[0], 0.2, 1e-9);  // moved along the normal only
  EXPECT_NEAR(p[1], -0.1, 1e-9);
}

// An occlusion gap: the nearest points are over kFallbackReach radii away
// (hole radius 10 spacings = 4 radii), so the vertex stays where it is.
TEST(ProjectToPoints, AVertexFarFromEveryPointStaysWhereItIs) {
  const std::vector<Eigen::Vector3d> points = PlanePoints(0.0, 5.0);
  const mesh_internal::PointIndex index(points);
  TriMesh mesh = VerticesAt({{0.2, -0.1, 0.8}});
  ProjectToPoints(points, index, kRadius, 3, &mesh);
  EXPECT_EQ(mesh.point(TriMesh::VertexHandle(0)), TriMesh::Point(0.2, -0.1, 0.8));
}

// On a sphere of radius R the fitted planes are secants: the projection lands
// inside by the sag of the weighted disc, ⟨d²⟩ / 2R = radius² / 8R (0.04 =
// 0.08 spacings here; 0.05 mm on the 8 mm bore of the test piece at h 0.68),
// give or take what the clumps and gaps of random samples add.
TEST(ProjectToPoints, LandsOnASphereWithinItsSag) {
  constexpr double kR = 5.0;
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  const int count = static_cast<int>(4 * M_PI * kR * kR / (kSpacing * kSpacing));
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    points.push_back(kR * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  const mesh_internal::PointIndex index(points);
  std::vector<Eigen::Vector3d> at;
  for (int i = 0; i < 50; ++i) {
    const double r = kR + (i % 2 ? 0.4 : -0.4);
    at.push_back(r * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  TriMesh mesh = VerticesAt(at);
  ProjectToPoints(points, index, kRadius, 3, &mesh);
  for (const auto v : mesh.vertices()) {
    EXPECT_NEAR(ToEigen(mesh.point(v)).norm(), kR - kRadius * kRadius / (8 * kR), 0.08 * kSpacing)
        << "vertex " << v.idx();
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
