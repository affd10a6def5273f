// Results are finite or the job fails: coordinates whose fourth powers
// overflow are refused before any work (INVALID_ARGUMENT naming the vertex
// and value), and a non-finite number anywhere in a result is named.
#include "pipeline/finite_result.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/pipeline.h"
#include "scratch_dir.h"

namespace meshseg::pipeline_internal {
namespace {

using ::testing::HasSubstr;

std::string Message(const absl::Status& s) { return std::string(s.message()); }

// A closed box of 12 triangles as OFF, its corners scaled by `scale`.
std::string WriteBox(const std::string& name, double scale) {
  const std::string path = testing_files::ScratchPath(name);
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) {
    out << scale * (i & 1) << " " << scale * ((i >> 1) & 1) << " " << scale * ((i >> 2) & 1)
        << "\n";
  }
  out << "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n"
         "3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n";
  return path;
}

TEST(CheckCoordinateRange, RefusesCloudCoordinatesWhoseFourthPowersOverflow) {
  const std::vector<Eigen::Vector3d> ok = {{0, 0, 0}, {-1e75, 1e75, 3}};
  EXPECT_TRUE(CheckCoordinateRange("a.xyz", ok).ok());
  const std::vector<Eigen::Vector3d> big = {{0, 0, 0}, {1, 2, -1e76}};
  const absl::Status s = CheckCoordinateRange("a.xyz", big);
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(s),
              HasSubstr("\"a.xyz\": point 1 has coordinate 1e+76, beyond the +-1e+75"));
}

// The mesh scaled by 1e300 used to end SUCCEEDED with NaN parameters; the
// reader now refuses it, before its areas overflow to "12 degenerate".
TEST(RunPipeline, AMeshScaledBy1e300FailsWithAReason) {
  const absl::StatusOr<PipelineResult> r = RunPipeline(WriteBox("huge_box.off", 1e300));
  EXPECT_EQ(r.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(r.status()), HasSubstr("\"huge_box.off\": vertex 1 has coordinate 1e+300"));
  EXPECT_TRUE(RunPipeline(WriteBox("box.off", 1e60)).ok()) << "large but in range";
}

TEST(CheckResultFinite, NamesTheFirstNonFiniteNumberAndWhereItIs) {
  PipelineResult result;
  Region plane;
  plane.id = 0;
  plane.type = SurfaceType::kPlane;
  plane.surface = Plane{};
  Region cylinder;
  cylinder.id = 1;
  cylinder.type = SurfaceType::kCylinder;
  Cylinder c;
  c.radius = std::numeric_limits<double>::quiet_NaN();
  cylinder.surface = c;
  result.regions = {plane, cylinder};
  const absl::Status s = CheckResultFinite("part.stl", result);
  EXPECT_EQ(s.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(Message(s),
              HasSubstr("\"part.stl\": non-finite result, region 1 (cylinder) radius is nan"));

  result.regions[1].surface = Cylinder{};
  EXPECT_TRUE(CheckResultFinite("part.stl", result).ok());
  result.estimates.noise_sigma = std::numeric_limits<double>::infinity();
  EXPECT_THAT(Message(CheckResultFinite("part.stl", result)),
              HasSubstr("estimates noise_sigma is inf"));
  result.estimates.noise_sigma = 0;
  result.topology.corners.resize(1);
  result.topology.corners[0].position.y() = -std::numeric_limits<double>::infinity();
  EXPECT_THAT(Message(CheckResultFinite("part.stl", result)),
              HasSubstr("corner 0 position.y is -inf"));
}

}  // namespace
}  // namespace meshseg::pipeline_internal
