#include "fit/axial_fit.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "samples.h"

namespace meshseg::fit_internal {
namespace {

// Cone with rho = 1.5 + 0.2 h about the line through (1, 0, 0) along z.
AxialSurface TrueCone() {
  return {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::UnitZ(), 1.5, std::atan(0.2)};
}

test::Samples ConeSamples() {
  const AxialSurface c = TrueCone();
  const double t = std::tan(c.angle);
  const Cone cone{c.origin - (c.radius / t) * c.axis, c.axis, c.angle};
  return test::SampleCone(cone, M_PI, 6.0, 10.0, 16, 8, 0.0);
}

Eigen::Vector3d Centroid(const test::Samples& s) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : s.points) c += p;
  return c / static_cast<double>(s.points.size());
}

TEST(AxialCost, ZeroOnTheSurface) {
  const test::Samples s = ConeSamples();
  EXPECT_LT(AxialCost(s.Input(), TrueCone()), 1e-24);
  AxialSurface off = TrueCone();
  off.radius += 0.1;
  // Every residual is -0.1 cos(angle).
  EXPECT_NEAR(AxialCost(s.Input(), off),
              s.points.size() * std::pow(0.1 * std::cos(off.angle), 2), 1e-12);
}

TEST(RefineAxial, RecoversConeFromPerturbedStart) {
  const test::Samples s = ConeSamples();
  const Eigen::Vector3d centroid = Centroid(s);
  AxialSurface start = TrueCone();
  start.origin += Eigen::Vector3d(0.1, -0.05, 0.0);
  start.axis = Eigen::Vector3d(0.05, 0.02, 1.0).normalized();
  start.radius += 0.2;
  start.angle = 0.0;
  const LmOutcome lm = RefineAxial(s.Input(), centroid, /*fit_angle=*/true, FitParams{}, &start);
  EXPECT_LT(lm.cost, 1e-20);
  EXPECT_NEAR(std::tan(start.angle), 0.2, 1e-9);
  EXPECT_GT(start.axis.dot(Eigen::Vector3d::UnitZ()), 1.0 - 1e-12);
  // The origin is moved next to the centroid, on the true axis.
  EXPECT_NEAR((centroid - start.origin).dot(start.axis), 0.0, 1e-9);
  EXPECT_LT(test::DistanceToLine(start.origin, TrueCone().origin, TrueCone().axis), 1e-9);
}

TEST(FitCrossSection, CircleOfProjectedCylinder) {
  const Cylinder cyl{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d::UnitY(), 2.5};
  const test::Samples s = test::SampleCylinder(cyl, M_PI / 2, 3.0, 10, 5, 0.0);
  AxialSurface out;
  ASSERT_TRUE(FitCrossSection(s.Input(), Centroid(s), Eigen::Vector3d::UnitY(), &out));
  EXPECT_NEAR(out.radius, 2.5, 1e-12);
  EXPECT_LT(test::DistanceToLine(out.origin, cyl.axis_origin, cyl.axis_direction), 1e-12);
}

TEST(BestAxialFit, KeepsTheLowerCostStart) {
  const test::Samples s = ConeSamples();
  AxialSurface bad = TrueCone();
  bad.axis = Eigen::Vector3d::UnitX();  // far from any good fit
  const std::vector<AxialSurface> starts = {bad, TrueCone()};
  AxialSurface best;
  int iterations = -1;
  const double cost = BestAxialFit(s.Input(), Centroid(s), starts, true,
                                   FitParams{.refine = false}, &best, &iterations);
  EXPECT_LT(cost, 1e-24);
  EXPECT_EQ(iterations, 0);
  EXPECT_GT(best.axis.z(), 0.99);
  EXPECT_TRUE(std::isinf(BestAxialFit(s.Input(), Centroid(s), {}, true, FitParams{}, &best,
                                      &iterations)));
}

// The cylinder's residual (P = 5, angle 0) takes a shortcut past the
// products by cos = 1 and sin = 0: it must give the general formulas'
// values, those of the cone's residual (P = 6) at angle 0 in its first
// five steps (equal as numbers: a zero's sign may differ, which the normal
// equations cannot see). Random points around a tilted axis, some on it.
TEST(AxialResidual, CylinderIsTheGeneralFormulaAtAngleZero) {
  const AxialFrame frame(Eigen::Vector3d(0.3, -1.2, 0.7),
                         Eigen::Vector3d(0.2, -0.5, 1.0).normalized(), 1.7, 0.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  points.push_back(frame.origin);
  points.push_back(frame.origin + 2.5 * frame.axis);
  for (const Eigen::Vector3d& p : points) {
    Eigen::Matrix<double, 1, 5> row5;
    Eigen::Matrix<double, 1, 6> row6;
    const double r5 = AxialResidual<5>(frame, p, &row5);
    const double r6 = AxialResidual<6>(frame, p, &row6);
    EXPECT_EQ(r5, r6) << p.transpose();
    for (int k = 0; k < 5; ++k) {
      EXPECT_EQ(row5(k), row6(k)) << "step " << k << " at " << p.transpose();
    }
  }
}

// AxialResidualPair must give each point AxialResidual's residual and row
// to the bit (memcmp): the cylinder's shortcut and the general formula
// (cone angles of both signs), P = 5 and 6, on random points at scales
// from 1e-3 to 1e3 around tilted axes, points on the axis included.
template <int P>
void ExpectPairIsTwoSingles(const AxialFrame& frame, const std::vector<Eigen::Vector3d>& points) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    Eigen::Matrix<double, 1, P> single0, single1, pair0, pair1;
    const double r0 = AxialResidual<P>(frame, points[i], &single0);
    const double r1 = AxialResidual<P>(frame, points[i + 1], &single1);
    double q0 = 0.0, q1 = 0.0;
    AxialResidualPair<P>(frame, points[i], points[i + 1], &q0, &pair0, &q1, &pair1);
    EXPECT_EQ(std::memcmp(&r0, &q0, sizeof(double)), 0) << points[i].transpose();
    EXPECT_EQ(std::memcmp(&r1, &q1, sizeof(double)), 0) << points[i + 1].transpose();
    EXPECT_EQ(std::memcmp(single0.data(), pair0.data(), sizeof(double) * P), 0)
        << "P " << P << " at " << points[i].transpose();
    EXPECT_EQ(std::memcmp(single1.data(), pair1.data(), sizeof(double) * P), 0)
        << "P " << P << " at " << points[i + 1].transpose();
  }
}

TEST(AxialResidual, PairIsTwoSinglesBitForBit) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double scale : {1e-3, 1.0, 37.0, 1e3}) {
    for (const double angle : {0.0, 0.35, -0.9}) {
      const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), 1.0).normalized();
      const AxialFrame frame(scale * Eigen::Vector3d(u(rng), u(rng), u(rng)), axis,
                             scale * (1.0 + u(rng) * 0.5), angle);
      std::vector<Eigen::Vector3d> points;
      for (int i = 0; i < 400; ++i) {
        points.push_back(scale * 3.0 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
      }
      // On the axis (rho = 0), next to and between others.
      points.insert(points.begin() + 7, frame.origin);
      points.insert(points.begin() + 20, frame.origin + scale * 2.5 * axis);
      points.push_back(frame.origin - scale * axis);
      ExpectPairIsTwoSingles<5>(frame, points);
      ExpectPairIsTwoSingles<6>(frame, points);
    }
  }
}

}  // namespace
}  // namespace meshseg::fit_internal
