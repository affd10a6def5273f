#include <cmath>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::BinaryStl;
using testing_files::CubeTriangles;
using testing_files::WriteTemp;

std::string AsciiStl(const std::vector<testing_files::Tri>& triangles) {
  std::string out = "solid cube\n";
  for (const auto& t : triangles) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto& v : t) {
      out += "      vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
             std::to_string(v[2]) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid cube\n";
}

void ExpectClosedCube(const absl::StatusOr<Mesh>& mesh) {
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshStats stats = MeshStatistics(*mesh);
  EXPECT_EQ(stats.vertex_count, 8);  // 36 corners welded
  EXPECT_EQ(stats.input_vertex_count, 36);
  EXPECT_EQ(stats.face_count, 12);
  EXPECT_EQ(stats.boundary_edge_count, 0);
  EXPECT_EQ(stats.component_count, 1);
}

TEST(ReadStl, ReadsAsciiAndWeldsCorners) {
  ExpectClosedCube(ReadMesh(WriteTemp("cube_ascii.stl", AsciiStl(CubeTriangles()))));
}

TEST(ReadStl, ReadsBinaryAndWeldsCorners) {
  ExpectClosedCube(ReadMesh(WriteTemp("cube_binary.stl", BinaryStl(CubeTriangles()))));
}

TEST(ReadStl, ReadsBinaryWhoseHeaderStartsWithSolid) {
  ExpectClosedCube(ReadMesh(
      WriteTemp("solid_header.stl", BinaryStl(CubeTriangles(), -1, "solid but binary"))));
}

TEST(ReadStl, WeldsNegativeZeroWithZero) {
  std::vector<testing_files::Tri> tris = CubeTriangles();
  for (auto& t : tris) {
    for (auto& v : t) {
      for (float& c : v) {
        if (c == 0.0f) c = -0.0f;
      }
    }
  }
  tris[0][0] = {0.0f, 0.0f, 0.0f};  // one corner with +0.0
  ExpectClosedCube(ReadMesh(WriteTemp("negative_zero.stl", BinaryStl(tris))));
}

TEST(ReadStl, RejectsTruncatedBinary) {
  std::string bytes = BinaryStl(CubeTriangles());
  bytes.resize(bytes.size() - 30);
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("truncated_binary.stl", bytes));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("\"truncated_binary.stl\""));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("header declares 12 triangles, file holds 11"));
}

TEST(ReadStl, RejectsHugeDeclaredCountBeforeAllocating) {
  const std::string bytes = BinaryStl(CubeTriangles(), 4'000'000'000LL);
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("huge_count.stl", bytes));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("huge_count.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("4000000000 triangles"));
}

TEST(ReadStl, RejectsCountOverMaxElements) {
  ReadMeshOptions options;
  options.max_elements = 10;
  const absl::StatusOr<Mesh> mesh =
      ReadMesh(WriteTemp("over_limit.stl", BinaryStl(CubeTriangles())), options);
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("over the limit of 10"));
}

TEST(ReadStl, RejectsNanVertexInBinary) {
  std::vector<testing_files::Tri> tris = CubeTriangles();
  tris[3][1][2] = std::numeric_limits<float>::quiet_NaN();
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("nan_vertex.stl", BinaryStl(tris)));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("nan_vertex.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("triangle 3"));
}

TEST(ReadStl, RejectsInfVertexInAsciiWithLine) {
  std::string text = AsciiStl(CubeTriangles());
  const size_t at = text.find("vertex", text.find("vertex") + 1);
  text.replace(at, 6, "vertex inf");  // the second vertex, on line 5
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("inf_vertex.stl", text));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("inf_vertex.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("line 5"));
}

TEST(ReadStl, RejectsFacetWithFourVertices) {
  const std::string text =
      "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n";
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("four_vertex_facet.stl", text));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("four_vertex_facet.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("line 8: facet has 4 vertices"));
}

TEST(ReadStl, RejectsEmptySolid) {
  const absl::StatusOr<Mesh> mesh =
      ReadMesh(WriteTemp("empty_solid.stl", "solid x\nendsolid x\n"));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("empty_solid.stl"));
}

TEST(ReadStl, RejectsBinaryWhoseTrianglesAreAllDegenerate) {
  // Two triangles: three collinear corners, and one corner repeated (which
  // welding turns into a repeated index).
  const std::vector<testing_files::Tri> tris = {
      {{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}}},
      {{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}}};
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("all_degenerate.stl", BinaryStl(tris)));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("all_degenerate.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("all 2 faces dropped (2 degenerate"));
}

TEST(ReadStl, RejectsShortBinary) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("short.stl", std::string(40, '\0')));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("short.stl"));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr("40 bytes"));
}

}  // namespace
}  // namespace meshseg
