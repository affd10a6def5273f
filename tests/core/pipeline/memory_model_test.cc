// The admission memory model: its terms, and RunPipeline refusing from the
// header, before reading, a job whose estimate exceeds the budget, with
// this process's peak RSS growing by far less than the file.
#include "pipeline/memory_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <limits>
#include <string>

#include "absl/strings/str_cat.h"
#include "meshseg/pipeline.h"
#include "meshseg/voxel.h"
#include "scratch_dir.h"

namespace meshseg::pipeline_internal {
namespace {

using ::testing::HasSubstr;

TEST(PeakBytes, GrowsByTheMeasuredCostPerFaceAndPoint) {
  PipelineParams no_remesh;
  no_remesh.remesh.mode = RemeshMode::kNever;
  const InputSize small{.format = FileFormat::kPly, .vertex_count = 500, .face_count = 1000};
  InputSize large = small;
  large.face_count += 1'000'000;
  EXPECT_EQ(PeakBytes(large, no_remesh) - PeakBytes(small, no_remesh),
            static_cast<int64_t>(kSafetyMargin * kBytesPerMeshFace * 1'000'000));
  // The remesh, when it may run, is paid for at its face budget.
  EXPECT_EQ(PeakBytes(small, {}) - PeakBytes(small, no_remesh),
            static_cast<int64_t>(kSafetyMargin * kBytesPerRemeshFace * RemeshParams{}.max_faces));
  const InputSize cloud{.format = FileFormat::kXyz, .point_cloud = true, .vertex_count = 100'000};
  EXPECT_EQ(PeakBytes(cloud, {}),
            static_cast<int64_t>(kSafetyMargin * (kBaseBytes + kBytesPerPoint * 100'000)));
}

TEST(PeakBytes, PaysForTheReturnedMeshOnlyWhenAskedFor) {
  const InputSize mesh{.format = FileFormat::kPly, .vertex_count = 500, .face_count = 10'000};
  PipelineParams with_mesh;
  with_mesh.include_mesh = true;
  EXPECT_EQ(PeakBytes(mesh, with_mesh) - PeakBytes(mesh, {}),
            static_cast<int64_t>(kSafetyMargin * kBytesPerReturnedFace * 10'000));
  const InputSize cloud{.format = FileFormat::kXyz, .point_cloud = true, .vertex_count = 7'000};
  EXPECT_EQ(PeakBytes(cloud, with_mesh) - PeakBytes(cloud, {}),
            static_cast<int64_t>(kSafetyMargin * kBytesPerReturnedFace * 7'000));
}

TEST(PeakBytes, PaysForDeclaredVerticesAndNeverOverflows) {
  const InputSize vertices{.format = FileFormat::kOff, .vertex_count = 1'000'000, .face_count = 1};
  EXPECT_EQ(CostedFaces(vertices), 2'000'000);
  const InputSize stl{.format = FileFormat::kStl, .vertex_count = 3'000, .face_count = 1'000};
  EXPECT_EQ(CostedFaces(stl), 1'000);
  const InputSize lie{.format = FileFormat::kPly,
                      .vertex_count = std::numeric_limits<int64_t>::max() / 2,
                      .face_count = std::numeric_limits<int64_t>::max()};
  EXPECT_EQ(PeakBytes(lie, {}), std::numeric_limits<int64_t>::max());
}

long PeakRssKib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A 1.9 GB binary PLY (sparse: its body is a hole) under a 1 GiB budget is
// refused from its header; reading it would map the whole file and build
// tens of millions of faces.
TEST(RunPipeline, RefusesAJobOverTheBudgetBeforeReadingIt) {
  constexpr int64_t kVertices = 70'000'000;
  constexpr int64_t kFaces = 80'000'000;
  const std::string path = testing_files::ScratchPath("huge.ply");
  std::ofstream(path) << "ply\nformat binary_little_endian 1.0\nelement vertex " << kVertices
                      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
                      << kFaces << "\nproperty list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(truncate(path.c_str(), kVertices * 12 + kFaces * 13 + 200), 0);
  PipelineParams params;
  params.memory_budget_bytes = int64_t{1} << 30;
  const absl::StatusOr<MemoryEstimate> estimate = EstimateJobMemory(path, params);
  ASSERT_TRUE(estimate.ok()) << estimate.status();
  EXPECT_GT(estimate->peak_bytes, kFaces * kBytesPerMeshFace);

  const long before = PeakRssKib();
  const absl::StatusOr<PipelineResult> r = RunPipeline(path, params);
  EXPECT_EQ(r.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(std::string(r.status().message()),
              HasSubstr(absl::StrCat("\"huge.ply\": ", kFaces, " faces, ", kVertices,
                                     " vertices declared need an estimated ", estimate->peak_bytes,
                                     " bytes, over the memory budget of ", int64_t{1} << 30)));
  constexpr long kMaxGrowthKib = 32 << 10;
  EXPECT_LT(PeakRssKib() - before, kMaxGrowthKib) << "refused without reading the body";
}

TEST(RunPipeline, AJobWithinTheBudgetRuns) {
  const std::string path = testing_files::ScratchPath("tetra.off");
  std::ofstream(path) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                         "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  PipelineParams params;
  params.memory_budget_bytes = int64_t{1} << 30;
  const absl::StatusOr<PipelineResult> r = RunPipeline(path, params);
  EXPECT_TRUE(r.ok()) << r.status();
  params.memory_budget_bytes = -1;
  EXPECT_EQ(RunPipeline(path, params).status().code(), absl::StatusCode::kInvalidArgument);
}

// A volume is costed from its header: the surface its grid's box can hold,
// two slices, and seed 003's bytes per voxel when it may be binary (8-bit
// samples in auto mode, or binary mode), not when read as grey.
TEST(EstimateJobMemory, CostsAVolumeFromItsHeader) {
  VolumeData v;
  v.type = VoxelType::kUint8;
  v.geometry.dims = {40, 30, 20};
  v.values.assign(40 * 30 * 20, 0.0);
  v.values[0] = 1.0;
  const std::string path = testing_files::ScratchPath("costed.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path).ok());
  const absl::StatusOr<MemoryEstimate> maybe_binary = EstimateJobMemory(path);
  ASSERT_TRUE(maybe_binary.ok()) << maybe_binary.status();
  EXPECT_EQ(maybe_binary->input.format, FileFormat::kNrrd);
  EXPECT_EQ(maybe_binary->input.face_count,
            kVolumeFacesPerBoxFace * (40 * 30 + 30 * 20 + 40 * 20));
  PipelineParams grey;
  grey.volume.mode = VolumeMode::kGrey;
  const absl::StatusOr<MemoryEstimate> as_grey = EstimateJobMemory(path, grey);
  ASSERT_TRUE(as_grey.ok()) << as_grey.status();
  EXPECT_NEAR(static_cast<double>(maybe_binary->peak_bytes - as_grey->peak_bytes),
              kSafetyMargin * kBinaryBytesPerVoxel * 40 * 30 * 20, 2.0);
  // A header that names a missing data file is an error, not a guess.
  std::ofstream(testing_files::ScratchPath("detached.nhdr"))
      << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n"
         "data file: missing.raw\n\n";
  PipelineParams nrrd;
  nrrd.format = FileFormat::kNrrd;
  EXPECT_FALSE(EstimateJobMemory(testing_files::ScratchPath("detached.nhdr"), nrrd).ok());
}

}  // namespace
}  // namespace meshseg::pipeline_internal
