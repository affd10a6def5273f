#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "test_meshes.h"

namespace meshseg {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(EstimateCurvature, SphereCurvatureIsOneOverRadius) {
  constexpr double kRadius = 10.0;
  // A quadratic over W2 = 5 edges overestimates curvature by ~(5 l / R)^2 / 4.
  constexpr double kRelTol = 0.02;  // of 1/R, with R ~ 20 l
  auto mesh = testing::MakeSphere(kRadius, 5);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  for (std::size_t v = 0; v < field->kappa_max.size(); ++v) {
    ASSERT_FALSE(field->sharp[v]) << "vertex " << v;
    // Outward normal: the sphere bends away from it, kappa = -1/R.
    EXPECT_NEAR(field->kappa_max[v], -1.0 / kRadius, kRelTol / kRadius) << "vertex " << v;
    EXPECT_NEAR(field->kappa_min[v], -1.0 / kRadius, kRelTol / kRadius) << "vertex " << v;
    const Eigen::Vector3d radial = ToEigen(mesh->tri.point(TriMesh::VertexHandle(v))).normalized();
    EXPECT_GT(field->smooth_normal[v].dot(radial), std::cos(0.5 * kPi / 180.0)) << "vertex " << v;
  }
}

TEST(EstimateCurvature, CylinderHasOneZeroCurvatureAlongTheAxis) {
  constexpr double kRadius = 5.0;
  constexpr double kLength = 20.0;
  constexpr double kTol = 0.03;  // of 1/R
  auto mesh = testing::MakeGrid(128, 81, [&](double s, double t) {  // R ~ 20 l
    const double a = 2.0 * kPi * s * 127.0 / 128.0;
    return Eigen::Vector3d(kRadius * std::cos(a), kRadius * std::sin(a), kLength * t);
  }, "cylinder");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  int checked = 0;
  for (std::size_t v = 0; v < field->kappa_max.size(); ++v) {
    const Eigen::Vector3d p = ToEigen(mesh->tri.point(TriMesh::VertexHandle(v)));
    const double a = std::atan2(p.y(), p.x());
    // Stay away from the open ends and the open seam.
    if (p.z() < 5.0 || p.z() > 15.0 || std::abs(a) < 0.8 || kPi - std::abs(a) < 0.8) continue;
    ++checked;
    EXPECT_NEAR(std::abs(field->kappa_max[v]), 1.0 / kRadius, kTol / kRadius) << "vertex " << v;
    EXPECT_NEAR(field->kappa_min[v], 0.0, kTol / kRadius) << "vertex " << v;
    EXPECT_LT(std::abs(field->dir_max[v].z()), 0.05) << "vertex " << v;
    EXPECT_FALSE(field->sharp[v]) << "vertex " << v;
  }
  EXPECT_GT(checked, 2000);
}

TEST(EstimateCurvature, FoldLineOfALShapeIsSharp) {
  // Two 10 x 10 planes meeting at a right angle along the y axis, edge 0.5.
  auto mesh = testing::MakeGrid(41, 21, [](double s, double t) {
    const double x = 20.0 * s - 10.0;
    return x <= 0.0 ? Eigen::Vector3d(x, 10.0 * t, 0.0) : Eigen::Vector3d(0.0, 10.0 * t, x);
  }, "l_shape");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  for (std::size_t v = 0; v < field->sharp.size(); ++v) {
    const Eigen::Vector3d p = ToEigen(mesh->tri.point(TriMesh::VertexHandle(v)));
    const double from_fold = p.x() < 0.0 ? -p.x() : p.z();
    if (p.y() < 1.0 || p.y() > 9.0) continue;
    if (from_fold < 1e-9) {
      EXPECT_TRUE(field->sharp[v]) << "fold vertex " << v;
    }
    if (from_fold > 2.6 && from_fold < 8.0) {
      EXPECT_FALSE(field->sharp[v]) << "vertex " << v << " at " << from_fold;
      EXPECT_NEAR(field->kappa_max[v], 0.0, 1e-6) << "vertex " << v;
    }
  }
}

TEST(EstimateCurvature, RejectsBadParams) {
  auto mesh = testing::MakeSphere(1.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  auto field = EstimateCurvature(*mesh, {.w1 = 3.0, .w2 = 2.0, .sharp_threshold = {}});
  EXPECT_EQ(field.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(field.status().message()), ::testing::HasSubstr("w2"));
}

TEST(EstimateCurvature, StopsWhenCancelled) {
  auto mesh = testing::MakeSphere(1.0, 2);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  std::stop_source stop;
  stop.request_stop();
  auto field = EstimateCurvature(*mesh, {}, RunContext{.stop = stop.get_token(), .on_progress = {}});
  EXPECT_EQ(field.status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg
