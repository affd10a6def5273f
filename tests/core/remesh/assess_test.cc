#include <gtest/gtest.h>

#include "cad_shapes.h"
#include "meshseg/generate.h"
#include "meshseg/remesh.h"

namespace meshseg {
namespace {

using testing::MeshOf;

TEST(Assess, CadCylinderOfLongStripsIsCadLike) {
  // 48 strips 40 long and 1.3 wide: nearly all the area is in thin triangles.
  const Mesh mesh = MeshOf(testing::CadCylinder(10.0, 40.0, 48));
  const TessellationShape shape = Assess(mesh);
  EXPECT_GT(shape.thin_area_fraction, 0.9);
  EXPECT_TRUE(shape.cad_like);
  // Median shortest edge: the chord 2 r sin(pi / 48).
  EXPECT_NEAR(shape.median_shortest_edge, 20.0 * std::sin(std::numbers::pi / 48), 1e-9);
  EXPECT_NEAR(shape.surface_area, 48 * 40.0 * 20.0 * std::sin(std::numbers::pi / 48) +
                                      2 * 48 * 50.0 * std::sin(2 * std::numbers::pi / 48),
              1e-6);
}

TEST(Assess, MarchingCubesPartIsScanLike) {
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  const TessellationShape shape = Assess(part->mesh);
  EXPECT_LT(shape.thin_area_fraction, 0.02);
  EXPECT_FALSE(shape.cad_like);
}

TEST(Assess, TargetLengthKeepsTheRemeshUnderMaxFaces) {
  const Mesh mesh = MeshOf(testing::CadCylinder(10.0, 40.0, 48));
  const TessellationShape fine = Assess(mesh, {.max_faces = 100'000'000});
  EXPECT_DOUBLE_EQ(fine.target_edge_length, fine.median_shortest_edge);
  const TessellationShape capped = Assess(mesh, {.max_faces = 1000});
  // sqrt(3)/4 L^2 per equilateral triangle: 1000 of them cover the area.
  EXPECT_NEAR(std::sqrt(3.0) / 4.0 * capped.target_edge_length * capped.target_edge_length * 1000,
              capped.surface_area, 1e-6 * capped.surface_area);
}

TEST(Assess, TooFineToRemeshWhenTheCapCoarsensTheRemesh) {
  // Median shortest edge 1.31 (the strips' width); at 1000 faces the remesh
  // needs edges of 5.6, over kMaxRemeshCoarsening times that.
  const Mesh mesh = MeshOf(testing::CadCylinder(10.0, 40.0, 48));
  EXPECT_FALSE(Assess(mesh, {.max_faces = 100'000'000}).too_fine_to_remesh);
  const TessellationShape capped = Assess(mesh, {.max_faces = 1000});
  ASSERT_GT(capped.target_edge_length, kMaxRemeshCoarsening * capped.median_shortest_edge);
  EXPECT_TRUE(capped.too_fine_to_remesh);
  // A scan-like mesh is never "too fine": it is not remeshed at all.
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece", {.voxel_size = 1.0});
  ASSERT_TRUE(part.ok()) << part.status();
  EXPECT_FALSE(Assess(part->mesh, {.max_faces = 1000}).too_fine_to_remesh);
}

}  // namespace
}  // namespace meshseg
