#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"
#include "voxel_shapes.h"

namespace meshseg {
namespace {

constexpr double kH = 0.5;

TEST(DetectBinaryLattice, FindsTheVoxelGridOfABinarySurface) {
  const VolumeData v =
      testing::SampleSdf(testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0), 36, kH, true);
  const VolumeSurface s = testing::SurfaceOf(v, "box.nrrd");
  const std::optional<BinaryLattice> lattice = DetectBinaryLattice(s.mesh.tri);
  ASSERT_TRUE(lattice.has_value());
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lattice->spacing[a], kH, 1e-9);
    const double m = (lattice->origin[a] - v.geometry.origin[a]) / kH;
    EXPECT_NEAR(m, std::round(m), 1e-6);  // a sample position
  }
}

TEST(DetectBinaryLattice, GreyIsoSurfaceIsNotBinary) {
  const VolumeSurface s =
      testing::SurfaceOf(testing::SampleSdf(testing::Ball(6.0), 32, kH, false), "ball.nrrd");
  EXPECT_FALSE(DetectBinaryLattice(s.mesh.tri).has_value());
}

TEST(BinaryMeshFeatures, RecoversTheVolumesFeatureVertices) {
  const VolumeSurface s = testing::SurfaceOf(
      testing::SampleSdf(testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0), 36, kH, true),
      "box2.nrrd");
  const std::optional<BinaryLattice> lattice = DetectBinaryLattice(s.mesh.tri);
  ASSERT_TRUE(lattice.has_value());
  const absl::StatusOr<BinaryVertices> features = BinaryMeshFeatures(s.mesh.tri, *lattice);
  ASSERT_TRUE(features.ok()) << features.status();
  EXPECT_EQ(features->feature, s.feature_vertex);
  ASSERT_EQ(features->inside.size(), s.edge_inside.size());
  for (size_t v = 0; v < s.edge_inside.size(); ++v) {
    ASSERT_LT((features->inside[v] - s.edge_inside[v]).norm(), 1e-9 * kH) << v;
    ASSERT_LT((features->outside[v] - s.edge_outside[v]).norm(), 1e-9 * kH) << v;
  }
}

TEST(RelaxTerraces, FlattensATurnedBoxFaceWithinItsEdges) {
  const auto box = testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0);
  const VolumeSurface s = testing::SurfaceOf(testing::SampleSdf(box, 36, kH, true), "box3.nrrd");
  const BinaryVertices bv{s.feature_vertex, s.edge_inside, s.edge_outside};
  const std::vector<Eigen::Vector3d> relaxed = RelaxTerraces(s.mesh.tri, bv);
  // Terraced vertices lie up to ~0.5 h off the true faces; relaxed, the
  // face interiors (more than the opening's reach from the edges) are flat,
  // and every vertex stays on its own grid edge.
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(17.0 * 3.14159265358979 / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  double before = 0.0, after = 0.0;
  int count = 0;
  for (size_t v = 0; v < relaxed.size(); ++v) {
    const Eigen::Vector3d d = s.edge_outside[v] - s.edge_inside[v];
    const double t = (relaxed[v] - s.edge_inside[v]).dot(d) / d.squaredNorm();
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
    const Eigen::Vector3d p = ToEigen(s.mesh.tri.point(TriMesh::VertexHandle(static_cast<int>(v))));
    Eigen::Vector3d q = (Eigen::Vector3d(5, 4, 3) - (r.transpose() * p).cwiseAbs()).cwiseAbs();
    std::sort(q.data(), q.data() + 3);
    if (q[1] < 3.5 * kH) continue;
    const double dp = box(p), dr = box(relaxed[v]);
    before += dp * dp, after += dr * dr, ++count;
  }
  ASSERT_GT(count, 100);
  std::cout << "rms to the faces: " << std::sqrt(before / count) << " -> "
            << std::sqrt(after / count) << "\n";
  EXPECT_LT(std::sqrt(after / count), 0.5 * std::sqrt(before / count));
}

}  // namespace
}  // namespace meshseg
