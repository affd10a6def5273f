#include <ostream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::CubeOff;
using testing_files::WriteTemp;

TEST(ReadOff, ReadsCube) {
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("cube.off", CubeOff()));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const MeshStats stats = MeshStatistics(*mesh);
  EXPECT_EQ(stats.vertex_count, 8);
  EXPECT_EQ(stats.face_count, 12);
  EXPECT_EQ(stats.boundary_edge_count, 0);
  EXPECT_NEAR(stats.mean_edge_length, (12 + 6 * std::sqrt(2.0)) / 18, 1e-12);
  EXPECT_EQ(stats.bbox_min, Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(stats.bbox_max, Eigen::Vector3d(1, 1, 1));
}

TEST(ReadOff, ReadsCountsOnHeaderLineCommentsAndColours) {
  const std::string text =
      "COFF 4 2 0\n# a comment\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n\n"
      "1 1 0 0 0 0 255\n0 1 0 0 0 0 255\n4 0 1 2 3 200 10 10\n3 0 2 1\n";
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp("square.off", text));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // The quad becomes triangles (0 1 2) and (0 2 3); the second face repeats
  // the vertex set of the first triangle and is dropped as a duplicate.
  EXPECT_EQ(mesh->tri.n_faces(), 2u);
  EXPECT_THAT(mesh->face_of_input, ::testing::ElementsAre(0, -1));
  EXPECT_EQ(mesh->input_topology.duplicate_face_count, 1);
}

struct BadOff {
  const char* file;
  const char* text;
  const char* message;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the file keeps the names
// the same from build to build.
void PrintTo(const BadOff& c, std::ostream* os) { *os << c.file; }

class ReadOffRejects : public testing::TestWithParam<BadOff> {};

TEST_P(ReadOffRejects, WithFileNameAndPlace) {
  const BadOff& bad = GetParam();
  const absl::StatusOr<Mesh> mesh = ReadMesh(WriteTemp(bad.file, bad.text));
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument) << mesh.status();
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr(std::string("\"") + bad.file + "\""));
  EXPECT_THAT(testing_files::Message(mesh.status()), HasSubstr(bad.message));
}

INSTANTIATE_TEST_SUITE_P(
    FaultyFiles, ReadOffRejects,
    testing::Values(
        BadOff{"huge_count.off", "OFF\n100000000 1 0\n0 0 0\n",
               "header declares 100000000 vertices (at least 6 bytes each), but only 6 bytes"},
        BadOff{"over_limit.off", "OFF\n900000000 1 0\n0 0 0\n",
               "header declares 900000000 vertices, over the limit of 200000000"},
        BadOff{"missing_faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# padding padding padding\n",
               "header declares 2 faces, file holds 1"},
        BadOff{"missing_vertices.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n# padding padding\n",
               "header declares 4 vertices, file holds 3"},
        BadOff{"extra_faces.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
               "line 7: data after the 1 declared faces"},
        BadOff{"out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
               "line 6: vertex index 3 out of range [0, 3)"},
        BadOff{"inf_vertex.off", "OFF\n3 1 0\n0 0 0\n1 -inf 0\n0 1 0\n3 0 1 2\n",
               "line 4: non-finite coordinate"},
        BadOff{"bad_magic.off", "OFX\n3 1 0\n", "line 1: expected \"OFF\""},
        BadOff{"no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
               "header declares 0 faces"}),
    [](const testing::TestParamInfo<BadOff>& info) {
      std::string name = info.param.file;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace meshseg
