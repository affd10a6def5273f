// FitBsplineSurface: a noisy paraboloid patch of a quadric region comes back
// as a B-spline within the noise of the true surface; a region that turns
// too far for a height field is refused with the reason.
#include "brep/bspline_surface_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;
using ::testing::HasSubstr;

constexpr double kSpacing = 0.5;  // mesh edge length l_avg
constexpr double kSigma = 0.01;   // noise along z

// z = a (x^2 + y^2) as a Region of type quadric with its vertices and faces.
struct Patch {
  Region region;
  RegionSamples samples;
};

Patch Paraboloid(double a) {
  Patch p;
  p.region.type = SurfaceType::kQuadric;
  Quadric q;
  q.c[0] = a;
  q.c[1] = a;
  q.c[8] = -1.0;
  p.region.surface = q;
  p.region.rms_distance = kSigma;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, kSigma);
  for (double x = -10.0; x <= 10.0; x += kSpacing) {
    for (double y = -8.0; y <= 8.0; y += kSpacing) {
      p.samples.points.emplace_back(x, y, a * (x * x + y * y) + noise(rng));
      if (p.samples.face_normals.size() < kMaxFaceSamples) {
        p.samples.face_centroids.push_back(p.samples.points.back());
        p.samples.face_normals.push_back(Vector3d(-2 * a * x, -2 * a * y, 1.0).normalized());
      }
    }
  }
  return p;
}

TEST(FitBsplineSurface, ParaboloidPatchWithinTheNoise) {
  const double a = 0.02;
  const Patch p = Paraboloid(a);
  const BsplineSurfaceFit fit = FitBsplineSurface(p.region, p.samples, kSpacing, kSigma);
  ASSERT_FALSE(fit.surface.IsNull()) << fit.failure;
  EXPECT_LE(fit.rms_distance, 2.0 * kSigma);
  // Inside the patch the spline lies on the paraboloid within the noise.
  for (double x = -9.0; x <= 9.0; x += 1.5) {
    for (double y = -7.0; y <= 7.0; y += 1.5) {
      const Vector3d truth(x, y, a * (x * x + y * y));
      const std::optional<SurfacePoint> q = ClosestPoint(fit.surface, truth);
      ASSERT_TRUE(q.has_value());
      EXPECT_LE(std::abs(q->distance), 3.0 * kSigma) << x << ", " << y;
      EXPECT_GT(q->normal.z(), 0.9) << "normal of the region's outer side";
    }
  }
}

TEST(FitBsplineSurface, RegionTurningTooFarIsRefused) {
  // Three quarters of a cylinder of radius 5 about the y axis.
  Patch p;
  p.region.type = SurfaceType::kFreeform;
  p.region.surface = Quadric{};
  for (double t = 0.0; t <= 1.5 * std::numbers::pi; t += 0.1) {
    for (double y = 0.0; y <= 10.0; y += 0.5) {
      p.samples.points.emplace_back(5.0 * std::cos(t), y, 5.0 * std::sin(t));
      p.samples.face_centroids.push_back(p.samples.points.back());
      p.samples.face_normals.emplace_back(std::cos(t), 0.0, std::sin(t));
    }
  }
  const BsplineSurfaceFit fit = FitBsplineSurface(p.region, p.samples, kSpacing, kSigma);
  EXPECT_TRUE(fit.surface.IsNull());
  EXPECT_THAT(fit.failure, HasSubstr("height field"));
}

TEST(FitBsplineSurface, TooFewVerticesIsRefused) {
  Patch p = Paraboloid(0.01);
  p.samples.points.resize(5);
  const BsplineSurfaceFit fit = FitBsplineSurface(p.region, p.samples, kSpacing, kSigma);
  EXPECT_TRUE(fit.surface.IsNull());
  EXPECT_THAT(fit.failure, HasSubstr("too few"));
}

}  // namespace
}  // namespace meshseg::brep_internal
