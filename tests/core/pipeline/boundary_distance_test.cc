#include "pipeline/boundary_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "gtest/gtest.h"

namespace meshseg::pipeline_internal {
namespace {

constexpr int kSize = 8;  // grid squares per side

// A unit grid of kSize x kSize squares in z = 0, two triangles each; vertex
// (i, j) has index i + (kSize + 1) * j, faces 2 (i + kSize * j) and the next
// cover square (i, j).
TriMesh Grid() {
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (int j = 0; j <= kSize; ++j) {
    for (int i = 0; i <= kSize; ++i) v.push_back(m.add_vertex({1.0 * i, 1.0 * j, 0.0}));
  }
  const auto at = [&](int i, int j) { return v[i + (kSize + 1) * j]; };
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return m;
}

TEST(VertexBoundaryDistance, EdgePathToTheNearestLabelChangeOrBorder) {
  // Label 0 left of x = 3, label 1 right of it: the vertices on x = 3 and
  // on the grid's border are boundary vertices; the others are as many unit
  // edges from the nearest of them as they are squares away.
  const TriMesh grid = Grid();
  std::vector<int> labels(grid.n_faces());
  for (int f = 0; f < static_cast<int>(labels.size()); ++f) labels[f] = (f / 2) % kSize < 3 ? 0 : 1;
  const std::vector<double> d = VertexBoundaryDistance(grid, labels);
  ASSERT_EQ(d.size(), grid.n_vertices());
  for (int j = 0; j <= kSize; ++j) {
    for (int i = 0; i <= kSize; ++i) {
      const int expected = std::min({std::abs(i - 3), i, kSize - i, j, kSize - j});
      EXPECT_DOUBLE_EQ(d[i + (kSize + 1) * j], expected) << "vertex (" << i << ", " << j << ")";
    }
  }
}

TEST(VertexBoundaryDistance, TheSearchStopsAtTheLimit) {
  // As above, with the search cut at 2: the vertices 2 or more edges from
  // every boundary vertex are at infinity.
  const TriMesh grid = Grid();
  std::vector<int> labels(grid.n_faces());
  for (int f = 0; f < static_cast<int>(labels.size()); ++f) labels[f] = (f / 2) % kSize < 3 ? 0 : 1;
  const std::vector<double> d = VertexBoundaryDistance(grid, labels, 2.0);
  for (int j = 0; j <= kSize; ++j) {
    for (int i = 0; i <= kSize; ++i) {
      const int expected = std::min({std::abs(i - 3), i, kSize - i, j, kSize - j});
      const double got = d[i + (kSize + 1) * j];
      if (expected < 2) {
        EXPECT_DOUBLE_EQ(got, expected) << "vertex (" << i << ", " << j << ")";
      } else {
        EXPECT_TRUE(std::isinf(got)) << "vertex (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(VertexBoundaryDistance, AClosedSurfaceOfOneLabelHasNoBoundary) {
  TriMesh tetrahedron;
  const auto a = tetrahedron.add_vertex({0, 0, 0});
  const auto b = tetrahedron.add_vertex({1, 0, 0});
  const auto c = tetrahedron.add_vertex({0, 1, 0});
  const auto e = tetrahedron.add_vertex({0, 0, 1});
  tetrahedron.add_face(a, c, b);
  tetrahedron.add_face(a, b, e);
  tetrahedron.add_face(b, c, e);
  tetrahedron.add_face(c, a, e);
  for (const double d : VertexBoundaryDistance(tetrahedron, std::vector<int>(4, 7))) {
    EXPECT_TRUE(std::isinf(d));
  }
  // Face c-a-e of another label: its corners are boundary vertices, b is
  // one unit edge (to a) from them.
  const std::vector<double> d = VertexBoundaryDistance(tetrahedron, std::vector<int>{7, 7, 7, 2});
  EXPECT_EQ(d[a.idx()], 0.0);
  EXPECT_EQ(d[c.idx()], 0.0);
  EXPECT_EQ(d[e.idx()], 0.0);
  EXPECT_DOUBLE_EQ(d[b.idx()], 1.0);
}

}  // namespace
}  // namespace meshseg::pipeline_internal
