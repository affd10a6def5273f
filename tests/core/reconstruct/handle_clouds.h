// Closed shapes for the handle tests of the whole reconstruction (sampled
// with clouds.h's MakeCloud): a horseshoe whose two pointed ends nearly
// touch (genus 0; the points cannot show the gap) and a plate with a wide through-hole
// (genus 1; the points show the hole).
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_HANDLE_CLOUDS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_HANDLE_CLOUDS_H_

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Core>

#include "clouds.h"

namespace meshseg::test {

// A tube of radius r swept along the circle of radius R about the z axis
// over the angles |θ| ≥ phi0, each end closed by a cone of height H along the
// circle's tangent: a genus-0 solid whose two cone tips point at each other
// across a gap of 2 (R sin(phi0) − H cos(phi0)) (HorseshoeAngle gives phi0).
inline Shape Horseshoe(double R, double r, double H, double phi0) {
  Shape s;
  const Eigen::Vector3d c0(R * std::cos(phi0), R * std::sin(phi0), 0);
  const Eigen::Vector3d c1(R * std::cos(phi0), -R * std::sin(phi0), 0);
  // The direction each tip points: along the tangent, out of the arc.
  const Eigen::Vector3d t0(std::sin(phi0), -std::cos(phi0), 0);
  const Eigen::Vector3d t1(std::sin(phi0), std::cos(phi0), 0);
  const double slant = std::hypot(r, H);
  // Signed distance to a cone (base centre c, axis t) in its axial plane.
  const auto cone = [=](const Eigen::Vector3d& p, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& t) {
    const double x = (p - c).dot(t), rho = ((p - c) - x * t).norm();
    // The slanted side from (0, r) to (H, 0).
    const Eigen::Vector2d a(0, r), b(H, 0), q(x, rho);
    const double u = std::clamp((q - a).dot(b - a) / (slant * slant), 0.0, 1.0);
    const double d = (q - a - u * (b - a)).norm();
    return x >= 0 && rho <= r * (1 - x / H) ? -d : d;
  };
  s.sdf = [=](const Eigen::Vector3d& p) {
    if (std::abs(std::atan2(p.y(), p.x())) >= phi0) {
      return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r;
    }
    return p.y() > 0 ? cone(p, c0, t0) : cone(p, c1, t1);
  };
  const double tube = (2 * M_PI - 2 * phi0) * R * 2 * M_PI * r, tips = 2 * M_PI * r * slant;
  s.sample = [=](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    if (u01(rng) < tips / (tube + tips)) {
      const bool first = u01(rng) < 0.5;
      const Eigen::Vector3d& c = first ? c0 : c1;
      const Eigen::Vector3d& t = first ? t0 : t1;
      const Eigen::Vector3d e1(0, 0, 1), e2 = t.cross(e1);
      const double f = std::sqrt(u01(rng)), a = 2 * M_PI * u01(rng);
      const Eigen::Vector3d radial = std::cos(a) * e1 + std::sin(a) * e2;
      *p = c + H * (1 - f) * t + r * f * radial;
      *n = (r * t + H * radial) / slant;
      return;
    }
    double v;
    do {
      v = 2 * M_PI * u01(rng);
    } while (u01(rng) > (R + r * std::cos(v)) / (R + r));
    const double a = phi0 + (2 * M_PI - 2 * phi0) * u01(rng);
    *n = Eigen::Vector3d(std::cos(v) * std::cos(a), std::cos(v) * std::sin(a), std::sin(v));
    *p = Eigen::Vector3d(R * std::cos(a), R * std::sin(a), 0.0) + r * *n;
  };
  s.area = tube + tips;
  return s;
}

// The phi0 at which Horseshoe(R, r, H, phi0)'s tips are `gap` apart.
inline double HorseshoeAngle(double R, double H, double gap) {
  return std::atan2(H, R) + std::asin(gap / (2 * std::hypot(R, H)));
}

// The box |x|, |y| ≤ half_side, |z| ≤ half_thickness with a round hole of
// radius `hole` through it along z: genus 1.
inline Shape PlateWithHole(double half_side, double half_thickness, double hole) {
  Shape s;
  const double a = half_side, t = half_thickness;
  s.sdf = [=](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p.cwiseAbs() - Eigen::Vector3d(a, a, t);
    const double box = q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    return std::max(box, hole - std::hypot(p.x(), p.y()));
  };
  const double face = 4 * a * a - M_PI * hole * hole, side = 2 * a * 2 * t;
  const double wall = 2 * M_PI * hole * 2 * t;
  s.sample = [=](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::discrete_distribution<int> pick({face, face, side, side, side, side, wall});
    const int f = pick(rng);
    if (f < 2) {
      do {
        *p = Eigen::Vector3d(a * u(rng), a * u(rng), f == 0 ? t : -t);
      } while (std::hypot(p->x(), p->y()) < hole);
      *n = Eigen::Vector3d(0, 0, f == 0 ? 1 : -1);
    } else if (f < 6) {
      const int axis = (f - 2) / 2;  // x or y
      const double sign = f % 2 == 0 ? 1.0 : -1.0;
      *p = Eigen::Vector3d(a * u(rng), a * u(rng), t * u(rng));
      (*p)[axis] = sign * a;
      *n = Eigen::Vector3d::Zero();
      (*n)[axis] = sign;
    } else {
      const double angle = M_PI * u(rng);
      *n = -Eigen::Vector3d(std::cos(angle), std::sin(angle), 0);
      *p = -hole * *n + Eigen::Vector3d(0, 0, t * u(rng));
    }
  };
  s.area = 2 * face + 4 * side + wall;
  return s;
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_HANDLE_CLOUDS_H_
