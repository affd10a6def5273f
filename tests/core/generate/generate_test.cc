// GeneratePart: parameters and errors, determinism, noise level.
#include "meshseg/generate.h"

#include <cmath>
#include <stop_token>

#include <gmock/gmock.h>
#include <tbb/global_control.h>
#include <gtest/gtest.h>

#include "meshseg/fit.h"

namespace meshseg {
namespace {

using ::testing::HasSubstr;

// Coarse voxels keep these parts around 5K triangles.
constexpr double kCoarseH = 0.8;

TEST(GeneratePart, NamesStartWithTheSmallPartAndIncludeTheTestPiece) {
  const std::vector<std::string> names = PartNames();
  ASSERT_GE(names.size(), 8u);
  EXPECT_EQ(names.front(), "small_block");
  EXPECT_THAT(names, ::testing::Contains("test_piece"));
  EXPECT_THAT(names, ::testing::Contains("test_piece_large"));
}

TEST(GeneratePart, UnknownNameIsInvalidArgument) {
  const auto part = GeneratePart("no_such_part");
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(part.status().message(), HasSubstr("no_such_part"));
  EXPECT_THAT(part.status().message(), HasSubstr("small_block"));
}

TEST(GeneratePart, NegativeOrNanVoxelSizeIsInvalidArgument) {
  for (double h : {-0.5, std::nan("")}) {
    const auto part = GeneratePart("small_block", {.voxel_size = h});
    ASSERT_FALSE(part.ok()) << h;
    EXPECT_EQ(part.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_THAT(part.status().message(), HasSubstr("voxel_size"));
  }
}

TEST(GeneratePart, AbsurdlyFineGridIsInvalidArgument) {
  const auto part = GeneratePart("test_piece", {.voxel_size = 1e-3});
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(part.status().message(), HasSubstr("limit"));
}

TEST(GeneratePart, NegativeNoiseIsInvalidArgument) {
  const auto part = GeneratePart("small_block", {.noise = -0.1});
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(part.status().message(), HasSubstr("noise"));
}

TEST(GeneratePart, StopRequestGivesCancelled) {
  std::stop_source stop;
  stop.request_stop();
  RunContext ctx;
  ctx.stop = stop.get_token();
  const auto part = GeneratePart("small_block", {}, ctx);
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.status().code(), absl::StatusCode::kCancelled);
}

TEST(GeneratePart, DefaultVoxelSizeIsReportedAndOutputSizesMatch) {
  const auto part = GeneratePart("small_block");
  ASSERT_TRUE(part.ok()) << part.status();
  EXPECT_GT(part->voxel_size, 0.0);
  EXPECT_EQ(part->noise, 0.0);
  EXPECT_EQ(part->face_primitive.size(), part->mesh.tri.n_faces());
  EXPECT_EQ(part->face_near_boundary.size(), part->mesh.tri.n_faces());
  EXPECT_EQ(part->vertex_primitive.size(), part->mesh.tri.n_vertices());
  for (size_t k = 0; k < part->primitives.size(); ++k) EXPECT_EQ(part->primitives[k].id, int(k));
  // Small part for fast tests: about 20K triangles.
  EXPECT_GT(part->mesh.tri.n_faces(), 10000u);
  EXPECT_LT(part->mesh.tri.n_faces(), 40000u);
}

// Marching cubes joins crossings on neighbouring cube edges: sides of about
// h and diagonals of about 1.4 h, near-uniformly.
TEST(GeneratePart, EdgesAreAboutOneVoxelLong) {
  const auto part = GeneratePart("test_piece", {.voxel_size = kCoarseH});
  ASSERT_TRUE(part.ok()) << part.status();
  const double l_avg = MeanEdgeLength(part->mesh.tri);
  EXPECT_GT(l_avg, 0.8 * kCoarseH);
  EXPECT_LT(l_avg, 1.2 * kCoarseH);
}

TEST(GeneratePart, SameSeedGivesSameMeshOtherSeedDiffers) {
  const GenerateParams params{.voxel_size = kCoarseH, .noise = 0.1, .seed = 7};
  const auto a = GeneratePart("plate_boss", params);
  const auto b = GeneratePart("plate_boss", params);
  auto other = params;
  other.seed = 8;
  const auto c = GeneratePart("plate_boss", other);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a->mesh.tri.n_vertices(), b->mesh.tri.n_vertices());
  ASSERT_EQ(a->mesh.tri.n_vertices(), c->mesh.tri.n_vertices());
  int same_as_b = 0, same_as_c = 0;
  for (const auto v : a->mesh.tri.vertices()) {
    same_as_b += a->mesh.tri.point(v) == b->mesh.tri.point(v);
    same_as_c += a->mesh.tri.point(v) == c->mesh.tri.point(v);
  }
  EXPECT_EQ(same_as_b, static_cast<int>(a->mesh.tri.n_vertices()));
  EXPECT_EQ(same_as_c, 0);
  EXPECT_EQ(a->face_primitive, b->face_primitive);
  EXPECT_EQ(a->face_primitive, c->face_primitive);  // labels come from the noise-free mesh
}

TEST(GeneratePart, OneThreadGivesTheSameMeshAsMany) {
  const GenerateParams params{.voxel_size = kCoarseH, .noise = 0.1};
  const auto many = GeneratePart("test_piece", params);
  absl::StatusOr<GeneratedPart> one = absl::UnknownError("not run");
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = GeneratePart("test_piece", params);
  }
  ASSERT_TRUE(many.ok() && one.ok());
  ASSERT_EQ(many->mesh.tri.n_vertices(), one->mesh.tri.n_vertices());
  ASSERT_EQ(many->mesh.tri.n_faces(), one->mesh.tri.n_faces());
  for (const auto v : many->mesh.tri.vertices()) {
    ASSERT_EQ(many->mesh.tri.point(v), one->mesh.tri.point(v)) << "vertex " << v.idx();
  }
  for (const auto f : many->mesh.tri.faces()) {
    ASSERT_EQ(many->mesh.tri.to_vertex_handle(many->mesh.tri.halfedge_handle(f)),
              one->mesh.tri.to_vertex_handle(one->mesh.tri.halfedge_handle(f)));
  }
  EXPECT_EQ(many->face_primitive, one->face_primitive);
  EXPECT_EQ(many->face_near_boundary, one->face_near_boundary);
}

