#include "voxel/edge_collapse.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace meshseg::voxel_internal {
namespace {

// A closed cylinder (radius 1, z in [-1, 1]): `around` x `along` side
// quads and two caps of `rings` rings each; its rims are two curved creases.
TriMesh CappedCylinder(int around, int along, int rings) {
  std::vector<Eigen::Vector3d> p;
  std::vector<std::array<int, 3>> t;
  const auto angle = [around](int j) { return 2.0 * std::numbers::pi * j / around; };
  for (int i = 0; i <= along; ++i) {
    for (int j = 0; j < around; ++j) {
      p.emplace_back(std::cos(angle(j)), std::sin(angle(j)), -1.0 + 2.0 * i / along);
    }
  }
  const auto side = [around](int i, int j) { return i * around + (j % around); };
  for (int i = 0; i < along; ++i) {
    for (int j = 0; j < around; ++j) {
      t.push_back({side(i, j), side(i, j + 1), side(i + 1, j + 1)});
      t.push_back({side(i, j), side(i + 1, j + 1), side(i + 1, j)});
    }
  }
  for (const int cap : {0, along}) {
    const double z = cap == 0 ? -1.0 : 1.0;
    int outer_start = cap * around;  // the rim
    for (int r = rings - 1; r >= 0; --r) {
      const int inner_start = static_cast<int>(p.size());
      const double radius = static_cast<double>(r) / rings;
      if (r == 0) {
        p.emplace_back(0.0, 0.0, z);
      } else {
        for (int j = 0; j < around; ++j) {
          p.emplace_back(radius * std::cos(angle(j)), radius * std::sin(angle(j)), z);
        }
      }
      for (int j = 0; j < around; ++j) {
        const int a = outer_start + j, b = outer_start + (j + 1) % around;
        const int c = r == 0 ? inner_start : inner_start + j;
        const int d = r == 0 ? inner_start : inner_start + (j + 1) % around;
        // Outward normals: -z on the bottom cap, +z on the top.
        if (z > 0) {
          t.push_back({a, b, d});
          if (r != 0) t.push_back({a, d, c});
        } else {
          t.push_back({a, d, b});
          if (r != 0) t.push_back({a, c, d});
        }
      }
      outer_start = inner_start;
    }
  }
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (const auto& x : p) v.push_back(m.add_vertex(TriMesh::Point(x.x(), x.y(), x.z())));
  for (const auto& f : t) m.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return m;
}

// Surviving crease edges after collapsing `m` to `target` faces; checks that
// each lies on a rim (its ends in a cap plane, on the rim circle's chords).
int CreaseEdgesLeft(TriMesh m, size_t target, bool interior_planes) {
  std::vector<uint8_t> crease(m.n_edges(), 0);  // the rim edges
  for (auto e : m.edges()) {
    const auto a = m.point(e.v0()), b = m.point(e.v1());
    crease[e.idx()] = a[2] == b[2] && std::abs(a[2]) == 1.0 && std::hypot(a[0], a[1]) > 0.999 &&
                      std::hypot(b[0], b[1]) > 0.999;
  }
  std::vector<uint8_t> after;
  const CollapseParams params{.target_faces = target, .interior_crease_planes = interior_planes};
  EXPECT_TRUE(CollapseEdges(m, params, {}, crease, {}, &after).ok());
  EXPECT_EQ(after.size(), m.n_edges());
  int left = 0;
  for (auto e : m.edges()) {
    if (m.status(e).deleted() || !after[e.idx()]) continue;
    ++left;
    for (auto v : {e.v0(), e.v1()}) {
      const auto x = m.point(v);
      EXPECT_NEAR(std::abs(x[2]), 1.0, 1e-12);
      EXPECT_GT(std::hypot(x[0], x[1]), std::cos(std::numbers::pi / 3)) << "far inside the rim";
      EXPECT_LT(std::hypot(x[0], x[1]), 1.0 + 1e-12);
    }
  }
  return left;
}

TEST(CollapseEdges, CurvedCreasesStayOnTheirLineWithOrWithoutInteriorPlanes) {
  // Crease vertices slide only along their crease edges, so at a sixtieth
  // of the faces both rims are still closed loops of chords of the circle
  // in their cap planes, with the constraint planes on interior creases or
  // without them; the flags handed back mark exactly those chords.
  const TriMesh m = CappedCylinder(96, 24, 8);
  const size_t target = m.n_faces() / 60;
  for (const bool planes : {true, false}) {
    EXPECT_GE(CreaseEdgesLeft(m, target, planes), 2 * 3) << "planes " << planes;
  }
}

}  // namespace
}  // namespace meshseg::voxel_internal
