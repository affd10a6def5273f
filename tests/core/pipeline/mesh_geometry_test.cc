// The mesh a result's ids refer to, copied out with the input face of each
// triangle: polygons fan-triangulated into consecutive triangles, dropped
// input faces skipped, vertices in file order.
#include "pipeline/mesh_geometry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>  // cross()
#include <algorithm>
#include <array>
#include <fstream>
#include <string>
#include <vector>

#include "scratch_dir.h"

namespace meshseg::pipeline_internal {
namespace {

using ::testing::ElementsAre;

// A unit cube as six outward quads, with a degenerate triangle (a repeated
// index, dropped while loading) as input face 2.
constexpr std::array<std::array<double, 3>, 8> kCorners = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
const std::vector<std::vector<int>> kInputFaces = {
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 0, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

std::string WriteCubeOff() {
  const std::string path = testing_files::ScratchPath("cube.off");
  std::ofstream out(path);
  out << "OFF\n" << kCorners.size() << " " << kInputFaces.size() << " 0\n";
  for (const auto& c : kCorners) out << c[0] << " " << c[1] << " " << c[2] << "\n";
  for (const std::vector<int>& face : kInputFaces) {
    out << face.size();
    for (int v : face) out << " " << v;
    out << "\n";
  }
  return path;
}

TEST(GeometryOf, EveryTriangleNamesThePolygonItCameFrom) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteCubeOff());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshGeometry g = GeometryOf(mesh->tri, mesh->face_of_input);

  ASSERT_EQ(g.vertices.size(), kCorners.size());
  for (std::size_t v = 0; v < kCorners.size(); ++v) {
    EXPECT_EQ(g.vertices[v], Eigen::Vector3d(kCorners[v][0], kCorners[v][1], kCorners[v][2]));
  }
  // Two triangles per quad, none for the dropped face 2.
  EXPECT_THAT(g.input_face, ElementsAre(0, 0, 1, 1, 3, 3, 4, 4, 5, 5, 6, 6));
  ASSERT_EQ(g.faces.size(), g.input_face.size());
  for (std::size_t f = 0; f < g.faces.size(); ++f) {
    const std::vector<int>& polygon = kInputFaces[g.input_face[f]];
    for (int v : g.faces[f]) {
      EXPECT_NE(std::find(polygon.begin(), polygon.end(), v), polygon.end())
          << "triangle " << f << " has vertex " << v << ", not a corner of its input face";
    }
    // The winding is the polygon's: the triangle's normal points out of the
    // cube, as the quad's does.
    const Eigen::Vector3d a = g.vertices[g.faces[f][0]], b = g.vertices[g.faces[f][1]],
                          c = g.vertices[g.faces[f][2]];
    const Eigen::Vector3d outward = (a + b + c) / 3.0 - Eigen::Vector3d(0.5, 0.5, 0.5);
    EXPECT_GT((b - a).cross(c - a).dot(outward), 0.0) << "triangle " << f;
  }
}

TEST(GeometryOf, AReconstructedMeshHasNoInputFaces) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteCubeOff());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshGeometry g = GeometryOf(mesh->tri, {});
  EXPECT_EQ(g.faces.size(), 12u);
  EXPECT_TRUE(g.input_face.empty());
}

}  // namespace
}  // namespace meshseg::pipeline_internal
