#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
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

// Points along the 12 edges of TurnedBox(half, degrees), away from the
// corners (the middle 80 % of each edge).
std::vector<Eigen::Vector3d> BoxEdgePoints(const Eigen::Vector3d& half, double degrees) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(degrees * 3.14159265358979 / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  std::vector<Eigen::Vector3d> points;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sa : {-1, 1}) {
      for (int sb : {-1, 1}) {
        for (double t = -0.8; t <= 0.8; t += 0.05) {
          Eigen::Vector3d p;
          p[axis] = t * half[axis];
          p[(axis + 1) % 3] = sa * half[(axis + 1) % 3];
          p[(axis + 2) % 3] = sb * half[(axis + 2) % 3];
          points.push_back(r * p);
        }
      }
    }
  }
  return points;
}

// The largest distance from `points` to the surface of `mesh`.
double FarthestFrom(const std::vector<Eigen::Vector3d>& points, const TriMesh& mesh) {
  double worst = 0.0;
  for (const Eigen::Vector3d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (auto f : mesh.faces()) {
      auto it = mesh.cfv_iter(f);
      const Eigen::Vector3d a = ToEigen(mesh.point(*it++)), b = ToEigen(mesh.point(*it++)),
                            c = ToEigen(mesh.point(*it));
      best = std::min(best, SquaredDistanceToTriangle(p, a, b, c));
    }
    worst = std::max(worst, std::sqrt(best));
  }
  return worst;
}

// A plain (grey, noise-free) box at a tenth of its faces: its creases are
// found and kept, so the box's edges are no farther from the simplified
// surface than from the input (whose marching cubes already bevel them) plus
// a tenth of a voxel, and the whole surface stays within a quarter voxel.
TEST(Simplify, PlainMeshKeepsItsCreasesAtATenthOfTheFaces) {
  const Eigen::Vector3d half(5, 4, 3);
  const VolumeSurface s = testing::SurfaceOf(
      testing::SampleSdf(testing::TurnedBox(half, 17.0), 36, kH, false), "grey_box.nrrd");
  const int64_t target = static_cast<int64_t>(s.mesh.tri.n_faces()) / 10;
  const absl::StatusOr<Simplification> out = Simplify(s.mesh.tri, {.target_faces = target});
  ASSERT_TRUE(out.ok()) << out.status();
  EXPECT_LE(out->mesh.tri.n_faces(), target + 2);
  const std::vector<Eigen::Vector3d> edges = BoxEdgePoints(half, 17.0);
  const double input_gap = FarthestFrom(edges, s.mesh.tri);
  const double output_gap = FarthestFrom(edges, out->mesh.tri);
  std::cout << "box edges to the input " << input_gap / kH << " h, to the output "
            << output_gap / kH << " h; Hausdorff " << out->hausdorff.Max() / kH << " h\n";
  EXPECT_LE(output_gap, input_gap + 0.1 * kH);
  EXPECT_LE(out->hausdorff.Max(), 0.25 * kH);
}

// The same box collapsed in two lanes at once (forced here; by default only
// from 200 000 faces): the halves and then the band between them reach the
// same target with the same bars, and the result is still a closed surface
// of genus 0 (V - E + F = 2, no border); progress only rises.
TEST(Simplify, TwoLanesKeepTheCreasesAndTheSurfaceClosed) {
  const Eigen::Vector3d half(5, 4, 3);
  const VolumeSurface s = testing::SurfaceOf(
      testing::SampleSdf(testing::TurnedBox(half, 17.0), 36, kH, false), "grey_box_lanes.nrrd");
  const int64_t target = static_cast<int64_t>(s.mesh.tri.n_faces()) / 10;
  std::vector<double> progress;
  RunContext ctx;
  ctx.on_progress = [&](std::string_view stage, double fraction) {
    if (stage == "simplify") progress.push_back(fraction);
  };
  const absl::StatusOr<Simplification> out =
      Simplify(s.mesh.tri, {.target_faces = target, .two_lanes_min_faces = 1}, {}, {}, ctx);
  ASSERT_TRUE(out.ok()) << out.status();
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end())) << "progress only rises";
  EXPECT_EQ(progress.back(), 1.0);
  const TriMesh& m = out->mesh.tri;
  EXPECT_LE(m.n_faces(), target + 2);
  EXPECT_GE(m.n_faces(), target - 2);
  for (auto e : m.edges()) ASSERT_FALSE(m.is_boundary(e)) << "edge " << e.idx();
  EXPECT_EQ(static_cast<int64_t>(m.n_vertices()) - static_cast<int64_t>(m.n_edges()) +
                static_cast<int64_t>(m.n_faces()),
            2);
  const std::vector<Eigen::Vector3d> edges = BoxEdgePoints(half, 17.0);
  const double input_gap = FarthestFrom(edges, s.mesh.tri);
  const double output_gap = FarthestFrom(edges, m);
  std::cout << "two lanes: box edges to the output " << output_gap / kH << " h; Hausdorff "
            << out->hausdorff.Max() / kH << " h\n";
  EXPECT_LE(output_gap, input_gap + 0.1 * kH);
  EXPECT_LE(out->hausdorff.Max(), 0.25 * kH);
}

// An open square patch (height noise of amplitude 0.01): its border is a
// feature line, so the border stays on the square's sides and the four
// corners stay, both to within the noise.
TEST(Simplify, OpenBorderSlidesAlongItselfAndKeepsItsCorners) {
  constexpr int kN = 21;
  constexpr double kNoise = 0.01;
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j < kN; ++j) {
    for (int i = 0; i < kN; ++i) points.emplace_back(i, j, kNoise * std::sin(i * j));
  }
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j + 1 < kN; ++j) {
    for (int i = 0; i + 1 < kN; ++i) {
      const int a = j * kN + i;
      triangles.push_back({a, a + 1, a + kN + 1});
      triangles.push_back({a, a + kN + 1, a + kN});
    }
  }
  const absl::StatusOr<Mesh> patch = BuildMesh(points, triangles, "patch");
  ASSERT_TRUE(patch.ok()) << patch.status();
  const absl::StatusOr<Simplification> out = Simplify(patch->tri, {.target_faces = 80});
  ASSERT_TRUE(out.ok()) << out.status();
  EXPECT_LE(out->mesh.tri.n_faces(), 82u);
  int corners = 0;
  for (auto v : out->mesh.tri.vertices()) {
    if (!out->mesh.tri.is_boundary(v)) continue;
    const auto p = out->mesh.tri.point(v);
    const double side = std::min({p[0], p[1], kN - 1 - p[0], kN - 1 - p[1]});
    EXPECT_NEAR(side, 0.0, kNoise) << "border vertex off the square at " << p[0] << ", " << p[1];
    corners += std::min(p[0], kN - 1 - p[0]) < kNoise && std::min(p[1], kN - 1 - p[1]) < kNoise;
  }
  EXPECT_EQ(corners, 4);
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
