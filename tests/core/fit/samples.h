// Synthetic samples of known surfaces for the fit tests: a grid over a patch
// of the surface, exact unit normals, optional Gaussian noise along the normal
// (fixed seed).
#ifndef MESHSEG_TESTS_CORE_FIT_SAMPLES_H_
#define MESHSEG_TESTS_CORE_FIT_SAMPLES_H_

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "meshseg/fit.h"

namespace meshseg::test {

struct Samples {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  FitInput Input() const { return {points, normals, {}}; }
  FitInput PointsOnly() const { return {points, {}, {}}; }
};

// Point and unit normal of a surface at parameters (s, t) in [0, 1]².
using Patch = std::function<void(double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n)>;

inline Samples SamplePatch(const Patch& patch, int n_s, int n_t, double sigma,
                           unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  Samples out;
  for (int i = 0; i < n_s; ++i) {
    for (int j = 0; j < n_t; ++j) {
      Eigen::Vector3d p, n;
      patch((i + 0.5) / n_s, (j + 0.5) / n_t, &p, &n);
      if (sigma > 0.0) p += sigma * noise(rng) * n;
      out.points.push_back(p);
      out.normals.push_back(n);
    }
  }
  return out;
}

// A rotation that tilts the z axis so tests do not run axis-aligned.
inline Eigen::Matrix3d Tilt() {
  return (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// Cylinder patch: angle in [0, arc], height in [0, length] along the axis.
inline Samples SampleCylinder(const Cylinder& c, double arc, double length, int n_s, int n_t,
                              double sigma, unsigned seed = 7) {
  Eigen::Vector3d a = c.axis_direction.normalized();
  Eigen::Vector3d b1 = a.unitOrthogonal(), b2 = a.cross(b1);
  return SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double phi = s * arc;
        *n = std::cos(phi) * b1 + std::sin(phi) * b2;
        *p = c.axis_origin + t * length * a + c.radius * *n;
      },
      n_s, n_t, sigma, seed);
}

// Sphere cap: polar angle in [0, cap] from `pole`.
inline Samples SampleSphere(const Sphere& sp, const Eigen::Vector3d& pole, double cap, int n_s,
                            int n_t, double sigma, unsigned seed = 7) {
  Eigen::Vector3d a = pole.normalized();
  Eigen::Vector3d b1 = a.unitOrthogonal(), b2 = a.cross(b1);
  return SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double theta = s * cap, phi = t * 2.0 * M_PI;
        *n = std::cos(theta) * a + std::sin(theta) * (std::cos(phi) * b1 + std::sin(phi) * b2);
        *p = sp.center + sp.radius * *n;
      },
      n_s, n_t, sigma, seed);
}

// Cone patch: angle in [0, arc], distance from the apex along the generator
// in [g0, g1].
inline Samples SampleCone(const Cone& c, double arc, double g0, double g1, int n_s, int n_t,
                          double sigma, unsigned seed = 7) {
  Eigen::Vector3d a = c.axis_direction.normalized();
  Eigen::Vector3d b1 = a.unitOrthogonal(), b2 = a.cross(b1);
  return SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double phi = s * arc, g = g0 + t * (g1 - g0);
        const Eigen::Vector3d e = std::cos(phi) * b1 + std::sin(phi) * b2;
        *p = c.apex + g * (std::sin(c.half_angle) * e + std::cos(c.half_angle) * a);
        *n = std::cos(c.half_angle) * e - std::sin(c.half_angle) * a;
      },
      n_s, n_t, sigma, seed);
}

// Torus patch: around the axis in [0, arc_major], around the tube in
// [tube0, tube1] (0 = outer equator).
inline Samples SampleTorus(const Torus& tr, double arc_major, double tube0, double tube1,
                           int n_s, int n_t, double sigma, unsigned seed = 7) {
  Eigen::Vector3d a = tr.axis_direction.normalized();
  Eigen::Vector3d b1 = a.unitOrthogonal(), b2 = a.cross(b1);
  return SamplePatch(
      [&](double s, double t, Eigen::Vector3d* p, Eigen::Vector3d* n) {
        const double phi = s * arc_major, psi = tube0 + t * (tube1 - tube0);
        const Eigen::Vector3d e = std::cos(phi) * b1 + std::sin(phi) * b2;
        *n = std::cos(psi) * e + std::sin(psi) * a;
        *p = tr.center + tr.major_radius * e + tr.minor_radius * *n;
      },
      n_s, n_t, sigma, seed);
}

inline double AxisAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}

// Distance from point q to the line through o along unit-ish a.
inline double DistanceToLine(const Eigen::Vector3d& q, const Eigen::Vector3d& o,
                             const Eigen::Vector3d& a) {
  const Eigen::Vector3d d = q - o;
  return (d - d.dot(a.normalized()) * a.normalized()).norm();
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_FIT_SAMPLES_H_
