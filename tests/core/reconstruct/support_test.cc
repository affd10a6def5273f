#include "reconstruct/support.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "mesh/point_index.h"
#include "reconstruct/surface_mesh.h"

namespace meshseg::reconstruct_internal {
namespace {

// A flat strip [0, 2] × [0, 1] in z = 0, triangulated on a grid of `step`.
Mesh Strip(double step) {
  const int nx = static_cast<int>(std::lround(2.0 / step)),
            ny = static_cast<int>(std::lround(1.0 / step));
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) vertices.emplace_back(i * step, j * step, 0.0);
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  }
  return *SurfaceMesh(vertices, triangles, "strip");
}

// Points on a square grid of `spacing` covering x in [0, 1] of the strip.
std::vector<Eigen::Vector3d> HalfCovered(double spacing) {
  std::vector<Eigen::Vector3d> points;
  const int n = static_cast<int>(std::lround(1.0 / spacing));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) points.emplace_back(i * spacing, j * spacing, 0.0);
  }
  return points;
}

// Centroid x of face f.
double CentroidX(const TriMesh& tri, TriMesh::FaceHandle f) {
  double x = 0;
  for (const auto v : tri.fv_range(f)) x += tri.point(v)[0] / 3.0;
  return x;
}

// On a square grid of spacing a the mean distance to the 6 nearest is
// (4 a + 2 √2 a) / 6 = 1.14 a inside, (3 a + 2 √2 a + 2 a) / 6 = 1.30 a on
// the last row and (2 a + √2 a + 2 · 2 a + 2 √5 a) / 6 = 1.61 a at a corner:
// sampling is sparser at the edge of the sampled area. The support reaches
// 2 × that (plus the band) past the last row of points.
TEST(SupportedFaces, FacesBeyondTwoLocalSpacingsOfTheSampledAreaAreUnsupported) {
  const Mesh strip = Strip(0.02);
  const double a = 0.05;
  const std::vector<Eigen::Vector3d> points = HalfCovered(a);
  const mesh_internal::PointIndex index(points);
  const double band = 0.01;
  const std::vector<uint8_t> supported = SupportedFaces(strip.tri, points, index, 2.0, band);
  ASSERT_EQ(supported.size(), strip.tri.n_faces());
  const double reach = 2.0 * 1.61 * a + band;  // 0.171
  for (const auto f : strip.tri.faces()) {
    const double x = CentroidX(strip.tri, f);
    // Up to 0.1 past the last row a face is within √(0.1² + 0.025²) = 0.103
    // of a point whose reach is at least 2 × 1.30 a + band = 0.14.
    if (x < 1.1) EXPECT_TRUE(supported[f.idx()]) << "x " << x;
    // Off the sampled area the nearest point is at least x − 1 away.
    if (x - 1.0 > reach) EXPECT_FALSE(supported[f.idx()]) << "x " << x;
  }
}

// The distance is relative to the density where the face is: the same gap is
// supported next to sparse points and not next to dense ones.
TEST(SupportedFaces, TheSameGapIsSupportedNextToSparsePointsOnly) {
  const Mesh strip = Strip(0.02);
  int dense_supported = 0, sparse_supported = 0, probed = 0;
  const std::vector<Eigen::Vector3d> dense = HalfCovered(0.025), sparse = HalfCovered(0.1);
  const mesh_internal::PointIndex dense_index(dense), sparse_index(sparse);
  const std::vector<uint8_t> by_dense = SupportedFaces(strip.tri, dense, dense_index, 2.0, 0.0);
  const std::vector<uint8_t> by_sparse = SupportedFaces(strip.tri, sparse, sparse_index, 2.0, 0.0);
  for (const auto f : strip.tri.faces()) {
    const double x = CentroidX(strip.tri, f);
    if (x < 1.1 || x > 1.15) continue;  // 0.1-0.15 past the last row
    ++probed;
    dense_supported += by_dense[f.idx()];
    sparse_supported += by_sparse[f.idx()];
  }
  ASSERT_GT(probed, 0);
  EXPECT_EQ(dense_supported, 0);        // reach at most 2 × 1.61 × 0.025 = 0.081
  EXPECT_EQ(sparse_supported, probed);  // reach 2 × 1.14 × 0.1 = 0.228
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
