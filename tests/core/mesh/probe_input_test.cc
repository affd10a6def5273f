// ProbeInput: declared counts of every format without reading the body, a
// sparse multi-GB file probed in a few MiB, and the errors it names.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/input_size.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;
using testing_files::WriteTemp;

TEST(ProbeInput, CountsEveryFormat) {
  struct Case {
    std::string name;
    std::string content;
    int64_t vertices;
    int64_t faces;
    bool cloud;
  };
  std::string binary_stl(84 + 2 * 50, '\0');
  binary_stl[80] = 2;
  const Case cases[] = {
      {"a.off", "OFF\n# c\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", 4, 2, false},
      {"b.off", "OFF 4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n", 4, 1, false},
      {"c.obj", "# x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1 2 4 3\nf 1 2 3\n", 4, 3,
       false},
      {"d.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
       "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n",
       3, 1, false},
      {"e.stl", binary_stl, 6, 2, false},
      {"f.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
       "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
       "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       3, 1, false},
      {"g.ply",
       "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n0 0 0\n1 0 0\n",
       2, 0, true},
      {"h.xyz", "# scan\n0 0 0\n\n1 0 0\n2 0 0", 3, 0, true},
      {"i.pwn", "2\n0 0 0\n1 0 0\n0 0 1\n0 0 1\n", 2, 0, true},
  };
  for (const Case& c : cases) {
    const absl::StatusOr<InputSize> size = ProbeInput(WriteTemp(c.name, c.content));
    ASSERT_TRUE(size.ok()) << c.name << ": " << size.status();
    EXPECT_EQ(size->vertex_count, c.vertices) << c.name;
    EXPECT_EQ(size->face_count, c.faces) << c.name;
    EXPECT_EQ(size->point_cloud, c.cloud) << c.name;
    EXPECT_EQ(size->file_bytes, static_cast<int64_t>(c.content.size())) << c.name;
  }
}

// A 2 GB binary PLY (sparse: its body is a hole) is probed from its header
// while this process's peak RSS grows by a few MiB, not by the file.
TEST(ProbeInput, ReadsAHugeFilesHeaderWithoutReadingItsBody) {
  constexpr int64_t kFaces = 80'000'000;
  constexpr int64_t kVertices = 40'000'000;
  const std::string header =
      absl::StrCat("ply\nformat binary_little_endian 1.0\nelement vertex ", kVertices,
                   "\nproperty float x\nproperty float y\nproperty float z\nelement face ", kFaces,
                   "\nproperty list uchar int vertex_indices\nend_header\n");
  const std::string path = WriteTemp("huge.ply", header);
  const int64_t bytes = static_cast<int64_t>(header.size()) + kVertices * 12 + kFaces * 13;
  ASSERT_EQ(truncate(path.c_str(), bytes), 0);
  rusage before{};
  getrusage(RUSAGE_SELF, &before);
  const absl::StatusOr<InputSize> size = ProbeInput(path);
  rusage after{};
  getrusage(RUSAGE_SELF, &after);
  ASSERT_TRUE(size.ok()) << size.status();
  EXPECT_EQ(size->face_count, kFaces);
  EXPECT_EQ(size->vertex_count, kVertices);
  EXPECT_EQ(size->file_bytes, bytes);
  constexpr long kMaxGrowthKib = 16 << 10;
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, kMaxGrowthKib);
}

TEST(ProbeInput, NamesTheFileAndTheProblem) {
  EXPECT_EQ(ProbeInput("/nonexistent/x.stl").status().code(), absl::StatusCode::kNotFound);
  const absl::Status empty = ProbeInput(WriteTemp("empty.off", "")).status();
  EXPECT_THAT(Message(empty), HasSubstr("\"empty.off\": empty file"));
  const absl::Status counts = ProbeInput(WriteTemp("nocount.off", "OFF\n")).status();
  EXPECT_THAT(Message(counts), HasSubstr("no vertex and face counts"));
  const absl::Status negative = ProbeInput(WriteTemp("neg.off", "OFF\n-3 1 0\n")).status();
  EXPECT_THAT(Message(negative), HasSubstr("negative count"));
  const absl::Status volume = ProbeInput(WriteTemp("ct.nrrd", "NRRD0004\ntype: uint8\n")).status();
  EXPECT_EQ(volume.code(), absl::StatusCode::kInvalidArgument) << volume;
  EXPECT_THAT(volume.message(), HasSubstr("nrrd volume has no mesh element counts")) << volume;
  const absl::Status unknown = ProbeInput(WriteTemp("x.bin", "\x01\x02garbage")).status();
  EXPECT_THAT(Message(unknown), HasSubstr("unknown format"));
}

}  // namespace
}  // namespace meshseg
