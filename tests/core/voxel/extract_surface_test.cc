#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"
#include "voxel_shapes.h"

namespace meshseg {
namespace {

using testing_files::ScratchPath;

constexpr double kH = 0.5;

TEST(ExtractSurface, GreyBallIsClosedAndOnTheSphereAtTheOtsuThreshold) {
  const VolumeData v = testing::SampleSdf(testing::Ball(6.0), 32, kH, /*binary=*/false);
  const std::string path = ScratchPath("ball.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path).ok());
  const absl::StatusOr<VolumeSurface> s = ExtractSurface(path);
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_FALSE(s->binary);
  EXPECT_NEAR(s->iso, 500.0, 50.0);  // between air 0 and material 1000
  const TriMesh& m = s->mesh.tri;
  EXPECT_EQ(static_cast<int>(m.n_vertices()) * 2 - static_cast<int>(m.n_faces()),
            4);  // closed sphere
  // The ramp is linear in the distance within 1 h of the sphere: the
  // interpolated vertices lie on the sphere where the ramp meets the iso
  // value, up to the distance's curvature along one grid edge.
  const double radius = 6.0 + (0.5 - s->iso / 1000.0) * 2.0 * kH;
  double worst = 0.0;
  for (auto vh : m.vertices())
    worst = std::max(worst, std::abs(ToEigen(m.point(vh)).norm() - radius));
  EXPECT_LT(worst, 0.02 * kH);
  for (auto f : m.faces()) {  // normals point out
    EXPECT_GT(ToEigen(m.normal(f)).dot(ToEigen(m.point(*m.cfv_iter(f)))), 0.0);
  }
}

TEST(ExtractSurface, BinaryBoxMarksFeatureVerticesOnItsEdgesOnly) {
  const auto box = testing::TurnedBox(Eigen::Vector3d(5.0, 4.0, 3.0), 17.0);
  const VolumeData v = testing::SampleSdf(box, 36, kH, /*binary=*/true);
  const std::string path = ScratchPath("box.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path, /*gzip=*/true).ok());
  const absl::StatusOr<VolumeSurface> s = ExtractSurface(path);
  ASSERT_TRUE(s.ok()) << s.status();
  ASSERT_TRUE(s->binary);
  EXPECT_DOUBLE_EQ(s->iso, 0.5);
  ASSERT_EQ(s->feature_vertex.size(), s->mesh.tri.n_vertices());
  // Feature vertices lie near the box's edges: within the reach of the
  // opening's ball (3 voxels) plus half a voxel of marching-cubes offset;
  // the faces' interiors stay free of them, so QEM can flatten the terraces.
  int features = 0, far_from_edges = 0;
  for (auto vh : s->mesh.tri.vertices()) {
    if (!s->feature_vertex[vh.idx()]) continue;
    ++features;
    // Distance to the nearest edge ~ second-largest face distance.
    const Eigen::Vector3d p = ToEigen(s->mesh.tri.point(vh));
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(17.0 * 3.14159265358979 / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
            .toRotationMatrix();
    Eigen::Vector3d q =
        (Eigen::Vector3d(5.0, 4.0, 3.0) - (r.transpose() * p).cwiseAbs()).cwiseAbs();
    std::sort(q.data(), q.data() + 3);
    if (q[1] > 3.5 * kH) ++far_from_edges;
  }
  EXPECT_GT(features, 50);
  EXPECT_LE(far_from_edges, features / 50) << far_from_edges << " of " << features;
}

TEST(ExtractSurface, ConstantVolumeHasNoSurface) {
  VolumeData v = testing::SampleSdf(testing::Ball(100.0), 8, kH, true);
  const std::string path = ScratchPath("solid.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path).ok());
  const absl::StatusOr<VolumeSurface> s = ExtractSurface(path);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.status().message(), ::testing::HasSubstr("solid.nrrd"));
}

TEST(ExtractSurface, IsoOutsideTheSamplesIsRefused) {
  const VolumeData v = testing::SampleSdf(testing::Ball(3.0), 16, kH, false);
  const std::string path = ScratchPath("ball_iso.nrrd");
  ASSERT_TRUE(WriteNrrd(v, path).ok());
  const absl::StatusOr<VolumeSurface> s =
      ExtractSurface(path, {.read = {}, .mode = VolumeMode::kAuto, .iso = 5000.0});
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.status().message(), ::testing::HasSubstr("outside the samples' range"));
}

TEST(OtsuThreshold, SplitsTwoPeaks) {
  std::vector<int64_t> h(100, 0);
  for (int b = 10; b < 20; ++b) h[b] = 100;
  for (int b = 70; b < 80; ++b) h[b] = 50;
  const double t = OtsuThreshold(h, 0.0, 100.0);
  EXPECT_GT(t, 19.0);  // between the classes' values 19 and 70
  EXPECT_LT(t, 70.0);
}

}  // namespace
}  // namespace meshseg
