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

TEST(ReadPwn, ReadsPointsThenNormals) {
  const absl::StatusOr<PointCloud> cloud =
      ReadPointCloud(WriteTemp("two.pwn", "2\n0 0 0\n1 2 3\n0 0 5\n0 -2 0\n"));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  ASSERT_EQ(cloud->points.size(), 2u);
  EXPECT_EQ(cloud->points[1], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(cloud->normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(cloud->normals[1], Eigen::Vector3d(0, -1, 0));
}

struct BadPwn {
  const char* file;
  const char* text;
  const char* message;
};

// GoogleTest prints a parameter without PrintTo as its bytes, pointers included,
// and ctest's test names carry that text: printing the file keeps the names
// the same from build to build.
void PrintTo(const BadPwn& c, std::ostream* os) { *os << c.file; }

class ReadPwnRejects : public testing::TestWithParam<BadPwn> {};

TEST_P(ReadPwnRejects, WithFileNameAndPlace) {
  const BadPwn& bad = GetParam();
  const absl::StatusOr<PointCloud> cloud = ReadPointCloud(WriteTemp(bad.file, bad.text));
  ASSERT_EQ(cloud.status().code(), absl::StatusCode::kInvalidArgument) << cloud.status();
  EXPECT_THAT(Message(cloud.status()), HasSubstr(std::string("\"") + bad.file + "\""));
  EXPECT_THAT(Message(cloud.status()), HasSubstr(bad.message));
}

INSTANTIATE_TEST_SUITE_P(
    FaultyFiles, ReadPwnRejects,
    testing::Values(
        BadPwn{"huge_count.pwn", "90000000\n0 0 0\n0 0 1\n",
               "header declares 90000000 points (at least 12 bytes each)"},
        BadPwn{"missing_normals.pwn", "2\n0 0 0\n1 1 1\n0 0 1\n# padding padding\n",
               "count declares 2 normals, file holds 1"},
        BadPwn{"extra_data.pwn", "1\n0 0 0\n0 0 1\n5 5 5\n", "line 4: data after the 1"},
        BadPwn{"inf_point.pwn", "1\n0 inf 0\n0 0 1\n", "line 2: non-finite number \"inf\""},
        BadPwn{"bad_count.pwn", "two\n0 0 0\n0 0 1\n", "line 1: expected the point count"}),
    [](const testing::TestParamInfo<BadPwn>& info) {
      std::string name = info.param.file;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace meshseg
