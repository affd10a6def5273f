#include <cmath>

#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"
#include "voxel_shapes.h"

namespace meshseg {
namespace {

constexpr double kH = 0.5;

VolumeSurface Surface(const VolumeData& v, const std::string& name) {
  const std::string path = testing_files::ScratchPath(name);
  EXPECT_TRUE(WriteNrrd(v, path).ok());
  absl::StatusOr<VolumeSurface> s = ExtractSurface(path);
  EXPECT_TRUE(s.ok()) << s.status();
  return *std::move(s);
}

TEST(DetectBinaryLattice, FindsTheVoxelGridOfABinarySurface) {
  const VolumeData v =
      testing::SampleSdf(testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0), 36, kH, true);
  const VolumeSurface s = Surface(v, "box.nrrd");
  const std::optional<BinaryLattice> lattice = DetectBinaryLattice(s.mesh.tri);
  ASSERT_TRUE(lattice.has_value());
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lattice->spacing[a], kH, 1e-9);
    const double m = (lattice->origin[a] - v.geometry.origin[a]) / kH;
    EXPECT_NEAR(m, std::round(m), 1e-6);  // a sample position
  }
}

TEST(DetectBinaryLattice, GreyIsoSurfaceIsNotBinary) {
  const VolumeSurface s = Surface(testing::SampleSdf(testing::Ball(6.0), 32, kH, false), "ball.nrrd");
  EXPECT_FALSE(DetectBinaryLattice(s.mesh.tri).has_value());
}

TEST(BinaryMeshFeatures, RecoversTheVolumesFeatureVertices) {
  const VolumeSurface s = Surface(
      testing::SampleSdf(testing::TurnedBox(Eigen::Vector3d(5, 4, 3), 17.0), 36, kH, true), "box2.nrrd");
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
  const VolumeSurface s = Surface(testing::SampleSdf(box, 36, kH, true), "box3.nrrd");
  const BinaryVertices bv{s.feature_vertex, s.edge_inside, s.edge_outside};
  const std::vector<Eigen::Vector3d> relaxed = RelaxTerraces(s.mesh.tri, bv);
  // Terraced vertices lie up to ~0.5 h off the true faces (rms ~0.2 h);
  // relaxed, the face interiors (away from the edges) are flat.
  double before = 0.0, after = 0.0;
  int count = 0;
  for (size_t v = 0; v < relaxed.size(); ++v) {
    const Eigen::Vector3d p = ToEigen(s.mesh.tri.point(TriMesh::VertexHandle(static_cast<int>(v))));
    if (box(p) < -1.5 * kH || std::abs(box(p)) > kH) continue;
    const double dp = std::abs(box(p)), dr = std::abs(box(relaxed[v]));
    // Only vertices whose nearest face is far from the edges (interiors).
    before += dp * dp, after += dr * dr, ++count;
    const Eigen::Vector3d d = s.edge_outside[v] - s.edge_inside[v];
    const double t = (relaxed[v] - s.edge_inside[v]).dot(d) / d.squaredNorm();
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
  }
  ASSERT_GT(count, 100);
  EXPECT_LT(std::sqrt(after / count), 0.6 * std::sqrt(before / count));
}

}  // namespace
}  // namespace meshseg
