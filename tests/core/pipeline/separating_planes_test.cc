// The maximal-margin plane of binary samples: on a digitized slanted disc it
// recovers the plane's normal far closer than least squares through the
// marching-cubes midpoints; samples no plane separates give nullopt.
#include "pipeline/separating_planes.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

namespace meshseg::pipeline_internal {
namespace {

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 /
         std::numbers::pi;
}

// A plane through (0.3, 0.1, 0.2) tilted 11 degrees, digitized on the unit
// lattice over a disc of `radius` voxels: for every vertical lattice edge it
// crosses, the material end (below) and the air end (above).
struct Digitized {
  Eigen::Vector3d normal;
  std::vector<Eigen::Vector3d> inside, outside, midpoints;
};

Digitized DigitizedDisc(double radius) {
  Digitized d;
  d.normal =
      Eigen::AngleAxisd(11.0 * std::numbers::pi / 180.0, Eigen::Vector3d(2, -1, 0).normalized()) *
      Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d point(0.3, 0.1, 0.2);
  const int r = static_cast<int>(std::ceil(radius));
  for (int i = -r; i <= r; ++i) {
    for (int j = -r; j <= r; ++j) {
      if (i * i + j * j > radius * radius) continue;
      // Height of the plane over (i, j); the edge from floor to floor + 1.
      const double z =
          point.z() -
          (d.normal.x() * (i - point.x()) + d.normal.y() * (j - point.y())) / d.normal.z();
      const Eigen::Vector3d a(i, j, std::floor(z)), b(i, j, std::floor(z) + 1.0);
      d.inside.push_back(a);
      d.outside.push_back(b);
      d.midpoints.push_back(0.5 * (a + b));
    }
  }
  return d;
}

Eigen::Vector3d LeastSquaresNormal(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const auto& p : points) m += (p - c) * (p - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  return eig.eigenvectors().col(0);
}

TEST(MaxMarginPlane, RecoversADigitizedSlantedDiscsNormal) {
  for (const double radius : {6.0, 8.0, 12.0}) {
    const Digitized d = DigitizedDisc(radius);
    // Started, as in the pipeline, from the least-squares plane.
    const Eigen::Vector3d start = LeastSquaresNormal(d.midpoints);
    const double ls = AngleDeg(start, d.normal);
    const std::optional<SeparatingPlane> fit =
        MaxMarginPlane(d.inside, d.outside, Plane{.point = {}, .normal = start});
    ASSERT_TRUE(fit.has_value()) << radius;
    EXPECT_GT(fit->margin, 0.0);
    const double separated = AngleDeg(fit->plane.normal, d.normal);
    std::cout << "disc radius " << radius << ": least squares " << ls << " deg, separator "
              << separated << " deg\n";
    EXPECT_LT(separated, 0.5 * ls) << radius;
    EXPECT_LT(separated, 0.3) << radius;
    // Every sample on its side, the normal towards the air.
    for (size_t k = 0; k < d.inside.size(); ++k) {
      EXPECT_LT(fit->plane.normal.dot(d.inside[k] - fit->plane.point), 0.0);
      EXPECT_GT(fit->plane.normal.dot(d.outside[k] - fit->plane.point), 0.0);
    }
  }
}

TEST(MaxMarginPlane, SamplesNoPlaneSeparatesGiveNothing) {
  Digitized d = DigitizedDisc(8.0);
  // An air sample two voxels under the material: no plane near the start
  // puts it above every material sample.
  d.outside.push_back(d.inside.front() - Eigen::Vector3d(0, 0, 2));
  EXPECT_FALSE(
      MaxMarginPlane(d.inside, d.outside, Plane{.point = {}, .normal = d.normal}).has_value());
  EXPECT_FALSE(MaxMarginPlane({}, d.outside, Plane{}).has_value());
}

}  // namespace
}  // namespace meshseg::pipeline_internal
