#include "mesh/normals.h"

#include <cmath>

#include <gtest/gtest.h>

namespace meshseg::mesh_internal {
namespace {

TEST(SetNormals, MatchesOpenMeshUpdateNormals) {
  TriMesh a;
  // A bumpy 8 x 8 height field.
  std::vector<TriMesh::VertexHandle> v;
  for (int y = 0; y <= 8; ++y) {
    for (int x = 0; x <= 8; ++x) v.push_back(a.add_vertex({x * 0.5, y * 0.5, std::sin(x + 2.0 * y)}));
  }
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const int i = y * 9 + x;
      a.add_face(v[i], v[i + 1], v[i + 10]);
      a.add_face(v[i], v[i + 10], v[i + 9]);
    }
  }
  a.add_vertex({9, 9, 9});  // isolated
  TriMesh b = a;
  a.update_normals();
  SetNormals(&b);
  for (const auto f : a.faces()) {
    EXPECT_NEAR((a.normal(f) - b.normal(f)).norm(), 0.0, 1e-12) << "face " << f.idx();
  }
  for (const auto vh : a.vertices()) {
    EXPECT_NEAR((a.normal(vh) - b.normal(vh)).norm(), 0.0, 1e-12) << "vertex " << vh.idx();
  }
}

}  // namespace
}  // namespace meshseg::mesh_internal
