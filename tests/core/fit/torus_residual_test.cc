// TorusResidualPair (torus_residual.h) must give each point TorusResidual's
// residual and row to the bit (memcmp), on random points at scales from
// 1e-3 to 1e3 around tilted tori (ring and spindle), points on the axis
// and on the tube-centre circle (distance 0) included.
#include "fit/torus_residual.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::fit_internal {
namespace {

TEST(TorusResidual, PairIsTwoSinglesBitForBit) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double scale : {1e-3, 1.0, 41.0, 1e3}) {
    for (const double minor_share : {0.25, 1.6}) {  // a ring torus, a spindle torus
      const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), 1.0, u(rng)).normalized();
      const double major = scale * (2.0 + u(rng));
      const TorusFrame frame(scale * Eigen::Vector3d(u(rng), u(rng), u(rng)), axis, major,
                             minor_share * major);
      std::vector<Eigen::Vector3d> points;
      for (int i = 0; i < 400; ++i) {
        points.push_back(frame.center + scale * 4.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
      }
      // On the axis (rho = 0) and on the tube-centre circle (distance 0).
      points.insert(points.begin() + 5, frame.center);
      points.insert(points.begin() + 12, frame.center + scale * axis);
      points.insert(points.begin() + 13, frame.center + major * frame.b1);
      points.push_back(frame.center + major * frame.b2);
      for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        Eigen::Matrix<double, 1, 7> single0, single1, pair0, pair1;
        const double r0 = TorusResidual(frame, points[i], &single0);
        const double r1 = TorusResidual(frame, points[i + 1], &single1);
        double q0 = 0.0, q1 = 0.0;
        TorusResidualPair(frame, points[i], points[i + 1], &q0, &pair0, &q1, &pair1);
        EXPECT_EQ(std::memcmp(&r0, &q0, sizeof(double)), 0) << points[i].transpose();
        EXPECT_EQ(std::memcmp(&r1, &q1, sizeof(double)), 0) << points[i + 1].transpose();
        EXPECT_EQ(std::memcmp(single0.data(), pair0.data(), sizeof(double) * 7), 0)
            << points[i].transpose();
        EXPECT_EQ(std::memcmp(single1.data(), pair1.data(), sizeof(double) * 7), 0)
            << points[i + 1].transpose();
      }
    }
  }
}

}  // namespace
}  // namespace meshseg::fit_internal
