#include "fit/fit_internal.h"

#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::fit_internal {
namespace {

TEST(PerpendicularBasis, IsRightHandedAndOrthonormal) {
  for (const Eigen::Vector3d& raw : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0),
                                     Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-1, 1e-9, 0)}) {
    const Eigen::Vector3d a = raw.normalized();
    Eigen::Vector3d b1, b2;
    PerpendicularBasis(a, &b1, &b2);
    EXPECT_NEAR(b1.norm(), 1.0, 1e-12);
    EXPECT_NEAR(b2.norm(), 1.0, 1e-12);
    EXPECT_NEAR(a.dot(b1), 0.0, 1e-12);
    EXPECT_LT((b1.cross(b2) - a).norm(), 1e-12);
  }
}

TEST(RotateAxis, SmallStepTiltsByItsLength) {
  const Eigen::Vector3d a = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Vector3d r = RotateAxis(a, 1e-3, 0.0);
  EXPECT_NEAR(r.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::acos(r.dot(a)), 1e-3, 1e-9);
}

TEST(PointMoments, WeightedCentroidAndScatter) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {2, 0, 0}, {10, 10, 10}};
  const std::vector<double> w = {1, 1, 0};
  const Moments m = PointMoments(FitInput{pts, {}, w});
  EXPECT_LT((m.centroid - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(m.scatter(0, 0), 2.0, 1e-12);
  EXPECT_NEAR(m.weight_sum, 2.0, 1e-12);
}

TEST(SetDistanceErrors, RmsAndMax) {
  const std::vector<Eigen::Vector3d> pts = {{0, 0, 1}, {0, 0, -1}, {1, 1, 3}};
  FitResult r;
  r.surface = Plane{};
  SetDistanceErrors(FitInput{pts, {}, {}}, &r);
  EXPECT_NEAR(r.rms_distance, std::sqrt(11.0 / 3.0), 1e-12);
  EXPECT_NEAR(r.max_distance, 3.0, 1e-12);
}

}  // namespace
}  // namespace meshseg::fit_internal
