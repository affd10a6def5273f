// RunPipeline on CAD tessellations: long thin triangles with their vertices
// exactly on the surface are segmented facet by facet as read
// (meshseg/segment.h: SegmentExactFacets); on the scan path
// (ExactMode::kNever, and for CAD-like meshes that are not exact) they are
// segmented on an isotropic remesh, labels come back per input face, and
// the surfaces are refitted on the input vertices.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>
#include <variant>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "cad_shapes.h"
#include "meshseg/pipeline.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

// RunPipeline on `shape` written to a temporary file `name`.
absl::StatusOr<PipelineResult> RunOnShape(const testing::CadShape& shape, const std::string& name,
                                          const PipelineParams& params = {}) {
  const Mesh mesh = testing::MeshOf(shape, name);
  const std::string path = testing_files::ScratchPath(name);
  EXPECT_TRUE(WriteMesh(mesh.tri, path).ok());
  absl::StatusOr<PipelineResult> result = RunPipeline(path, params);
  std::filesystem::remove(path);
  return result;
}

// The region holding most of the faces on `surface`, and its share of them.
std::pair<int, double> MainRegion(const testing::CadShape& shape, const PipelineResult& result,
                                  int surface) {
  std::map<int, int> count;
  int total = 0;
  for (std::size_t f = 0; f < shape.triangles.size(); ++f) {
    if (shape.surface[f] != surface) continue;
    ++total;
    ++count[result.face_labels[f]];
  }
  std::pair<int, int> best{-1, 0};
  for (const auto& [region, n] : count) {
    if (n > best.second) best = {region, n};
  }
  return {best.first, static_cast<double>(best.second) / std::max(total, 1)};
}

// An exact CAD cylinder of long strips: facet by facet, no remesh, the
// cylinder and its caps exact, each its own surface.
TEST(CadInput, ExactCylinderOfLongStripsIsSegmentedFacetByFacet) {
  const testing::CadShape shape = testing::CadCylinder(10.0, 40.0, 48);
  const absl::StatusOr<PipelineResult> result = RunOnShape(shape, "cad_cylinder_exact_test.ply");
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->estimates.path, SegmentationPath::kExactFacets);
  EXPECT_EQ(result->remesh_face_count, 0);
  EXPECT_GE(result->estimates.exact_share, kMinExactShare);
  ASSERT_EQ(result->regions.size(), 3u);
  ASSERT_EQ(result->surfaces.size(), 3u);
  for (std::size_t f = 0; f < shape.triangles.size(); ++f) {
    const Region& r = result->regions[result->face_labels[f]];
    ASSERT_EQ(r.type, shape.surface[f] == 0 ? SurfaceType::kCylinder : SurfaceType::kPlane);
    if (r.type == SurfaceType::kCylinder) {
      EXPECT_NEAR(std::get<Cylinder>(r.surface).radius, 10.0, 1e-9);
    }
    EXPECT_EQ(result->surfaces[r.surface_id].regions, std::vector<int>{r.id});
  }
}

// The same on the scan path: segmented on an isotropic remesh.
TEST(CadInput, CylinderOfLongStripsComesBackAsOneExactCylinderAndTwoPlanes) {
  const testing::CadShape shape = testing::CadCylinder(10.0, 40.0, 48);
  PipelineParams scan;
  scan.segment.exact = ExactMode::kNever;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_cylinder_input_test.ply", scan);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->remesh_face_count, 10 * static_cast<int64_t>(shape.triangles.size()));
  EXPECT_EQ(result->estimates.path, SegmentationPath::kRemeshed);
  EXPECT_GT(result->remesh_edge_length, 0.0);
  ASSERT_EQ(result->face_labels.size(), shape.triangles.size());
  EXPECT_LE(result->regions.size(), 4u);
  for (int surface = 0; surface < 3; ++surface) {
    const auto [region, share] = MainRegion(shape, *result, surface);
    SCOPED_TRACE(::testing::Message() << "surface " << surface << " region " << region);
    ASSERT_GE(region, 0);
    EXPECT_GE(share, 0.95);
    const Region& reg = result->regions[region];
    if (surface == 0) {
      ASSERT_EQ(reg.type, SurfaceType::kCylinder);
      const Cylinder& c = std::get<Cylinder>(reg.surface);
      // Refitted on the input's vertices, which lie on the cylinder itself:
      // exact, where the remesh's vertices (on the chords) give r < 10.
      EXPECT_NEAR(c.radius, 10.0, 1e-6);
      EXPECT_NEAR(std::abs(c.axis_direction.z()), 1.0, 1e-9);
      EXPECT_LT(reg.rms_distance, 1e-6);
    } else {
      ASSERT_EQ(reg.type, SurfaceType::kPlane);
      const Plane& p = std::get<Plane>(reg.surface);
      EXPECT_NEAR(std::abs(p.normal.z()), 1.0, 1e-9);
      EXPECT_NEAR(p.point.z(), surface == 1 ? 0.0 : 40.0, 1e-9);
    }
  }
  // Face and vertex counts are those of the input, not of the remesh.
  int64_t faces = 0;
  for (const Region& r : result->regions) faces += r.face_count;
  EXPECT_EQ(faces, static_cast<int64_t>(shape.triangles.size()));
  EXPECT_EQ(result->vertex_labels.size(), shape.vertices.size());
  // Curves are on the input mesh: vertex ids below its vertex count.
  EXPECT_FALSE(result->topology.curves.empty());
  for (const auto& curve : result->topology.curves) {
    for (const int v : curve.vertices) ASSERT_LT(v, static_cast<int>(shape.vertices.size()));
  }
}

