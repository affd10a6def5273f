// Point clouds sampled from closed shapes with known signed distance, for the
// reconstruct tests: uniform samples with outward normals, optional Gaussian
// noise, uniform outliers in the bounding box and a missing patch (fixed
// seeds). Also mesh checks: closed, manifold, components, distance to truth.
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_CLOUDS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_CLOUDS_H_

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"

namespace meshseg::test {

struct Shape {
  // Signed distance, negative inside.
  std::function<double(const Eigen::Vector3d&)> sdf;
  // A uniform random surface point and its outward normal.
  std::function<void(std::mt19937&, Eigen::Vector3d*, Eigen::Vector3d*)> sample;
  double area = 0.0;
};

inline Shape Sphere(double radius) {
  Shape s;
  s.sdf = [radius](const Eigen::Vector3d& p) { return p.norm() - radius; };
  s.sample = [radius](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::normal_distribution<double> g;
    *n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    *p = radius * *n;
  };
  s.area = 4 * M_PI * radius * radius;
  return s;
}

// Axis-aligned box centred at the origin with half sizes `half`.
inline Shape Box(const Eigen::Vector3d& half) {
  Shape s;
  s.sdf = [half](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p.cwiseAbs() - half;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
  };
  const Eigen::Vector3d face(4 * half.y() * half.z(), 4 * half.x() * half.z(),
                             4 * half.x() * half.y());
  s.sample = [half, face](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::discrete_distribution<int> pick(
        {face.x(), face.x(), face.y(), face.y(), face.z(), face.z()});
    const int f = pick(rng);
    const int axis = f / 2;
    const double sign = f % 2 == 0 ? 1.0 : -1.0;
    for (int a = 0; a < 3; ++a) (*p)[a] = u(rng) * half[a];
    (*p)[axis] = sign * half[axis];
    *n = Eigen::Vector3d::Zero();
    (*n)[axis] = sign;
  };
  s.area = 2 * face.sum();
  return s;
}

// Torus about the z axis: major radius R, minor radius r.
inline Shape Torus(double R, double r) {
  Shape s;
  s.sdf = [R, r](const Eigen::Vector3d& p) {
    return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r;
  };
  s.sample = [R, r](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::uniform_real_distribution<double> u(0.0, 2 * M_PI), accept(0.0, 1.0);
    double v;
    do {
      v = u(rng);
    } while (accept(rng) > (R + r * std::cos(v)) / (R + r));
    const double t = u(rng);
    *n = Eigen::Vector3d(std::cos(v) * std::cos(t), std::cos(v) * std::sin(t), std::sin(v));
    *p = Eigen::Vector3d(R * std::cos(t), R * std::sin(t), 0.0) + r * *n;
  };
  s.area = 4 * M_PI * M_PI * R * r;
  return s;
}

struct CloudSpec {
  int points = 4000;
  double noise = 0.0;        // Gaussian sigma, in spacing
  double outliers = 0.0;     // fraction of `points` added uniformly in the bounding box
  double hole_radius = 0.0;  // points within this distance of hole_center are removed
  Eigen::Vector3d hole_center = Eigen::Vector3d::Zero();
  int clumps = 0;       // small flat discs of stray points (ghost sheets) in the box
  bool normals = true;  // outward unit normals (outliers get random ones)
  unsigned seed = 1;
};

// sqrt(area / count): the spacing of `count` uniform samples on `shape`.
inline double Spacing(const Shape& shape, int count) { return std::sqrt(shape.area / count); }

inline PointCloud MakeCloud(const Shape& shape, const CloudSpec& spec) {
  std::mt19937 rng(spec.seed);
  std::normal_distribution<double> g;
  const double h = Spacing(shape, spec.points);
  PointCloud cloud;
  cloud.name = "synthetic.xyz";
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (int i = 0; i < spec.points; ++i) {
    Eigen::Vector3d p, n;
    shape.sample(rng, &p, &n);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    if ((p - spec.hole_center).norm() < spec.hole_radius) continue;
    p += spec.noise * h * Eigen::Vector3d(g(rng), g(rng), g(rng));
    cloud.points.push_back(p);
    if (spec.normals) cloud.normals.push_back(n);
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int outliers = static_cast<int>(spec.outliers * spec.points);
  for (int i = 0; i < outliers; ++i) {
    const Eigen::Vector3d t(u(rng), u(rng), u(rng));
    cloud.points.push_back(lo + t.cwiseProduct(hi - lo));
    if (spec.normals) cloud.normals.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  // Ghost sheets: discs of radius 2 h sampled at spacing h, away from the part.
  for (int i = 0; i < spec.clumps; ++i) {
    Eigen::Vector3d c;
    do {
      c = lo + Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
    } while (std::abs(shape.sdf(c)) < 6 * h);
    const Eigen::Vector3d n = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
    for (int x = -2; x <= 2; ++x) {
      for (int y = -2; y <= 2; ++y) {
        if (x * x + y * y > 4) continue;
        cloud.points.push_back(c + h * (x * a + y * b));
        if (spec.normals) cloud.normals.push_back(n);
      }
    }
  }
  return cloud;
}

inline int64_t BoundaryEdgeCount(const TriMesh& m) {
  int64_t n = 0;
  for (const auto e : m.edges()) n += m.is_boundary(e);
  return n;
}

inline int64_t NonManifoldVertexCount(const TriMesh& m) {
  int64_t n = 0;
  for (const auto v : m.vertices()) n += !m.is_manifold(v) || m.is_isolated(v);
  return n;
}

inline int ComponentCount(const TriMesh& m) {
  std::vector<int> comp(m.n_faces(), -1);
  int count = 0;
  for (const auto f : m.faces()) {
    if (comp[f.idx()] >= 0) continue;
    std::vector<OpenMesh::SmartFaceHandle> stack = {f};
    comp[f.idx()] = count;
    while (!stack.empty()) {
      const auto cur = stack.back();
      stack.pop_back();
      for (const auto nb : cur.faces()) {
        if (comp[nb.idx()] < 0) {
          comp[nb.idx()] = count;
          stack.push_back(nb);
        }
      }
    }
    ++count;
  }
  return count;
}

// Fraction of mesh vertices with |sdf| ≤ tolerance.
inline double FractionWithin(const TriMesh& m, const Shape& shape, double tolerance) {
  int64_t near = 0;
  for (const auto v : m.vertices()) near += std::abs(shape.sdf(ToEigen(m.point(v)))) <= tolerance;
  return m.n_vertices() == 0 ? 0.0 : static_cast<double>(near) / m.n_vertices();
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_CLOUDS_H_
