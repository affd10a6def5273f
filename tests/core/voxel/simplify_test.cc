#include <algorithm>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"
#include "voxel_shapes.h"

namespace meshseg {
namespace {

constexpr double kH = 0.5;

TEST(Simplify, BinaryBoxKeepsEveryFeatureVertexWithinHalfAVoxel) {
  const VolumeSurface s = testing::SurfaceOf(
      testing::SampleSdf(testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0), 36, kH, true),
      "box.nrrd");
  const int64_t target = static_cast<int64_t>(s.mesh.tri.n_faces()) / 10;
  const absl::StatusOr<Simplification> out =
      Simplify(s.mesh.tri, {.target_faces = target, .max_error = 0.5 * kH}, s.feature_vertex);
  ASSERT_TRUE(out.ok()) << out.status();
  // The feature bands along the 12 edges stay whole: on this small box they
  // hold a third of the faces.
  EXPECT_LE(out->mesh.tri.n_faces(), s.mesh.tri.n_faces() / 2);
  // Seed 003 section 2.2: feature points are never removed.
  const std::set<int> kept(out->input_vertex.begin(), out->input_vertex.end());
  for (size_t v = 0; v < s.feature_vertex.size(); ++v) {
    if (s.feature_vertex[v]) {
      EXPECT_TRUE(kept.count(static_cast<int>(v))) << "feature vertex " << v;
    }
  }
  EXPECT_LE(out->hausdorff.Max(), 0.75 * kH);
}

TEST(Simplify, LabelledFacesKeepTheirLabelAndTheBoundaryStays) {
  const VolumeSurface s =
      testing::SurfaceOf(testing::SampleSdf(testing::Ball(6.0), 32, kH, false), "ball.nrrd");
  std::vector<int> labels;
  for (auto f : s.mesh.tri.faces())
    labels.push_back(s.mesh.tri.calc_face_centroid(f)[2] > 0.7 ? 1 : 0);
  const absl::StatusOr<Simplification> out =
      Simplify(s.mesh.tri, {.target_faces = static_cast<int64_t>(labels.size()) / 8}, {}, labels);
  ASSERT_TRUE(out.ok()) << out.status();
  ASSERT_EQ(out->face_labels.size(), out->mesh.tri.n_faces());
  // The boundary circle z = 0.7 is kept: each face lies on its side of it.
  int wrong = 0;
  for (auto f : out->mesh.tri.faces()) {
    const double z = out->mesh.tri.calc_face_centroid(f)[2];
    wrong += (z > 0.7) != (out->face_labels[f.idx()] == 1);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_LE(out->hausdorff.Max(), 0.3 * kH);
}

TEST(Simplify, MaxErrorAloneStopsTheCollapses) {
  const VolumeSurface s =
      testing::SurfaceOf(testing::SampleSdf(testing::Ball(6.0), 32, kH, false), "ball2.nrrd");
  const absl::StatusOr<Simplification> out = Simplify(s.mesh.tri, {.max_error = 0.02 * kH});
  ASSERT_TRUE(out.ok()) << out.status();
  EXPECT_LT(out->mesh.tri.n_faces(), s.mesh.tri.n_faces());
  EXPECT_LE(out->hausdorff.Max(), 0.1 * kH);
}

TEST(Simplify, BadArgumentsAreRefused) {
  const VolumeSurface s =
      testing::SurfaceOf(testing::SampleSdf(testing::Ball(3.0), 16, kH, false), "ball3.nrrd");
  EXPECT_EQ(Simplify(s.mesh.tri, {}).status().code(), absl::StatusCode::kInvalidArgument);
  const std::vector<uint8_t> short_flags(3, 0);
  const absl::Status bad = Simplify(s.mesh.tri, {.target_faces = 10}, short_flags).status();
  EXPECT_THAT(bad.message(), ::testing::HasSubstr("3 feature flags"));
}

TEST(Hausdorff, IsZeroToItselfAndSeesAMovedVertex) {
  const VolumeSurface s =
      testing::SurfaceOf(testing::SampleSdf(testing::Ball(3.0), 16, kH, false), "ball4.nrrd");
  EXPECT_NEAR(Hausdorff(s.mesh.tri, s.mesh.tri).Max(), 0.0, 1e-12);
  TriMesh moved = s.mesh.tri;
  auto v = *moved.vertices().begin();
  moved.set_point(v, moved.point(v) + moved.normal(v) * 0.3);
  EXPECT_NEAR(Hausdorff(s.mesh.tri, moved).output_to_input, 0.3, 0.05);
}

}  // namespace
}  // namespace meshseg
