#include <algorithm>
#include <cmath>
#include <stop_token>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "cad_shapes.h"
#include "meshseg/remesh.h"

namespace meshseg {
namespace {

Mesh CadCylinderMesh() {
  return testing::MeshOf(testing::CadCylinder(10.0, 40.0, 48), "cad_cylinder");
}

// Distance from p to the plane of the side facet (of `segments` around the z
// axis, the first starting at angle 0) whose angle p falls in.
double DistanceToSideFacet(const Eigen::Vector3d& p, int segments, double radius) {
  const double step = 2.0 * std::numbers::pi / segments;
  double t = std::atan2(p.y(), p.x());
  if (t < 0) t += 2.0 * std::numbers::pi;
  const double mid = (std::floor(t / step) + 0.5) * step;
  const double apothem = radius * std::cos(step / 2.0);
  return std::abs(p.x() * std::cos(mid) + p.y() * std::sin(mid) - apothem);
}

// Distance from p to the tessellated cylinder's surface (side facets or caps);
// exact for points on the side facets and caps, which is all we test.
double DistanceToFacets(const Eigen::Vector3d& p, int segments, double radius, double height) {
  const double z_gap = std::min(std::abs(p.z()), std::abs(p.z() - height));
  return std::min(z_gap, DistanceToSideFacet(p, segments, radius));
}

TEST(IsotropicRemesh, GivesNearEquilateralTrianglesOnTheInputSurface) {
  const Mesh mesh = CadCylinderMesh();
  const double target = 1.0;
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(mesh, target);
  ASSERT_TRUE(fine.ok()) << fine.status();
  const TriMesh& tri = fine->tri;
  EXPECT_GT(tri.n_faces(), 10 * mesh.tri.n_faces());
  EXPECT_NEAR(MeanEdgeLength(tri), target, 0.25 * target);
  int thin = 0;
  double area = 0.0;
  for (const auto f : tri.faces()) {
    double longest = 0.0;
    for (const auto e : tri.fe_range(f)) longest = std::max(longest, tri.calc_edge_length(e));
    const double a = tri.calc_face_area(f);
    area += a;
    if (longest * longest > kThinAspect * 2.0 * a) ++thin;
  }
  EXPECT_LT(thin, 0.01 * tri.n_faces());
  // Closed, and every vertex on the input facets (projected back by CGAL).
  for (const auto e : tri.edges()) ASSERT_FALSE(tri.is_boundary(e));
  double worst = 0.0;
  for (const auto v : tri.vertices()) {
    worst = std::max(worst, DistanceToFacets(ToEigen(tri.point(v)), 48, 10.0, 40.0));
  }
  EXPECT_LT(worst, 1e-6);
  double input_area = 0.0;
  for (const auto f : mesh.tri.faces()) input_area += mesh.tri.calc_face_area(f);
  EXPECT_NEAR(area, input_area, 1e-3 * input_area);
}

TEST(IsotropicRemesh, KeepsTheSharpRimsAsEdges) {
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(CadCylinderMesh(), 1.0);
  ASSERT_TRUE(fine.ok()) << fine.status();
  // The 90-degree rims stay polylines of mesh edges: every rim corner of the
  // input is still a vertex, and no face straddles a rim (all three corners
  // of a face are on one side of z = 0+ / z = 40-).
  const TriMesh& tri = fine->tri;
  for (const auto f : tri.faces()) {
    int on_bottom = 0, on_top = 0, inside = 0;
    for (const auto v : tri.fv_range(f)) {
      const double z = tri.point(v)[2];
      if (z < 1e-9) ++on_bottom;
      else if (z > 40.0 - 1e-9) ++on_top;
      else ++inside;
    }
    // A face of a cap has all three corners on it; a side face touches a
    // cap with at most one edge (two corners).
    EXPECT_FALSE(inside > 0 && on_bottom == 3);
    EXPECT_LE(on_bottom + on_top, 3);
    if (inside > 0) {
      EXPECT_LE(on_bottom, 2);
      EXPECT_LE(on_top, 2);
    }
  }
  int rim_corners_kept = 0;
  for (const auto v : tri.vertices()) {
    const auto p = tri.point(v);
    const double r = std::hypot(p[0], p[1]);
    const double t = std::atan2(p[1], p[0]) / (2.0 * std::numbers::pi / 48);
    if (std::abs(r - 10.0) < 1e-9 && std::abs(t - std::round(t)) < 1e-9 &&
        (p[2] < 1e-9 || p[2] > 40.0 - 1e-9)) {
      ++rim_corners_kept;
    }
  }
  EXPECT_EQ(rim_corners_kept, 2 * 48);
}

// Mean length of the edges of `tri` whose both ends satisfy `where`.
template <typename Where>
double MeanEdgeLengthWhere(const TriMesh& tri, Where where) {
  double sum = 0.0;
  int count = 0;
  for (const auto e : tri.edges()) {
    const auto h = tri.halfedge_handle(e, 0);
    const Eigen::Vector3d a = ToEigen(tri.point(tri.from_vertex_handle(h)));
    const Eigen::Vector3d b = ToEigen(tri.point(tri.to_vertex_handle(h)));
    if (!where(a) || !where(b)) continue;
    sum += (b - a).norm();
    ++count;
  }
  EXPECT_GT(count, 0);
  return sum / std::max(count, 1);
}

TEST(IsotropicRemesh, RemeshesFinerAroundASmallHole) {
  // A hole of r = 2.5 at edges of 1.5 would get 10 edges around; the second
  // pass gives it edges of r / 4, while the rest of the plate keeps 1.5.
  const double radius = 2.5, thickness = 6.0, target = 1.5;
  const testing::CadShape shape = testing::CadPlateWithHole(20.0, thickness, radius, 24);
  RemeshStats stats;
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(testing::MeshOf(shape), target, {}, {}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  EXPECT_NEAR(stats.small_feature_radius, radius, 0.01 * radius);
  EXPECT_NEAR(stats.fine_edge_length, radius / 4.0, 0.01 * radius);
  const auto on_wall = [&](const Eigen::Vector3d& p) {
    return std::hypot(p.x(), p.y()) < radius + 1e-6;
  };
  const auto far_out = [&](const Eigen::Vector3d& p) {
    return std::hypot(p.x(), p.y()) > radius + 3.0 * kZoneMargin * target;
  };
  EXPECT_NEAR(MeanEdgeLengthWhere(fine->tri, on_wall), radius / 4.0, 0.25 * radius / 4.0);
  EXPECT_NEAR(MeanEdgeLengthWhere(fine->tri, far_out), target, 0.25 * target);
  // The wall's new vertices lie on the input's facets, the rims' too, not on
  // the first pass's chords (sagitta 0.11 for its edges of 1.5).
  double worst = 0.0;
  int on_the_wall = 0;
  for (const auto v : fine->tri.vertices()) {
    const Eigen::Vector3d p = ToEigen(fine->tri.point(v));
    if (!on_wall(p)) continue;
    ++on_the_wall;
    worst = std::max(worst, DistanceToSideFacet(p, 24, radius));
  }
  EXPECT_GT(on_the_wall, 200);
  EXPECT_LT(worst, 1e-6);
}

TEST(IsotropicRemesh, RemeshesUniformlyWhenToldNotToRefine) {
  const Mesh mesh = testing::MeshOf(testing::CadPlateWithHole(20.0, 6.0, 2.5, 24));
  RemeshParams params;
  params.small_radius_edges = 0.0;
  RemeshStats stats;
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(mesh, 1.5, params, {}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  EXPECT_EQ(stats.fine_edge_length, 0.0);
  const double wall = MeanEdgeLengthWhere(
      fine->tri, [](const Eigen::Vector3d& p) { return std::hypot(p.x(), p.y()) < 2.5 + 1e-6; });
  EXPECT_GT(wall, 1.0);
}

TEST(IsotropicRemesh, RejectsANonPositiveTarget) {
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(CadCylinderMesh(), 0.0);
  ASSERT_EQ(fine.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(fine.status().message().find("cad_cylinder"), std::string::npos);
  EXPECT_NE(fine.status().message().find("got 0"), std::string::npos);
}

TEST(IsotropicRemesh, StopsWhenCancelled) {
  std::stop_source stop;
  stop.request_stop();
  const absl::StatusOr<Mesh> fine = IsotropicRemesh(CadCylinderMesh(), 1.0, {}, {.stop = stop.get_token(), .on_progress = {}});
  EXPECT_EQ(fine.status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg
