// The proofs that no sphere / no cylinder lies within tau of a set of
// points: never claimed for points that do lie within tau of one (the
// proof must be sound, or an exact fit that would succeed is skipped), and
// claimed for the corners of a strip group reaching from a round over its
// tangent flat side, the groups whose failing fits they are there to skip.
#include "segment/fit_exclusion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = std::numbers::pi;

// A unit vector perpendicular to unit a.
Eigen::Vector3d Across(const Eigen::Vector3d& a) { return a.unitOrthogonal(); }

// Corners of a round of radius r about the x axis (arc from angle 0 to
// `arc`, `steps` strips) followed by its tangent flat side of length
// `side`, at the two rims x = 0 and x = length, as a CAD exporter writes a
// rounded prism's side; `normals` gets the strip and side normals.
std::vector<Eigen::Vector3d> RoundThenSide(double r, double arc, int steps, double side,
                                           double length, std::vector<Eigen::Vector3d>* normals) {
  std::vector<Eigen::Vector2d> profile;
  for (int k = 0; k <= steps; ++k) {
    const double t = arc * k / steps;
    profile.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  // Tangent at the arc's end: direction (-sin, cos).
  profile.push_back(profile.back() + side * Eigen::Vector2d(-std::sin(arc), std::cos(arc)));
  std::vector<Eigen::Vector3d> points;
  for (const double x : {0.0, length}) {
    for (const Eigen::Vector2d& p : profile) points.emplace_back(x, p.x(), p.y());
  }
  normals->clear();
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const Eigen::Vector2d d = profile[k + 1] - profile[k];
    normals->push_back(Eigen::Vector3d(0.0, d.y(), -d.x()).normalized());
  }
  return points;
}

TEST(FitExclusionTest, StripsOverATangentSideFitNoSphereAndNoCylinder) {
  // Six strips of 10 degrees and the side: 16 corners, a seed group of the
  // exact path at a facet beside the side.
  std::vector<Eigen::Vector3d> normals;
  const std::vector<Eigen::Vector3d> points =
      RoundThenSide(2.54, kPi / 3.0, 6, 2.42, 20.0, &normals);
  const double tau = 4e-5;
  EXPECT_TRUE(NoSphereWithin(points, tau));
  EXPECT_TRUE(NoCylinderWithin(points, normals, 1e-4, tau));
}

TEST(FitExclusionTest, StripsOfOneRoundAreNotExcluded) {
  // The same strips without the side lie on the round's cylinder (axis x,
  // perpendicular to every strip normal).
  std::vector<Eigen::Vector3d> normals;
  std::vector<Eigen::Vector3d> points = RoundThenSide(2.54, kPi / 6.0, 3, 2.42, 20.0, &normals);
  points.erase(points.begin() + 4);  // the side's far corner at x = 0
  points.pop_back();                 // and at x = 20
  normals.pop_back();
  EXPECT_FALSE(NoCylinderWithin(points, normals, 1e-4, 4e-5));
}

TEST(FitExclusionTest, NeverExcludesPointsWithinTauOfASphere) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d centre(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    const double radius = std::pow(10.0, 2.0 * unit(rng));  // 0.01 to 100
    const double tau = radius * std::pow(10.0, -3.0 + 3.0 * unit(rng));
    const double cap = 0.05 + 1.5 * std::abs(unit(rng));  // cap half-angle, radians
    const Eigen::Vector3d pole = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 16; ++k) {
      const double t = cap * std::abs(unit(rng)), phi = kPi * unit(rng);
      const Eigen::Vector3d u = Across(pole), v = pole.cross(u);
      const Eigen::Vector3d n =
          std::cos(t) * pole + std::sin(t) * (std::cos(phi) * u + std::sin(phi) * v);
      // Off the sphere by up to tau, the worst case at a few corners.
      const double off = k % 3 == 0 ? tau * (k % 2 ? 1.0 : -1.0) : tau * unit(rng);
      points.push_back(centre + (radius + off) * n);
    }
    EXPECT_FALSE(NoSphereWithin(points, tau)) << "trial " << trial;
  }
}

TEST(FitExclusionTest, NeverExcludesPointsWithinTauOfAnAdmissibleCylinder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    // Normals perpendicular to e, fanned over up to 60 degrees; the
    // cylinder's axis tilted from e as far as max_tilt lets it.
    const Eigen::Vector3d e = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const Eigen::Vector3d u = Across(e), v = e.cross(u);
    const double max_tilt = 1e-4 + 1e-3 * std::abs(unit(rng));
    const double fan = 0.2 + std::abs(unit(rng));
    std::vector<Eigen::Vector3d> normals;
    for (int k = 0; k < 4; ++k) {
      const double t = fan * k / 3.0;
      normals.push_back(std::cos(t) * u + std::sin(t) * v);
    }
    // The axis turned toward the normals' mean direction by the largest
    // angle keeping |n . a| <= max_tilt for all of them.
    const Eigen::Vector3d mean = (normals.front() + normals.back()).normalized();
    double least = 1.0;
    for (const Eigen::Vector3d& n : normals) least = std::min(least, n.dot(mean));
    const double tilt = std::asin(max_tilt / least) * 0.999;
    const Eigen::Vector3d axis = std::cos(tilt) * e + std::sin(tilt) * mean;
    const Eigen::Vector3d origin(5 * unit(rng), 5 * unit(rng), 5 * unit(rng));
    const double radius = std::pow(10.0, 2.0 * unit(rng));
    const double tau = radius * std::pow(10.0, -4.0 + 3.0 * unit(rng));
    const Eigen::Vector3d a1 = Across(axis), a2 = axis.cross(a1);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 16; ++k) {
      const double t = fan * std::abs(unit(rng)), h = 20.0 * unit(rng);
      const double off = k % 3 == 0 ? tau * (k % 2 ? 1.0 : -1.0) : tau * unit(rng);
      points.push_back(origin + h * axis + (radius + off) * (std::cos(t) * a1 + std::sin(t) * a2));
    }
    EXPECT_FALSE(NoCylinderWithin(points, normals, max_tilt, tau)) << "trial " << trial;
  }
}

// Corners of a round (radius r, arc from 0 to `arc`) and its tangent flat
// side, at heights spread along x as a fine tessellation puts them.
std::vector<Eigen::Vector3d> RoundThenSideAtHeights(double r, double arc, double side) {
  std::vector<Eigen::Vector3d> points;
  const double heights[] = {0.0, 3.0, 7.5, 12.0, 20.0};
  for (int k = 0; k < 10; ++k) {
    const double t = arc * k / 9.0;
    points.emplace_back(heights[k % 5], r * std::cos(t), r * std::sin(t));
  }
  const Eigen::Vector2d end(r * std::cos(arc), r * std::sin(arc));
  const Eigen::Vector2d along(-std::sin(arc), std::cos(arc));
  for (int k = 1; k <= 4; ++k) {
    const Eigen::Vector2d p = end + side * k / 4.0 * along;
    points.emplace_back(heights[(k + 2) % 5], p.x(), p.y());
  }
  return points;
}

TEST(FitExclusionTest, ARoundAndItsSideAtSpreadHeightsFitNoQuadric) {
  EXPECT_TRUE(NoQuadricWithin(RoundThenSideAtHeights(2.54, kPi / 3.0, 2.42), 4e-5));
}

TEST(FitExclusionTest, NoQuadricProofForCornersOnTwoRims) {
  // Every point on x = 0 or x = 20: the pair of planes x (x - 20) = 0 holds
  // them all, whatever their section.
  std::vector<Eigen::Vector3d> normals;
  EXPECT_FALSE(NoQuadricWithin(RoundThenSide(2.54, kPi / 3.0, 6, 2.42, 20.0, &normals), 4e-5));
}

TEST(FitExclusionTest, NeverExcludesPointsWithinTauOfAConeOrCylinder) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const Eigen::Vector3d apex(5 * unit(rng), 5 * unit(rng), 5 * unit(rng));
    // Half angle 0 (a cylinder of radius `radius`) up to 80 degrees.
    const double half_angle = trial % 4 == 0 ? 0.0 : 1.4 * std::abs(unit(rng));
    const double radius = std::pow(10.0, 1.5 * unit(rng));
    const double tau = radius * std::pow(10.0, -4.0 + 3.0 * unit(rng));
    const Eigen::Vector3d u = Across(axis), v = axis.cross(u);
    const double fan = 0.2 + 2.0 * std::abs(unit(rng));
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < 20; ++k) {
      const double t = fan * unit(rng), h = radius * (1.0 + 3.0 * std::abs(unit(rng)));
      const Eigen::Vector3d e = std::cos(t) * u + std::sin(t) * v;
      // A point of the surface at height h (radius + h tan for a cone),
      // moved off it along the surface normal by up to tau.
      const double rho = half_angle == 0.0 ? radius : h * std::tan(half_angle);
      const Eigen::Vector3d normal = std::cos(half_angle) * e - std::sin(half_angle) * axis;
      const double off = k % 3 == 0 ? tau * (k % 2 ? 1.0 : -1.0) : tau * unit(rng);
      points.push_back(apex + h * axis + rho * e + off * normal);
    }
    EXPECT_FALSE(NoQuadricWithin(points, tau)) << "trial " << trial;
  }
}

