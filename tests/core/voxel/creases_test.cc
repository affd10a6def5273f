#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"
#include "voxel/edge_collapse.h"
#include "voxel_shapes.h"

namespace meshseg {
namespace {

constexpr double kH = 0.5;
constexpr double kDegrees = 17.0;
constexpr double kBevel = 2.5 * kH;

// The box's own frame: TurnedBox turns by kDegrees about (1, 2, 3).
Eigen::Vector3d InBoxFrame(const Eigen::Vector3d& p) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(kDegrees * 3.14159265358979 / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  return r.transpose() * p;
}

// A marching-cubes box (grey, noise-free): the creases found are along its
// 12 edges. A crease edge counts as on a box edge within 2.5 voxels
// (marching cubes interpolates the distance field linearly, but around an
// edge it is not linear, so the cut corner reaches into the cells two voxels
// from the edge). Measured: 7 of 689 crease edges lie on the faces
// (slivers of the ripple the clamped grey ramp leaves), and 88 of the 96
// interior tenths of the edges hold creases (where the cut corner is spread
// over three face rows, no one-ring turns by 30 deg). Bounds: at most 2 % of
// the crease edges off the box edges, at least 80 % of the tenths covered,
// and every box edge has creases along at least half its length.
TEST(CreaseEdges, FindTheEdgesOfABoxAndFewOnItsFaces) {
  const Eigen::Vector3d half(5, 4, 3);
  const VolumeSurface s = testing::SurfaceOf(
      testing::SampleSdf(testing::TurnedBox(half, kDegrees), 36, kH, false), "crease_box.nrrd");
  const TriMesh& mesh = s.mesh.tri;
  const std::vector<uint8_t> crease = voxel_internal::CreaseEdges(mesh, 30.0);
  ASSERT_EQ(crease.size(), mesh.n_edges());
  // Per box edge (axis, side signs), which tenths of its length hold creases.
  std::vector<std::vector<bool>> covered(12, std::vector<bool>(10, false));
  int creases = 0, off = 0;
  for (auto e : mesh.edges()) {
    if (!crease[e.idx()]) continue;
    ++creases;
    const Eigen::Vector3d q = InBoxFrame(ToEigen(mesh.calc_edge_midpoint(e)));
    int near_sides = 0, free_axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (std::abs(std::abs(q[a]) - half[a]) <= kBevel) {
        ++near_sides;
      } else {
        free_axis = a;
      }
    }
    off += near_sides < 2;
    if (near_sides != 2) continue;
    const int b = (free_axis + 1) % 3, c = (free_axis + 2) % 3;
    const int edge = 4 * free_axis + 2 * (q[b] > 0) + (q[c] > 0);
    const int tenth =
        std::clamp(static_cast<int>((q[free_axis] / half[free_axis] + 1.0) * 5.0), 0, 9);
    covered[edge][tenth] = true;
  }
  int tenths = 0;
  for (int edge = 0; edge < 12; ++edge) {
    int here = 0;
    for (int tenth = 1; tenth < 9; ++tenth) here += covered[edge][tenth];
    EXPECT_GE(here, 4) << "box edge " << edge;
    tenths += here;
  }
  std::cout << creases << " crease edges, " << off << " off the box edges; " << tenths
            << " of 96 tenths covered\n";
  EXPECT_LE(off, 0.02 * creases);
  EXPECT_GE(tenths, 0.8 * 96);
}

// Open borders are feature lines too.
TEST(CreaseEdges, MarkOpenBorders) {
  const absl::StatusOr<Mesh> mesh = BuildMesh({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                               Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)},
                                              {{0, 1, 2}, {0, 2, 3}}, "quad");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::vector<uint8_t> crease = voxel_internal::CreaseEdges(mesh->tri, 30.0);
  int border = 0, inner = 0;
  for (auto e : mesh->tri.edges()) {
    (mesh->tri.is_boundary(e) ? border : inner) += crease[e.idx()];
  }
  EXPECT_EQ(border, 4);
  EXPECT_EQ(inner, 0);
}

}  // namespace
}  // namespace meshseg
