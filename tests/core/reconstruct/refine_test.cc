#include "reconstruct/refine.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "clouds.h"
#include "core/curvature/test_meshes.h"
#include "meshseg/remesh.h"
#include "reconstruct/project_to_points.h"
#include "grid_supports.h"
#include "surface_metrics.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr double kRadius = 1.0;
constexpr int kPoints = 20000;

double Spacing() { return std::sqrt(4 * M_PI * kRadius * kRadius / kPoints); }

// What marching tetrahedra gives, roughly: an icosahedron on the sphere, its
// faces split in four 3 times (edges of 5 point spacings), every vertex moved
// off the sphere by up to half a spacing.
Mesh CoarseSphere() {
  absl::StatusOr<Mesh> mesh = testing::MakeSphere(kRadius, 3);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> off(-0.5 * Spacing(), 0.5 * Spacing());
  for (const auto v : mesh->tri.vertices()) {
    mesh->tri.set_point(v, mesh->tri.point(v) * (1.0 + off(rng) / kRadius));
  }
  mesh->tri.update_normals();
  return *std::move(mesh);
}

// kPoints uniform on the sphere, keeping those with z above `min_z`.
std::vector<Eigen::Vector3d> SpherePoints(double min_z = -2 * kRadius) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < kPoints; ++i) {
    const Eigen::Vector3d p = kRadius * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    if (p.z() > min_z) points.push_back(p);
  }
  return points;
}

TEST(SplitInFour, QuartersEveryTriangleKeepingTheClosedSurface) {
  const absl::StatusOr<Mesh> mesh = testing::MakeSphere(kRadius, 2);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const absl::StatusOr<Mesh> split = SplitInFour(*mesh);
  ASSERT_TRUE(split.ok()) << split.status();
  EXPECT_EQ(split->tri.n_faces(), 4 * mesh->tri.n_faces());
  EXPECT_EQ(split->tri.n_vertices(), mesh->tri.n_vertices() + mesh->tri.n_edges());
  for (const auto e : split->tri.edges()) ASSERT_FALSE(split->tri.is_boundary(e));
  EXPECT_NEAR(Assess(*split).surface_area, Assess(*mesh).surface_area, 1e-9);
  double longest = 0.0, longest_split = 0.0;
  for (const auto e : mesh->tri.edges()) longest = std::max(longest, mesh->tri.calc_edge_length(e));
  for (const auto e : split->tri.edges()) {
    longest_split = std::max(longest_split, split->tri.calc_edge_length(e));
  }
  EXPECT_NEAR(longest_split, 0.5 * longest, 1e-12);
  // Outward orientation kept: the signed volume is unchanged.
  const auto volume = [](const Mesh& m) {
    double v = 0.0;
    for (const auto f : m.tri.faces()) {
      auto fv = m.tri.cfv_iter(f);
      const Eigen::Vector3d a = ToEigen(m.tri.point(*fv)), b = ToEigen(m.tri.point(*++fv)),
                            c = ToEigen(m.tri.point(*++fv));
      v += a.dot(b.cross(c)) / 6.0;
    }
    return v;
  };
  EXPECT_NEAR(volume(*split), volume(*mesh), 1e-9);
}

// The implicit of the unit sphere (f = 1 − |x| to first order, positive
// inside) over supports on a 9³ grid.
class RefineOnPointsTest : public ::testing::Test {
 protected:
  // RefineOnPoints on CoarseSphere() with `points` and this implicit.
  absl::StatusOr<Mesh> Refine(const std::vector<Eigen::Vector3d>& points,
                              const ReconstructParams& params, ReconstructStats* stats) const {
    const mesh_internal::PointIndex index(points);
    return RefineOnPoints(CoarseSphere(), points, {}, index, f_, Spacing(), params, {}, stats);
  }

  const std::vector<Support> supports_ = test::GridSupports(9, 1.5 * kRadius);
  const PuFunction f_{supports_};
};