// Points within tau of one nappe of a cone (or of a cylinder, half angle
// 0): at radii from `rho0` to `rho1` from the axis, or at those two radii
// only (the rims of a frustum: corners on two parallel planes, the pair of
// planes beside the cone), over a fan of `fan` radians, pushed off the
// surface along its normal by up to tau (exactly tau at every third).
std::vector<Eigen::Vector3d> OnOneNappe(const Eigen::Vector3d& apex, const Eigen::Vector3d& axis,
                                        double half_angle, double rho0, double rho1, double fan,
                                        bool rims_only, double tau, std::mt19937* rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d u = Across(axis), v = axis.cross(u);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 20; ++k) {
    const double t = fan * unit(*rng);
    const Eigen::Vector3d e = std::cos(t) * u + std::sin(t) * v;
    const double s = rims_only ? (k % 2) : std::abs(unit(*rng));
    const double rho = rho0 + s * (rho1 - rho0);
    // A cylinder (half angle 0) of radius rho0 between heights 0 and 20.
    const double h = half_angle == 0.0 ? 20.0 * s : rho / std::tan(half_angle);
    const Eigen::Vector3d at = apex + h * axis + (half_angle == 0.0 ? rho0 : rho) * e;
    const Eigen::Vector3d normal = std::cos(half_angle) * e - std::sin(half_angle) * axis;
    const double off = k % 3 == 0 ? tau * (k % 2 ? 1.0 : -1.0) : tau * unit(*rng);
    points.push_back(at + off * normal);
  }
  return points;
}

TEST(FitExclusionTest, NeverExcludesPointsWithinTauOfOneNappeOrACylinder) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const Eigen::Vector3d apex(5 * unit(rng), 5 * unit(rng), 5 * unit(rng));
    // Cylinders, cones up to 80 degrees, and nearly flat ones up to 89.9:
    // the cones whose quadric is nearest a pair of planes.
    const double half_angle = trial % 4 == 0   ? 0.0
                              : trial % 4 == 1 ? 1.4 * std::abs(unit(rng))
                                               : 1.4 + 0.17 * std::abs(unit(rng));
    const double rho0 = std::pow(10.0, 1.5 * unit(rng));
    const double rho1 = rho0 * (1.2 + 3.0 * std::abs(unit(rng)));
    const double tau = rho0 * std::pow(10.0, -4.0 + 3.0 * unit(rng));
    const double fan = 0.2 + 2.0 * std::abs(unit(rng));
    const bool rims_only = trial % 2 == 0;
    const AxialExclusion proof = ExcludeAxial(
        OnOneNappe(apex, axis, half_angle, rho0, rho1, fan, rims_only, tau, &rng), tau);
    EXPECT_FALSE(proof.cone) << "trial " << trial;
    if (half_angle == 0.0) {
      EXPECT_FALSE(proof.cylinder) << "trial " << trial;
    }
  }
}

TEST(FitExclusionTest, StripsOverATangentSideFitNoConeThoughTheirRimsFitAPairOfPlanes) {
  // Every corner on x = 0 or x = 20: the pair of planes holds them (no
  // quadric proof), but no cylinder of any axis, and no cone: the cone
  // quadric nearest the pair of planes is a nearly flat double cone about
  // x, one nappe through each rim.
  std::vector<Eigen::Vector3d> normals;
  const std::vector<Eigen::Vector3d> points =
      RoundThenSide(2.54, kPi / 3.0, 6, 2.42, 20.0, &normals);
  ASSERT_FALSE(NoQuadricWithin(points, 4e-5));
  const AxialExclusion proof = ExcludeAxial(points, 4e-5);
  EXPECT_TRUE(proof.cylinder);
  EXPECT_TRUE(proof.cone);
  // The round's strips alone lie on its cylinder: neither is excluded.
  std::vector<Eigen::Vector3d> round = RoundThenSide(2.54, kPi / 3.0, 6, 2.42, 20.0, &normals);
  round.erase(round.begin() + 7);  // the side's far corner at x = 0
  round.pop_back();                // and at x = 20
  const AxialExclusion none = ExcludeAxial(round, 4e-5);
  EXPECT_FALSE(none.cylinder);
  EXPECT_FALSE(none.cone);
}

TEST(FitExclusionTest, ProvesNothingFromTooLittle) {
  const std::vector<Eigen::Vector3d> four = {
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}};  // any 4 points lie on a sphere
  EXPECT_FALSE(NoSphereWithin(four, 1e-9));
  std::vector<Eigen::Vector3d> normals;
  const std::vector<Eigen::Vector3d> points = RoundThenSide(1.0, kPi / 4.0, 3, 1.0, 5.0, &normals);
  // One normal direction leaves the axis free: no proof.
  const std::vector<Eigen::Vector3d> parallel(4, Eigen::Vector3d::UnitZ());
  EXPECT_FALSE(NoCylinderWithin(points, parallel, 1e-4, 1e-6));
  EXPECT_FALSE(NoCylinderWithin(points, {}, 1e-4, 1e-6));
}

}  // namespace
}  // namespace meshseg::segment_internal
