// Parametric closed meshes for the handle tests: tori (genus 1; the meridian
// is the tube's loop, the longitude runs round the hole) and capped rods
// (genus 0; a short loop that separates).
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_TUBE_MESHES_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_TUBE_MESHES_H_

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

struct TubeMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;

  // Appends `other` (a separate component).
  void Add(const TubeMesh& other) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& t : other.triangles)
      triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
};

// Appends the triangles of a closed nu × nv grid of vertices (vertex i × nv
// + j, both directions wrapping round): a torus-like surface.
inline void AddTorusGrid(int nu, int nv, TubeMesh* m) {
  const auto id = [&](int i, int j) { return (i % nu) * nv + j % nv; };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      m->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
}

// Torus about the z axis through `center`: major radius R, minor r, nu
// vertices round the axis and nv round the tube.
inline TubeMesh TorusTubeMesh(double R, double r, int nu, int nv,
                              const Eigen::Vector3d& center = Eigen::Vector3d::Zero()) {
  TubeMesh m;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.vertices.push_back(center + Eigen::Vector3d((R + r * std::cos(v)) * std::cos(u),
                                                    (R + r * std::cos(v)) * std::sin(u),
                                                    r * std::sin(v)));
    }
  }
  AddTorusGrid(nu, nv, &m);
  return m;
}

// Rod along z from `base`: radius r, length `length`, n vertices round it,
// `rings` + 1 rings along it, each end closed by a fan.
inline TubeMesh RodTubeMesh(double r, double length, int n, int rings,
                            const Eigen::Vector3d& base) {
  TubeMesh m;
  for (int k = 0; k <= rings; ++k) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n;
      m.vertices.push_back(base +
                           Eigen::Vector3d(r * std::cos(u), r * std::sin(u), length * k / rings));
    }
  }
  const auto id = [&](int i, int k) { return k * n + i % n; };
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, k), id(i + 1, k), id(i + 1, k + 1)});
      m.triangles.push_back({id(i, k), id(i + 1, k + 1), id(i, k + 1)});
    }
  }
  const int bottom = static_cast<int>(m.vertices.size());
  m.vertices.push_back(base);
  const int top = bottom + 1;
  m.vertices.push_back(base + Eigen::Vector3d(0, 0, length));
  for (int i = 0; i < n; ++i) {
    m.triangles.push_back({bottom, id(i + 1, 0), id(i, 0)});
    m.triangles.push_back({top, id(i, rings), id(i + 1, rings)});
  }
  return m;
}

// `count` points uniform by area on the torus above (rejection on the
// tube angle), fixed seed.
inline std::vector<Eigen::Vector3d> TorusSamples(
    double R, double r, int count, const Eigen::Vector3d& center = Eigen::Vector3d::Zero()) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), accept(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  while (static_cast<int>(points.size()) < count) {
    const double u = angle(rng), v = angle(rng);
    if (accept(rng) > (R + r * std::cos(v)) / (R + r)) continue;
    points.push_back(center + Eigen::Vector3d((R + r * std::cos(v)) * std::cos(u),
                                              (R + r * std::cos(v)) * std::sin(u),
                                              r * std::sin(v)));
  }
  return points;
}

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_TUBE_MESHES_H_
