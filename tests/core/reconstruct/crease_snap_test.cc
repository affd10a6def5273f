#include "reconstruct/crease_snap.h"

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

// The right-angled convex edge along y of the solid {x ≤ 0, z ≤ 0}: face 0 is
// z = 0 (inward normal −z), face 1 is x = 0 (inward normal −x).
Crease RightAngle() {
  Crease c;
  c.point[0] = c.point[1] = Eigen::Vector3d::Zero();
  c.normal[0] = -Eigen::Vector3d::UnitZ();
  c.normal[1] = -Eigen::Vector3d::UnitX();
  c.convex = true;
  return c;
}

// A grid strip folded over the edge: columns at s = −0.95, −0.85, ..., 0.95
// (none on the edge), s < 0 on face 0 at x = s, s > 0 on face 1 at z = −s;
// rows at y = 0, 0.1, ..., 1. Every vertex lies on the surface, as the
// projection leaves it, but the triangles between the columns ±0.05 are
// chords that cut the edge off by up to 0.035.
TriMesh FoldedStrip() {
  TriMesh mesh;
  constexpr int kColumns = 20, kRows = 11;
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kColumns; ++c) {
      const double s = -0.95 + 0.1 * c, y = 0.1 * r;
      const Eigen::Vector3d p = s < 0 ? Eigen::Vector3d(s, y, 0) : Eigen::Vector3d(0, y, -s);
      mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z()));
    }
  }
  const auto at = [&](int r, int c) { return TriMesh::VertexHandle(r * kColumns + c); };
  for (int r = 0; r + 1 < kRows; ++r) {
    for (int c = 0; c + 1 < kColumns; ++c) {
      // Diagonals alternate so both kinds of straddling triangle occur.
      if ((r + c) % 2 == 0) {
        mesh.add_face(at(r, c), at(r, c + 1), at(r + 1, c + 1));
        mesh.add_face(at(r, c), at(r + 1, c + 1), at(r + 1, c));
      } else {
        mesh.add_face(at(r, c), at(r, c + 1), at(r + 1, c));
        mesh.add_face(at(r, c + 1), at(r + 1, c + 1), at(r + 1, c));
      }
    }
  }
  return mesh;
}

TEST(SnapToCreases, EveryTriangleEndsInOneOfThePlanes) {
  TriMesh mesh = FoldedStrip();
  std::vector<std::pair<int, Crease>> creases;
  for (const auto v : mesh.vertices()) creases.emplace_back(v.idx(), RightAngle());
  const CreaseSnap snap = SnapToCreases(creases, &mesh);
  // A vertex on the line for each crossing edge: the 10 rows' horizontal
  // edges (y = 0, ..., 1: 11) and diagonals (10), each moved or added.
  EXPECT_EQ(snap.moved + snap.inserted, 21);
  for (const auto f : mesh.faces()) {
    bool in0 = true, in1 = true;
    for (const auto v : mesh.fv_range(f)) {
      in0 = in0 && std::abs(mesh.point(v)[2]) < 1e-12;
      in1 = in1 && std::abs(mesh.point(v)[0]) < 1e-12;
    }
    EXPECT_TRUE(in0 || in1) << "face " << f.idx() << " still cuts the edge: " << [&] {
      std::string s;
      for (const auto v : mesh.fv_range(f))
        s += std::to_string(mesh.point(v)[0]) + "," + std::to_string(mesh.point(v)[1]) + "," +
             std::to_string(mesh.point(v)[2]) + " ";
      return s;
    }();
  }
  // The strip's area is that of the two flat halves, 1.9 × 1 (the chords
  // cut 0.05² / 2 per unit length off the fold).
  double area = 0.0;
  for (const auto f : mesh.faces()) area += mesh.calc_face_area(f);
  EXPECT_NEAR(area, 1.9, 1e-9);
}

TEST(SnapToCreases, VerticesWithoutACreaseStay) {
  TriMesh mesh = FoldedStrip();
  const TriMesh before = mesh;
  std::vector<std::pair<int, Crease>> creases;
  // Only the outer columns (s = ±0.95) have a crease, and their edges all
  // stay on one side of it: nothing moves.
  for (const auto v : mesh.vertices()) {
    if (v.idx() % 20 == 0 || v.idx() % 20 == 19) creases.emplace_back(v.idx(), RightAngle());
  }
  const CreaseSnap snap = SnapToCreases(creases, &mesh);
  EXPECT_EQ(snap.moved + snap.inserted, 0);
  EXPECT_EQ(mesh.n_vertices(), before.n_vertices());
  for (const auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), before.point(v));
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
