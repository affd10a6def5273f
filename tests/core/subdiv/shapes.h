// Generated smooth and creased bodies with known surfaces for the fit tests.
#ifndef MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_
#define MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "server/test_files.h"

namespace meshseg::testing {

struct Triangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
};

// The unit icosahedron split `levels` times at edge midpoints, on the unit
// sphere: 20 * 4^levels faces.
inline Triangles UnitIcosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Triangles m;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : m.vertices) v.normalize();
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = mid.try_emplace(key, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> faces;
    for (const auto& f : m.faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({f[1], bc, ab});
      faces.push_back({f[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  return m;
}

// The superellipsoid |x|^p + |y|^p + |z|^p = r^p.
struct Superellipsoid {
  double r = 10.0;
  double p = 3.0;
  // (sum |x_i|^p)^(1/p): homogeneous of degree 1, = r on the surface.
  double Gauge(const Eigen::Vector3d& x) const {
    return std::pow(
        std::pow(std::abs(x.x()), p) + std::pow(std::abs(x.y()), p) + std::pow(std::abs(x.z()), p),
        1.0 / p);
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const {
    const double g = Gauge(x);
    Eigen::Vector3d d;
    for (int i = 0; i < 3; ++i) {
      d[i] = std::pow(std::abs(x[i]) / g, p - 1) * (x[i] < 0 ? -1.0 : 1.0);
    }
    return d;
  }
  // Signed distance to first order, (G - r) / |grad G|.
  double Distance(const Eigen::Vector3d& x) const { return (Gauge(x) - r) / Gradient(x).norm(); }
  Eigen::Vector3d Project(const Eigen::Vector3d& direction) const {
    return direction * (r / Gauge(direction));
  }
};

// Returns the mean edge length of `m`.
inline double MeanEdge(const Triangles& m) {
  double sum = 0.0;
  for (const auto& f : m.faces) {
    for (int i = 0; i < 3; ++i) sum += (m.vertices[f[i]] - m.vertices[f[(i + 1) % 3]]).norm();
  }
  return sum / (3.0 * m.faces.size());
}

// Moves each vertex along `normal(v)` by Gaussian noise of deviation sigma.
template <class Normal>
void AddNoise(Triangles& m, double sigma, Normal normal, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& v : m.vertices) v += noise(rng) * normal(v).normalized();
}

// A cube [-s, s]^3, each side an n x n grid of squares split along a
// diagonal (the service tests' SplitBox, centred).
inline Triangles Cube(double s, int n) {
  const testing_files::TestMesh box = testing_files::SplitBox(n, Eigen::Vector3d::Constant(2 * s));
  Triangles m{box.v, box.f};
  for (auto& v : m.vertices) v -= Eigen::Vector3d::Constant(s);
  return m;
}

// Distance from p to the surface of the cube [-s, s]^3.
inline double CubeDistance(const Eigen::Vector3d& p, double s) {
  const Eigen::Vector3d q = p.cwiseAbs() - Eigen::Vector3d::Constant(s);
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : -q.maxCoeff();
}

inline absl::StatusOr<Mesh> ToMesh(const Triangles& t, std::string name) {
  return BuildMesh(t.vertices, t.faces, std::move(name));
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_