TEST(CadInput, NeverModeSegmentsTheInputAsRead) {
  const testing::CadShape shape = testing::CadCylinder(10.0, 40.0, 48);
  PipelineParams params;
  params.remesh.mode = RemeshMode::kNever;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_cylinder_never_test.ply", params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->remesh_face_count, 0);
  EXPECT_EQ(result->remesh_edge_length, 0.0);
}

// With a face budget of 1000 the remesh would need edges of 5.6 for strips
// 1.3 wide (remesh.h: too_fine_to_remesh): the input itself is segmented,
// facet by facet, into the exact cylinder and its caps.
TEST(CadInput, TooFineToRemeshIsSegmentedFacetByFacet) {
  const testing::CadShape shape = testing::CadCylinder(10.0, 40.0, 48);
  PipelineParams params;
  params.remesh.max_faces = 1000;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_cylinder_too_fine_test.ply", params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->remesh_face_count, 0);
  EXPECT_EQ(result->estimates.noise_sigma, 0.0);
  ASSERT_EQ(result->regions.size(), 3u);
  for (std::size_t f = 0; f < shape.triangles.size(); ++f) {
    const Region& r = result->regions[result->face_labels[f]];
    ASSERT_EQ(r.type, shape.surface[f] == 0 ? SurfaceType::kCylinder : SurfaceType::kPlane);
    if (r.type == SurfaceType::kCylinder) {
      EXPECT_NEAR(std::get<Cylinder>(r.surface).radius, 10.0, 1e-9);
    }
  }
}

// The same shape with noise of 0.01 on its vertices: it is not an exact
// tessellation (no two triangles coplanar), so the pipeline remeshes it
// after all.
TEST(CadInput, TooFineButNotExactIsRemeshed) {
  testing::CadShape shape = testing::CadCylinder(10.0, 40.0, 48);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (Eigen::Vector3d& v : shape.vertices) {
    v += Eigen::Vector3d(noise(random), noise(random), noise(random));
  }
  PipelineParams params;
  params.remesh.max_faces = 1000;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_cylinder_not_exact_test.ply", params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_GT(result->remesh_face_count, 0);
  EXPECT_EQ(result->face_labels.size(), shape.triangles.size());
}

// On the scan path, a hole of r = 2.5 in a plate remeshed at edges of 1.5 (as the face budget
// sets them on a large plate, plate_holes.stl): the remesh is refined around
// it, and the hole comes back as one cylinder of its radius.
TEST(CadInput, SmallHoleOfAPlateIsFound) {
  const testing::CadShape shape = testing::CadPlateWithHole(20.0, 6.0, 2.5, 24);
  PipelineParams params;
  params.segment.exact = ExactMode::kNever;
  params.remesh.target_edge_length = 1.5;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_plate_hole_test.ply", params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_NEAR(result->remesh_fine_edge_length, 2.5 / 4.0, 0.01);
  const auto [region, share] = MainRegion(shape, *result, 0);
  ASSERT_GE(region, 0);
  EXPECT_EQ(share, 1.0);
  const Region& hole = result->regions[region];
  ASSERT_EQ(hole.type, SurfaceType::kCylinder);
  // Refitted on the input's vertices, the 24-gon's corners: r exactly.
  EXPECT_NEAR(std::get<Cylinder>(hole.surface).radius, 2.5, 1e-6);
  EXPECT_NEAR(std::abs(std::get<Cylinder>(hole.surface).axis_direction.z()), 1.0, 1e-9);
  for (const int surface : {1, 2}) {
    const auto [plane, plane_share] = MainRegion(shape, *result, surface);
    ASSERT_GE(plane, 0);
    EXPECT_EQ(plane_share, 1.0);
    EXPECT_EQ(result->regions[plane].type, SurfaceType::kPlane);
    EXPECT_LT(result->regions[plane].rms_distance, 1e-9);
  }
}

// The same at a uniform remesh: 10 edges around the hole, whose wall goes to
// planes (measured: 62 % of it in one plane, rms 2.8).
TEST(CadInput, SmallHoleIsLostWithoutTheFinerRemesh) {
  const testing::CadShape shape = testing::CadPlateWithHole(20.0, 6.0, 2.5, 24);
  PipelineParams params;
  params.segment.exact = ExactMode::kNever;
  params.remesh.target_edge_length = 1.5;
  params.remesh.small_radius_edges = 0.0;
  const absl::StatusOr<PipelineResult> result =
      RunOnShape(shape, "cad_plate_hole_uniform_test.ply", params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->remesh_fine_edge_length, 0.0);
  const auto [region, share] = MainRegion(shape, *result, 0);
  ASSERT_GE(region, 0);
  EXPECT_FALSE(result->regions[region].type == SurfaceType::kCylinder && share >= 0.95);
}

}  // namespace
}  // namespace meshseg