// The coarse sphere becomes a fine one on the points: every vertex within the
// sag of the projection (radius² / 8R, see project_to_points_test) plus 0.1 h,
// edges of about refine_edge_length spacings, the same closed genus-0 surface.
TEST_F(RefineOnPointsTest, TurnsACoarseMeshIntoAFineOneOnThePoints) {
  const double h = Spacing();
  const ReconstructParams params;
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine = Refine(SpherePoints(), params, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  const TriMesh& m = fine->tri;
  EXPECT_DOUBLE_EQ(stats.refine_edge_length, params.refine_edge_length * h);
  const double edge = MeanEdgeLength(m) / h;
  EXPECT_GT(edge, 1.2);
  EXPECT_LT(edge, 1.8);
  const double r = params.projection_radius * h;
  for (const auto v : m.vertices()) {
    ASSERT_NEAR(ToEigen(m.point(v)).norm(), kRadius - r * r / (8 * kRadius), 0.1 * h)
        << "vertex " << v.idx();
  }
  EXPECT_EQ(stats.unsupported_vertex_count, 0);
  EXPECT_EQ(static_cast<int64_t>(m.n_vertices()) - static_cast<int64_t>(m.n_edges()) +
                static_cast<int64_t>(m.n_faces()),
            2);
  for (const auto e : m.edges()) ASSERT_FALSE(m.is_boundary(e));
}

TEST_F(RefineOnPointsTest, MaxFacesLengthensTheEdges) {
  constexpr int64_t kMaxFaces = 2000;
  const double h = Spacing();
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine = Refine(SpherePoints(), {.refine_max_faces = kMaxFaces}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  EXPECT_GT(stats.refine_edge_length, 1.5 * h);
  // CGAL keeps edges within 4/5 and 4/3 of the target, so the count is about,
  // not at most, the cap.
  EXPECT_GT(fine->tri.n_faces(), 0.5 * kMaxFaces);
  EXPECT_LT(fine->tri.n_faces(), 1.5 * kMaxFaces);
}

// A coarse mesh far inside the points, as marching-tetrahedra triangles
// between large supports are on a dense sample: the sphere shrunk to a
// quarter, 30 spacings from every point, beyond any projection's reach.
// Newton steps take its vertices onto f = 0 however far that is (ten steps
// of a projection radius left them 5 h short); where the points fill the
// projection neighbourhood there, they end on the points like every other
// vertex, elsewhere they stay on f = 0 (on this coarse grid up to ~1.4 h
// off the sphere).
TEST_F(RefineOnPointsTest, VerticesFarInsideGoOntoTheImplicitAndThenOntoThePoints) {
  const double h = Spacing();
  ReconstructParams params;
  params.sharp_creases = false;  // no normals given
  const std::vector<Eigen::Vector3d> points = SpherePoints();
  const mesh_internal::PointIndex index(points);
  Mesh coarse = CoarseSphere();
  for (const auto v : coarse.tri.vertices()) coarse.tri.set_point(v, 0.25 * coarse.tri.point(v));
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine =
      RefineOnPoints(coarse, points, {}, index, f_, h, params, {}, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  const TriMesh& m = fine->tri;
  const double r = params.projection_radius * h;
  int64_t on_points = 0;
  for (const auto v : m.vertices()) {
    const Eigen::Vector3d x = ToEigen(m.point(v));
    if (std::abs(x.norm() - (kRadius - r * r / (8 * kRadius))) < 0.1 * h) {
      ++on_points;
    } else {
      ASSERT_LT(std::abs(f_(x)), 0.01 * h)
          << "vertex " << v.idx() << " neither on the points nor on f = 0";
    }
  }
  EXPECT_GT(on_points, m.n_vertices() / 2);  // 78 % measured
  EXPECT_EQ(stats.unsupported_vertex_count, static_cast<int64_t>(m.n_vertices()) - on_points);
  for (const auto e : m.edges()) ASSERT_FALSE(m.is_boundary(e));
  ::testing::Test::RecordProperty("on_points",
                                  std::to_string(on_points) + "/" + std::to_string(m.n_vertices()));
}

// Points on the upper part only, as if the scanner never saw the rest:
// vertices over kFallbackReach projection radii from every point go onto
// f = 0 instead (the grid supports put it near the unit sphere).
TEST_F(RefineOnPointsTest, VerticesFarFromThePointsGoOntoTheImplicit) {
  const double h = Spacing();
  const ReconstructParams params;
  ReconstructStats stats;
  const absl::StatusOr<Mesh> fine = Refine(SpherePoints(0.0), params, &stats);
  ASSERT_TRUE(fine.ok()) << fine.status();
  const TriMesh& m = fine->tri;
  const double reach = kFallbackReach * params.projection_radius * h;
  int64_t far = 0;
  double worst = 0.0;
  for (const auto v : m.vertices()) {
    const Eigen::Vector3d x = ToEigen(m.point(v));
    if (x.z() > -reach) continue;  // near the points, or widened to reach them
    ++far;
    worst = std::max(worst, std::abs(f_(x)));
  }
  EXPECT_GT(far, 0);
  EXPECT_GE(stats.unsupported_vertex_count, far);
  // |∇f| ≈ 1, so |f| is the distance to the zero set, which on this coarse
  // grid lies up to 1.4 h inside the unit sphere: left where the remesh put
  // them, the vertices would be 1–2 h from it.
  EXPECT_LT(worst, 0.01 * h);
}

// A block with a step: [−1, 1] × [−0.7, 0.7] × [−0.5, 0.5] without the
// quarter x > 0, z > 0. Eleven convex right-angled edges and one concave
// one (x = 0, z = 0, along y), all sharp. Its faces as rectangles
// p = origin + u a + v b, u, v in [0, 1], with outward normals.
struct Rect {
  Eigen::Vector3d origin, a, b, normal;
};
std::vector<Rect> SteppedBlockFaces() {
  const double y = 0.7;
  std::vector<Rect> rects = {
      {{-1, -y, -0.5}, {0, 2 * y, 0}, {0, 0, 1}, {-1, 0, 0}},  // x = −1
      {{1, -y, -0.5}, {0, 2 * y, 0}, {0, 0, 0.5}, {1, 0, 0}},  // x = 1, lower
      {{0, -y, 0}, {0, 2 * y, 0}, {0, 0, 0.5}, {1, 0, 0}},     // step wall x = 0
      {{-1, -y, -0.5}, {2, 0, 0}, {0, 2 * y, 0}, {0, 0, -1}},  // z = −0.5
      {{-1, -y, 0.5}, {1, 0, 0}, {0, 2 * y, 0}, {0, 0, 1}},    // z = 0.5, left
      {{0, -y, 0}, {1, 0, 0}, {0, 2 * y, 0}, {0, 0, 1}},       // step floor z = 0
  };
  for (const double s : {-y, y}) {  // the L-shaped sides as two rectangles
    rects.push_back({{-1, s, -0.5}, {1, 0, 0}, {0, 0, 1}, {0, s / y, 0}});
    rects.push_back({{0, s, -0.5}, {1, 0, 0}, {0, 0, 0.5}, {0, s / y, 0}});
  }
  return rects;
}

// Uniform samples by area with outward normals (MakeCloud; no sdf: no
// clumps are asked for).
test::Shape SteppedBlock() {
  const std::vector<Rect> rects = SteppedBlockFaces();
  std::vector<double> areas;
  for (const Rect& r : rects) areas.push_back(r.a.cross(r.b).norm());
  test::Shape s;
  s.sample = [rects, areas](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::discrete_distribution<int> pick(areas.begin(), areas.end());
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Rect& r = rects[pick(rng)];
    *p = r.origin + u(rng) * r.a + u(rng) * r.b;
    *n = r.normal;
  };
  for (const double a : areas) s.area += a;
  return s;
}

// The true surface as triangles, two per face rectangle.
std::vector<test::Triangle> SteppedBlockTriangles() {
  std::vector<test::Triangle> out;
  for (const Rect& r : SteppedBlockFaces()) {
    out.push_back({r.origin, r.origin + r.a, r.origin + r.a + r.b});
    out.push_back({r.origin, r.origin + r.a + r.b, r.origin + r.b});
  }
  return out;
}

// Points along the block's twelve edges, 0.01 apart, farther than `margin`
// from its corners (where three faces meet, which two planes do not model).
std::vector<Eigen::Vector3d> SteppedBlockEdgePoints(double margin) {
  const double y = 0.7;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> edges = {
      {{-1, -y, -0.5}, {-1, y, -0.5}}, {{-1, -y, 0.5}, {-1, y, 0.5}},
      {{1, -y, -0.5}, {1, y, -0.5}},   {{1, -y, 0}, {1, y, 0}},
      {{0, -y, 0.5}, {0, y, 0.5}},     {{0, -y, 0}, {0, y, 0}},  // the concave edge
  };
  for (const double s : {-y, y}) {
    edges.push_back({{-1, s, -0.5}, {1, s, -0.5}});
    edges.push_back({{-1, s, -0.5}, {-1, s, 0.5}});
    edges.push_back({{-1, s, 0.5}, {0, s, 0.5}});
    edges.push_back({{0, s, 0}, {0, s, 0.5}});
    edges.push_back({{0, s, 0}, {1, s, 0}});
    edges.push_back({{1, s, -0.5}, {1, s, 0}});
  }
  std::vector<Eigen::Vector3d> out;
  for (const auto& [a, b] : edges) {
    const double length = (b - a).norm();
    for (double t = margin; t <= length - margin; t += 0.01)
      out.push_back(a + t / length * (b - a));
  }
  return out;
}

// Issue 38 item 3, "sharp edges kept": clean and lightly noisy (σ 0.1 of
// the sampling's spacing, about 0.2 sp) samples of a part with convex and
// concave right-angled edges, given normals. Distances in sp, the cloud's
// median nearest-neighbour distance (issue 38's unit). Measured: the
// edges' p95 distance to the reconstruction, away from the corners (three
// planes, not modelled), over 2 sp rounded (sharp_creases off: one plane
// per vertex; 3.2 sp at 8000 points) and 0.61 sp sharp on the clean cloud,
// 1.08 sp sharp on the noisy one; the whole surface's accuracy p95 0.30 and
// 0.72 sp. The clean bound guards the halving of stretched crease edges to
// convergence: stopped after four rounds, tents across the edges stayed and
// the clean accuracy was 0.41 sp.
TEST(SharpCreases, TheEdgesOfASteppedBlockStaySharp) {
  const test::Shape block = SteppedBlock();
  const std::vector<Eigen::Vector3d> edge_points = SteppedBlockEdgePoints(0.1);
  const test::SurfaceDistance to_truth(SteppedBlockTriangles());
  struct Case {
    double noise, max_edges, max_accuracy;  // noise in spacings, bounds in sp
  };
  for (const Case c : {Case{0.0, 0.75, 0.375}, Case{0.1, 1.5, 1.0}}) {
    const PointCloud cloud = test::MakeCloud(block, {.points = 6000, .noise = c.noise});
    const double sp = test::MedianSpacing(cloud.points);
    const auto sharp = Reconstruct(cloud);
    ASSERT_TRUE(sharp.ok()) << sharp.status();
    const std::vector<test::Triangle> triangles = test::Triangles(sharp->mesh.tri);
    const test::SurfaceDistance to_sharp(triangles);
    const double edges = test::Quantile(test::SortedDistances(edge_points, to_sharp), 0.95) / sp;
    const double accuracy =
        test::Quantile(test::SortedDistances(test::AreaSamples(triangles, 4000), to_truth), 0.95) /
        sp;
    EXPECT_LT(edges, c.max_edges) << "noise " << c.noise;
    EXPECT_LT(accuracy, c.max_accuracy) << "noise " << c.noise;
    EXPECT_GT(sharp->stats.crease_vertex_count, 0);
    EXPECT_GT(sharp->stats.crease_inserted_count + sharp->stats.crease_snapped_count, 0);
    EXPECT_EQ(test::BoundaryEdgeCount(sharp->mesh.tri), 0);
    EXPECT_EQ(test::NonManifoldVertexCount(sharp->mesh.tri), 0);
    EXPECT_EQ(sharp->mesh.face_of_input.size(), sharp->mesh.tri.n_faces());
    ::testing::Test::RecordProperty(c.noise == 0 ? "edges_sp_clean" : "edges_sp_noisy",
                                    std::to_string(edges));
    if (c.noise > 0) continue;
    // The same cloud with one plane per vertex: the edges rounded off.
    const auto round = Reconstruct(cloud, {.sharp_creases = false});
    ASSERT_TRUE(round.ok()) << round.status();
    const test::SurfaceDistance to_round(test::Triangles(round->mesh.tri));
    EXPECT_GT(test::Quantile(test::SortedDistances(edge_points, to_round), 0.95) / sp, 2.0);
    EXPECT_EQ(round->stats.crease_vertex_count, 0);
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
