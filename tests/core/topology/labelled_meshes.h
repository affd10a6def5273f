// Small labelled meshes with known boundary structure for the topology
// tests: a gridded box (six planes) and a capped cylinder (two planes and a
// cylinder), with their ground-truth regions.
#ifndef MESHSEG_TESTS_CORE_TOPOLOGY_LABELLED_MESHES_H_
#define MESHSEG_TESTS_CORE_TOPOLOGY_LABELLED_MESHES_H_

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"

namespace meshseg::testing {

struct LabelledMesh {
  Mesh mesh;
  std::vector<int> face_labels;
  std::vector<Region> regions;
};

inline Region PlaneRegion(int id, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  Region r;
  r.id = id;
  r.type = SurfaceType::kPlane;
  r.surface = Plane{point, normal.normalized()};
  return r;
}

// The box [0, size.x] x [0, size.y] x [0, size.z], each side an n x n grid.
// Labels: 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z. Planes 1, 3 and 5 carry inward
// normals, as a fit may return them.
inline LabelledMesh GriddedBox(const Eigen::Vector3d& size, int n) {
  std::map<std::tuple<int, int, int>, int> index;
  std::vector<Eigen::Vector3d> vertices;
  auto vertex = [&](int i, int j, int k) {
    auto [it, inserted] = index.try_emplace({i, j, k}, static_cast<int>(vertices.size()));
    if (inserted) {
      vertices.push_back({size.x() * i / n, size.y() * j / n, size.z() * k / n});
    }
    return it->second;
  };
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> labels;
  // Side `label` along axis `axis` at grid coordinate `at` (0 or n); (u, v)
  // span the other two axes so that u x v points outward.
  auto side = [&](int label, int axis, int at) {
    const int u_axis = (axis + 1) % 3;
    const int v_axis = (axis + 2) % 3;
    const bool flip = at == 0;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        std::array<int, 4> quad;
        const int du[4] = {0, 1, 1, 0};
        const int dv[4] = {0, 0, 1, 1};
        for (int q = 0; q < 4; ++q) {
          int c[3];
          c[axis] = at;
          c[u_axis] = a + du[q];
          c[v_axis] = b + dv[q];
          quad[q] = vertex(c[0], c[1], c[2]);
        }
        if (flip) std::swap(quad[1], quad[3]);
        triangles.push_back({quad[0], quad[1], quad[2]});
        triangles.push_back({quad[0], quad[2], quad[3]});
        labels.push_back(label);
        labels.push_back(label);
      }
    }
  };
  for (int axis = 0; axis < 3; ++axis) {
    side(2 * axis, axis, 0);
    side(2 * axis + 1, axis, n);
  }
  LabelledMesh out;
  out.mesh = *BuildMesh(std::move(vertices), triangles, "box");
  out.face_labels = labels;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    out.regions.push_back(PlaneRegion(2 * axis, Eigen::Vector3d::Zero(), -e));
    out.regions.push_back(PlaneRegion(2 * axis + 1, size.cwiseProduct(e), -e));
  }
  return out;
}

// A cylinder of `radius` and `height` on the z axis from z = 0, closed by
// two discs: m segments around, k rows along, `rings` rings per disc.
// Labels: 0 bottom disc, 1 side, 2 top disc.
inline LabelledMesh CappedCylinder(double radius, double height, int m, int k, int rings) {
  std::vector<Eigen::Vector3d> vertices;
  auto ring_point = [&](double r, int i, double z) {
    const double t = 2.0 * std::numbers::pi * i / m;
    vertices.push_back({r * std::cos(t), r * std::sin(t), z});
  };
  // Side rows 0..k; disc rings 1..rings-1 inside each cap; two centres.
  for (int j = 0; j <= k; ++j) {
    for (int i = 0; i < m; ++i) ring_point(radius, i, height * j / k);
  }
  auto side = [&](int j, int i) { return j * m + (i % m); };
  std::array<int, 2> centre{};
  std::array<int, 2> inner_start{};
  for (int cap = 0; cap < 2; ++cap) {
    const double z = cap == 0 ? 0.0 : height;
    inner_start[cap] = static_cast<int>(vertices.size());
    for (int r = 1; r < rings; ++r) {
      for (int i = 0; i < m; ++i) ring_point(radius * r / rings, i, z);
    }
    centre[cap] = static_cast<int>(vertices.size());
    vertices.push_back({0.0, 0.0, z});
  }
  // Vertex of ring r (0 = centre, rings = rim) of a cap.
  auto cap_vertex = [&](int cap, int r, int i) {
    if (r == 0) return centre[cap];
    if (r == rings) return side(cap == 0 ? 0 : k, i);
    return inner_start[cap] + (r - 1) * m + (i % m);
  };
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> labels;
  auto add = [&](int a, int b, int c, int label, bool flip) {
    triangles.push_back(flip ? std::array<int, 3>{a, c, b} : std::array<int, 3>{a, b, c});
    labels.push_back(label);
  };
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < m; ++i) {
      add(side(j, i), side(j, i + 1), side(j + 1, i + 1), 1, false);
      add(side(j, i), side(j + 1, i + 1), side(j + 1, i), 1, false);
    }
  }
  for (int cap = 0; cap < 2; ++cap) {
    const int label = cap == 0 ? 0 : 2;
    const bool flip = cap == 0;  // the bottom faces down
    for (int i = 0; i < m; ++i) add(centre[cap], cap_vertex(cap, 1, i), cap_vertex(cap, 1, i + 1),
                                    label, flip);
    for (int r = 1; r < rings; ++r) {
      for (int i = 0; i < m; ++i) {
        const int a = cap_vertex(cap, r, i);
        const int b = cap_vertex(cap, r + 1, i);
        const int c = cap_vertex(cap, r + 1, i + 1);
        const int d = cap_vertex(cap, r, i + 1);
        add(a, b, c, label, flip);
        add(a, c, d, label, flip);
      }
    }
  }
  LabelledMesh out;
  out.mesh = *BuildMesh(std::move(vertices), triangles, "cylinder");
  out.face_labels = labels;
  out.regions.push_back(PlaneRegion(0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
  Region side_region;
  side_region.id = 1;
  side_region.type = SurfaceType::kCylinder;
  side_region.surface = Cylinder{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), radius};
  out.regions.push_back(side_region);
  out.regions.push_back(PlaneRegion(2, {0.0, 0.0, height}, Eigen::Vector3d::UnitZ()));
  return out;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_TOPOLOGY_LABELLED_MESHES_H_
