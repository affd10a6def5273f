// Small analytic meshes with known curvature for the curvature tests.
#ifndef MESHSEG_TESTS_CORE_CURVATURE_TEST_MESHES_H_
#define MESHSEG_TESTS_CORE_CURVATURE_TEST_MESHES_H_

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "meshseg/mesh.h"

namespace meshseg::testing {

// Sphere of `radius` at the origin: icosahedron subdivided `levels` times.
inline absl::StatusOr<Mesh> MakeSphere(double radius, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                    {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                    {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]) / 2.0);
      mid[key] = static_cast<int>(v.size()) - 1;
      return static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& tri : f) {
      const int ab = midpoint(tri[0], tri[1]);
      const int bc = midpoint(tri[1], tri[2]);
      const int ca = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f = std::move(g);
  }
  for (auto& p : v) p = p.normalized() * radius;
  return BuildMesh(std::move(v), f, "sphere");
}

// A (nu x nw)-vertex grid mapped through `point(s, t)`, s, t in [0, 1].
inline absl::StatusOr<Mesh> MakeGrid(int nu, int nw,
                                     const std::function<Eigen::Vector3d(double, double)>& point,
                                     const char* name) {
  std::vector<Eigen::Vector3d> v;
  for (int j = 0; j < nw; ++j) {
    for (int i = 0; i < nu; ++i) v.push_back(point(double(i) / (nu - 1), double(j) / (nw - 1)));
  }
  std::vector<std::array<int, 3>> f;
  for (int j = 0; j + 1 < nw; ++j) {
    for (int i = 0; i + 1 < nu; ++i) {
      const int a = j * nu + i;
      f.push_back({a, a + 1, a + nu + 1});
      f.push_back({a, a + nu + 1, a + nu});
    }
  }
  return BuildMesh(std::move(v), f, name);
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_CURVATURE_TEST_MESHES_H_