// The noise is measured as the signed distance of each vertex to the
// surface of its primitive; it must have the requested sigma.
TEST(GeneratePart, NoiseAlongNormalsHasRequestedSigma) {
  constexpr double kNoise = 0.2;        // x h
  constexpr double kSigmaRelTol = 0.1;  // 10 %
  const auto part = GeneratePart("test_piece", {.voxel_size = kCoarseH, .noise = kNoise, .seed = 3});
  ASSERT_TRUE(part.ok()) << part.status();
  EXPECT_DOUBLE_EQ(part->noise, kNoise * kCoarseH);
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (const auto v : part->mesh.tri.vertices()) {
    const int p = part->vertex_primitive[v.idx()];
    ASSERT_GE(p, 0);
    const double d = SignedDistance(part->primitives[p].surface, ToEigen(part->mesh.tri.point(v)));
    sum += d, sum_sq += d * d, ++n;
  }
  ASSERT_GT(n, 1000);
  const double mean = sum / n;
  const double sigma = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_NEAR(sigma, kNoise * kCoarseH, kSigmaRelTol * kNoise * kCoarseH);
  EXPECT_NEAR(mean, 0.0, 5.0 * kNoise * kCoarseH / std::sqrt(n));
}

TEST(GeneratePart, NoiseFreeVerticesLieOnTheirPrimitive) {
  constexpr double kOnSurfaceTol = 1e-9;  // x h
  const auto part = GeneratePart("plate_boss", {.voxel_size = kCoarseH});
  ASSERT_TRUE(part.ok()) << part.status();
  double worst = 0.0;
  for (const auto v : part->mesh.tri.vertices()) {
    const int p = part->vertex_primitive[v.idx()];
    ASSERT_GE(p, 0);
    worst = std::max(worst, std::abs(SignedDistance(part->primitives[p].surface,
                                                    ToEigen(part->mesh.tri.point(v)))));
  }
  EXPECT_LT(worst, kOnSurfaceTol * kCoarseH);
}

}  // namespace
}  // namespace meshseg
