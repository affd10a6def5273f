// BuildManifold must build exactly the mesh add_face() builds.
#include "mesh/manifold_build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

struct Soup {
  std::vector<TriMesh::Point> points;
  LargeVector<std::array<int, 3>> triangles;
};

// An n x n grid of squares in z = 0, two triangles each, with the squares in
// `holes` left out.
Soup Grid(int n, const std::vector<int>& holes = {}) {
  Soup s;
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) s.points.emplace_back(x, y, 0.0);
  }
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      if (std::find(holes.begin(), holes.end(), y * n + x) != holes.end()) continue;
      const int a = y * (n + 1) + x;
      s.triangles.push_back({a, a + 1, a + n + 2});
      s.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  }
  return s;
}

// A closed UV sphere with single pole vertices.
Soup Sphere(int lat, int lon) {
  Soup s;
  s.points.emplace_back(0, 0, 1);
  for (int i = 1; i < lat; ++i) {
    for (int j = 0; j < lon; ++j) {
      const double t = M_PI * i / lat, p = 2 * M_PI * j / lon;
      s.points.emplace_back(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
    }
  }
  s.points.emplace_back(0, 0, -1);
  const int south = static_cast<int>(s.points.size()) - 1;
  auto ring = [lon](int i, int j) { return 1 + (i - 1) * lon + (j % lon); };
  for (int j = 0; j < lon; ++j) {
    s.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < lat; ++i) {
      s.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
    s.triangles.push_back({ring(lat - 1, j), south, ring(lat - 1, j + 1)});
  }
  return s;
}

void AddVertices(const Soup& s, TriMesh* m) {
  for (const auto& p : s.points) m->add_vertex(p);
}

void ExpectSameMesh(const Soup& s) {
  TriMesh reference, fast;
  AddVertices(s, &reference);
  AddVertices(s, &fast);
  for (const auto& t : s.triangles) {
    ASSERT_TRUE(reference
                    .add_face(TriMesh::VertexHandle(t[0]), TriMesh::VertexHandle(t[1]),
                              TriMesh::VertexHandle(t[2]))
                    .is_valid());
  }
  ASSERT_TRUE(BuildManifold(s.triangles, &fast));
  ASSERT_EQ(fast.n_faces(), reference.n_faces());
  ASSERT_EQ(fast.n_edges(), reference.n_edges());
  for (const auto f : fast.faces()) {
    std::vector<int> a, b;
    for (const auto v : fast.fv_range(f)) a.push_back(v.idx());
    for (const auto v : reference.fv_range(TriMesh::FaceHandle(f.idx()))) b.push_back(v.idx());
    EXPECT_EQ(a, b) << "face " << f.idx();
  }
  for (const auto v : fast.vertices()) {
    const auto r = TriMesh::VertexHandle(v.idx());
    EXPECT_EQ(fast.is_boundary(v), reference.is_boundary(r)) << "vertex " << v.idx();
    EXPECT_EQ(fast.valence(v), reference.valence(r)) << "vertex " << v.idx();
    // OpenMesh's invariant: a boundary vertex points at a boundary halfedge.
    if (fast.is_boundary(v)) {
      EXPECT_TRUE(fast.is_boundary(fast.halfedge_handle(v))) << "vertex " << v.idx();
    }
  }
  for (const auto h : fast.halfedges()) {
    EXPECT_EQ(fast.prev_halfedge_handle(fast.next_halfedge_handle(h)), h);
    EXPECT_EQ(fast.from_vertex_handle(fast.next_halfedge_handle(h)), fast.to_vertex_handle(h));
    EXPECT_EQ(fast.from_vertex_handle(h), fast.to_vertex_handle(fast.opposite_halfedge_handle(h)));
  }
}

// The halfedge index each halfedge 3t+k (corner k -> k+1 of triangle t) must
// get: edges numbered in order of the halfedge that reaches them first, that
// halfedge 2e, its twin 2e+1 (what add_face() in triangle order gives).
std::vector<int> ExpectedHalfedgeIndices(const Soup& s) {
  std::map<std::pair<int, int>, int> edge_of;  // undirected edge -> number
  std::vector<int> out;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const auto [it, inserted] =
          edge_of.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<int>(edge_of.size()));
      out.push_back(2 * it->second + (inserted ? 0 : 1));
    }
  }
  return out;
}

TEST(BuildManifold, NumbersEdgesAsAddFaceOnALargeGridWithHoles) {
  // Large enough that the edge numbering and linking run in several blocks.
  const Soup s = Grid(130, {5, 400, 401, 531, 9000, 16000});
  ExpectSameMesh(s);
  TriMesh m;
  AddVertices(s, &m);
  ASSERT_TRUE(BuildManifold(s.triangles, &m));
  const std::vector<int> expected = ExpectedHalfedgeIndices(s);
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
    for (const auto h : m.fh_range(TriMesh::FaceHandle(t))) {
      const int from = m.from_vertex_handle(h).idx();
      const int k = static_cast<int>(std::find(s.triangles[t].begin(), s.triangles[t].end(), from) -
                                     s.triangles[t].begin());
      ASSERT_LT(k, 3);
      EXPECT_EQ(h.idx(), expected[3 * t + k]) << "triangle " << t << " corner " << k;
    }
  }
}

TEST(BuildManifold, MatchesAddFaceOnOpenGrid) { ExpectSameMesh(Grid(6)); }

TEST(BuildManifold, MatchesAddFaceOnGridWithHoles) { ExpectSameMesh(Grid(7, {8, 9, 30})); }

TEST(BuildManifold, MatchesAddFaceOnClosedSphere) { ExpectSameMesh(Sphere(12, 16)); }

TEST(BuildManifold, RefusesInconsistentOrientationWithoutTouchingTheMesh) {
  Soup s = Grid(2);
  std::swap(s.triangles[1][1], s.triangles[1][2]);  // flips one triangle
  TriMesh m;
  AddVertices(s, &m);
  EXPECT_FALSE(BuildManifold(s.triangles, &m));
  EXPECT_EQ(m.n_faces(), 0u);
  EXPECT_EQ(m.n_edges(), 0u);
  EXPECT_EQ(m.n_vertices(), s.points.size());
}

}  // namespace
}  // namespace meshseg::mesh_internal
