#include <ostream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/point_cloud.h"
#include "temp_file.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;
using testing_files::Message;
using testing_files::WriteTemp;

TEST(ReadXyz, ReadsCommasBlanksAndComments) {
  const absl::StatusOr<PointCloud> cloud =
      ReadPointCloud(WriteTemp("mixed.xyz", "# scanner output\n1,2,3\n\n4 5\t6  # near\r\n"));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  ASSERT_EQ(cloud->points.size(), 2u);
  EXPECT_EQ(cloud->points[1], Eigen::Vector3d(4, 5, 6));
  EXPECT_FALSE(cloud->has_normals());
}

struct BadXyz {
  const char* file;
  const char* text;
  const char* message;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the file keeps the names
// the same from build to build.
void PrintTo(const BadXyz& c, std::ostream* os) { *os << c.file; }

class ReadXyzRejects : public testing::TestWithParam<BadXyz> {};

TEST_P(ReadXyzRejects, WithFileNameAndLine) {
  const BadXyz& bad = GetParam();
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(WriteTemp(bad.file, bad.text));
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr(std::string("\"") + bad.file + "\""));
  EXPECT_THAT(Message(cloud.status()), HasSubstr(bad.message));
}

INSTANTIATE_TEST_SUITE_P(
    FaultyFiles, ReadXyzRejects,
    testing::Values(
        BadXyz{"nan_point.xyz", "0 0 0\n1 nan 1\n", "line 2: non-finite value \"nan\""},
        BadXyz{"wrong_columns.xyz", "0 0 0\n1 1 1 0 0 1\n", "line 2: 6 values, expected 3"},
        BadXyz{"four_columns.xyz", "0 0 0 1\n", "line 1: 4 values, expected 3 (x y z) or 6"},
        BadXyz{"seven_columns.xyz", "0 0 0 1 1 1 1\n", "line 1: more than 6 values"},
        BadXyz{"word.xyz", "0 0 0\nx y z\n", "line 2: expected a number, got \"x\""},
        BadXyz{"comments_only.xyz", "# nothing\n\n", "no points"}),
    [](const testing::TestParamInfo<BadXyz>& info) {
      std::string name = info.param.file;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

TEST(ReadXyz, RejectsMorePointsThanMaxElements) {
  ReadMeshOptions options;
  options.max_elements = 2;
  const absl::StatusOr<PointCloud> cloud =
      ReadPointCloud(WriteTemp("three.xyz", "0 0 0\n1 1 1\n2 2 2\n"), options);
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr("line 3: more than 2 points"));
}

}  // namespace
}  // namespace meshseg
