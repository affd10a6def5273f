#include "reconstruct/refine.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/curvature/test_meshes.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kRadius = 1.0;
constexpr int kPoints = 20000;

double Spacing() { return std::sqrt(4 * M_PI * kRadius * kRadius / kPoints); }

// What marching tetrahedra gives, roughly: an icosahedron on the sphere, its
// faces split in four 3 times (edges of 5 point spacings), every vertex moved
// off the sphere by up to half a spacing.
Mesh CoarseSphere() {
  absl::StatusOr<Mesh> mesh = testing::MakeSphere(kRadius, 3);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> off(-0.5 * Spacing(), 0.5 * Spacing());
  for (const auto v : mesh->tri.vertices()) {
    mesh->tri.set_point(v, mesh->tri.point(v) * (1.0 + off(rng) / kRadius));
  }
  mesh->tri.update_normals();
  return *std::move(mesh);
}

std::vector<Eigen::Vector3d> SpherePoints() {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < kPoints; ++i) {
    points.push_back(kRadius * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  return points;
}

// The coarse sphere becomes a fine one on the points: every vertex within the
// sag of the projection (radius² / 8R, see project_to_points_test) plus 0.1 h,
// edges of about refine_edge_length spacings, the same closed genus-0 surface.
TEST(RefineOnPoints, TurnsACoarseMeshIntoAFineOneOnThePoints) {
  const std::vector<Eigen::Vector3d> points = SpherePoints();
  const PointIndex index(points);
  const double h = Spacing();
  const ReconstructParams params;
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine =
      RefineOnPoints(CoarseSphere(), points, index, h, params, {}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  const TriMesh& m = fine->tri;
  EXPECT_DOUBLE_EQ(stats.refine_edge_length, params.refine_edge_length * h);
  const double edge = MeanEdgeLength(m) / h;
  EXPECT_GT(edge, 1.2);
  EXPECT_LT(edge, 1.8);
  const double r = params.projection_radius * h;
  for (const auto v : m.vertices()) {
    ASSERT_NEAR(ToEigen(m.point(v)).norm(), kRadius - r * r / (8 * kRadius), 0.1 * h)
        << "vertex " << v.idx();
  }
  EXPECT_EQ(static_cast<int64_t>(m.n_vertices()) - static_cast<int64_t>(m.n_edges()) +
                static_cast<int64_t>(m.n_faces()),
            2);
  for (const auto e : m.edges()) ASSERT_FALSE(m.is_boundary(e));
}

TEST(RefineOnPoints, MaxFacesLengthensTheEdges) {
  constexpr int64_t kMaxFaces = 2000;
  const std::vector<Eigen::Vector3d> points = SpherePoints();
  const PointIndex index(points);
  const double h = Spacing();
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine = RefineOnPoints(
      CoarseSphere(), points, index, h, {.refine_max_faces = kMaxFaces}, {}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  EXPECT_GT(stats.refine_edge_length, 1.5 * h);
  // CGAL keeps edges within 4/5 and 4/3 of the target, so the count is about,
  // not at most, the cap.
  EXPECT_GT(fine->tri.n_faces(), 0.5 * kMaxFaces);
  EXPECT_LT(fine->tri.n_faces(), 1.5 * kMaxFaces);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
