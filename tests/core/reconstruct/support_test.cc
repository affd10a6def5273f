#include "reconstruct/support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "mesh/point_index.h"
#include "meshseg/generate.h"
#include "meshseg/reconstruct.h"
#include "reconstruct/surface_mesh.h"
#include "surface_metrics.h"

namespace meshseg::reconstruct_internal {
namespace {

// A flat strip [0, 2] × [0, 1] in z = 0, triangulated on a grid of `step`.
Mesh Strip(double step) {
  const int nx = static_cast<int>(std::lround(2.0 / step)),
            ny = static_cast<int>(std::lround(1.0 / step));
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) vertices.emplace_back(i * step, j * step, 0.0);
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  }
  return *SurfaceMesh(vertices, triangles, "strip");
}

// Points on a square grid of `spacing` covering x in [0, 1] of the strip.
std::vector<Eigen::Vector3d> HalfCovered(double spacing) {
  std::vector<Eigen::Vector3d> points;
  const int n = static_cast<int>(std::lround(1.0 / spacing));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) points.emplace_back(i * spacing, j * spacing, 0.0);
  }
  return points;
}

// Centroid x of face f.
double CentroidX(const TriMesh& tri, TriMesh::FaceHandle f) {
  double x = 0;
  for (const auto v : tri.fv_range(f)) x += tri.point(v)[0] / 3.0;
  return x;
}

// On a square grid of spacing a the mean distance to the 6 nearest is
// (4 a + 2 √2 a) / 6 = 1.14 a inside, (3 a + 2 √2 a + 2 a) / 6 = 1.30 a on
// the last row and (2 a + √2 a + 2 · 2 a + 2 √5 a) / 6 = 1.61 a at a corner.
// Inside the sampled area every centroid is supported; past its last row the
// support reaches half a local spacing along the surface, not 2 × that plus
// the band (the true border lies between the last row and the next, missing
// one).
TEST(SupportedFaces, PastTheSampledAreaOnlyHalfASpacingIsSupported) {
  const Mesh strip = Strip(0.02);
  const double a = 0.05;
  const std::vector<Eigen::Vector3d> points = HalfCovered(a);
  const mesh_internal::PointIndex index(points);
  const double band = 0.01;
  const std::vector<uint8_t> supported = SupportedFaces(strip.tri, points, index, 2.0, band, 0.0);
  ASSERT_EQ(supported.size(), strip.tri.n_faces());
  int past = 0;
  for (const auto f : strip.tri.faces()) {
    const double x = CentroidX(strip.tri, f);
    if (x < 1.0) {
      EXPECT_TRUE(supported[f.idx()]) << "x " << x;
    } else if (x - 1.0 > 0.041) {
      // The nearest point is at least x − 1 away, more than half of any
      // local spacing here (at most 0.5 × 1.61 a = 0.040); the isotropic
      // reach 2 × 1.30 a + band = 0.14 would keep those up to 0.14.
      past += x - 1.0 < 0.14;
      EXPECT_FALSE(supported[f.idx()]) << "x " << x;
    }
  }
  EXPECT_GT(past, 100);
}

// Points on the unit square with no point within `radius` of its centre.
std::vector<Eigen::Vector3d> WithHole(double spacing, double radius) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : HalfCovered(spacing)) {
    if ((p - Eigen::Vector3d(0.5, 0.5, 0.0)).norm() >= radius) points.push_back(p);
  }
  return points;
}

// Inside the sampled area a gap is judged relative to the density around it:
// the same gap is supported among sparse points and not among dense ones
// (its centroids are surrounded by points either way).
TEST(SupportedFaces, TheSameGapIsSupportedAmongSparsePointsOnly) {
  const Mesh strip = Strip(0.02);
  int dense_supported = 0, sparse_supported = 0, probed = 0;
  const std::vector<Eigen::Vector3d> dense = WithHole(0.025, 0.13), sparse = WithHole(0.1, 0.13);
  const mesh_internal::PointIndex dense_index(dense), sparse_index(sparse);
  const std::vector<uint8_t> by_dense = SupportedFaces(strip.tri, dense, dense_index, 2.0, 0.0, 0.0);
  const std::vector<uint8_t> by_sparse = SupportedFaces(strip.tri, sparse, sparse_index, 2.0, 0.0, 0.0);
  for (const auto f : strip.tri.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto v : strip.tri.fv_range(f)) c += ToEigen(strip.tri.point(v)) / 3.0;
    if ((c - Eigen::Vector3d(0.5, 0.5, 0.0)).norm() > 0.04) continue;
    ++probed;
    dense_supported += by_dense[f.idx()];
    sparse_supported += by_sparse[f.idx()];
  }
  ASSERT_GT(probed, 0);
  // Dense: the nearest point is over 0.09 away, its reach 2 s with s at most
  // 1.61 × 0.025 on the hole's rim, 0.081. Sparse: within 0.19 of points whose s
  // is at least 1.14 × 0.1, reach 0.228.
  EXPECT_EQ(dense_supported, 0);
  EXPECT_EQ(sparse_supported, probed);
}

// On a sphere the centroid of an inscribed triangle lies r² / R from the
// tangent plane at each corner (r its circumradius): the circle through the
// corners is tilted by asin(r / R) against each corner's tangent plane.
TEST(ChordError, OfATriangleOnASphereIsItsCircumradiusSquaredOverTheRadius) {
  const double R = 2.0, r = 0.3, depth = std::sqrt(R * R - r * r);
  std::array<Eigen::Vector3d, 3> corner, normal;
  for (int k = 0; k < 3; ++k) {
    corner[k] = Eigen::Vector3d(r * std::cos(2 * M_PI * k / 3), r * std::sin(2 * M_PI * k / 3),
                                depth);
    normal[k] = corner[k] / R;
  }
  EXPECT_NEAR(ChordError(corner, normal), r * r / R, 1e-12);
  // The face in its corners' tangent planes (a flat surface) has none.
  for (Eigen::Vector3d& n : normal) n = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(ChordError(corner, normal), 0.0, 1e-12);
}

// An open prism z in [0, 2] over the closed polygon `section` (counter-
// clockwise), with rings every 0.25: the faces are as coarse as the polygon.
Mesh Prism(const std::vector<Eigen::Vector2d>& section) {
  const int n = static_cast<int>(section.size()), rings = 9;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int r = 0; r < rings; ++r) {
    for (const Eigen::Vector2d& q : section) vertices.emplace_back(q.x(), q.y(), 0.25 * r);
  }
  for (int r = 0; r + 1 < rings; ++r) {
    for (int i = 0; i < n; ++i) {
      const int a = r * n + i, b = r * n + (i + 1) % n, c = a + n, d = b + n;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  }
  return *SurfaceMesh(vertices, triangles, "prism");
}

// Points `spacing` apart along the closed curve `at` (arc-length parameter
// t in [0, length)) and up z in [0, 1]: the prism's lower half is seen.
std::vector<Eigen::Vector3d> LowerHalfSamples(const std::function<Eigen::Vector2d(double)>& at,
                                              double length, double spacing) {
  std::vector<Eigen::Vector3d> points;
  const int n = static_cast<int>(std::lround(length / spacing));
  const int rows = static_cast<int>(std::lround(1.0 / spacing));
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i < n; ++i) {
      // Offset by half a step from the mesh's corners.
      const Eigen::Vector2d q = at((i + 0.5) * length / n);
      points.emplace_back(q.x(), q.y(), j * 1.0 / rows);
    }
  }
  return points;
}

// Expects every face of `prism` with all corners in the seen half (z ≤ 1)
// supported by `points`, and every face with a corner 0.25 beyond it not.
void ExpectSeenHalfSupported(const Mesh& prism, const std::vector<Eigen::Vector3d>& points,
                             const char* what) {
  const mesh_internal::PointIndex index(points);
  // The prism's faces are at most 1.23 long, within the resolution 1.5.
  const std::vector<uint8_t> supported = SupportedFaces(prism.tri, points, index, 2.0, 0.0, 1.5);
  int seen = 0, unseen = 0, seen_kept = 0, unseen_kept = 0;
  for (const auto f : prism.tri.faces()) {
    double hi = 0.0;
    for (const auto v : prism.tri.fv_range(f)) hi = std::max<double>(hi, prism.tri.point(v)[2]);
    if (hi <= 1.0) {
      ++seen;
      seen_kept += supported[f.idx()];
    } else {
      ++unseen;
      unseen_kept += supported[f.idx()];
    }
  }
  EXPECT_EQ(seen_kept, seen) << what << ": faces chording the seen surface";
  EXPECT_EQ(unseen_kept, 0) << what << ": faces of the unseen half (of " << unseen << ")";
}

// A mesh coarser than the points chords the surface between its corners:
// its centroids lie off the points by more than the reach 2 s (s = 1.14 ×
// 0.015 here, reach 0.034) although the face is on the surface. The reach of
// a face whose corners are on the points grows by its chord error. Faces with
// a corner in the unseen half are still not supported: those across the
// border have their centroid within the widened reach (0.131 on the cylinder,
// 0.228 at the cut corners) but a corner 0.25 off the points.
TEST(SupportedFaces, AFaceChordingTheSurfaceBetweenSeenCornersIsSupported) {
  const double spacing = 0.015;
  // Curvature: an octagon inscribed in the unit circle; a face's centroid lies
  // 1 − |2 + e^{iπ/4}| / 3 = 0.067 inside the cylinder.
  std::vector<Eigen::Vector2d> octagon;
  for (int i = 0; i < 8; ++i) octagon.emplace_back(std::cos(i * M_PI / 4), std::sin(i * M_PI / 4));
  const Mesh cylinder = Prism(octagon);
  const std::vector<Eigen::Vector3d> on_cylinder =
      LowerHalfSamples([](double t) { return Eigen::Vector2d(std::cos(t), std::sin(t)); },
                       2.0 * M_PI, spacing);
  ExpectSeenHalfSupported(cylinder, on_cylinder, "cylinder");
  // Faces longer than the mesh's resolution (0.5 here) are tents, not chords:
  // none of these is supported then.
  const mesh_internal::PointIndex index(on_cylinder);
  const std::vector<uint8_t> coarse =
      SupportedFaces(cylinder.tri, on_cylinder, index, 2.0, 0.0, 0.5);
  EXPECT_EQ(std::count(coarse.begin(), coarse.end(), 1), 0);
  // Creases: the square |x|, |y| ≤ 1 with its corners cut by chords from
  // (1, 0.6) to (0.6, 1); a chord face's centroid lies 0.133 inside the square.
  std::vector<Eigen::Vector2d> cut;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Rotation2Dd turn(k * M_PI / 2);
    cut.push_back(turn * Eigen::Vector2d(1.0, 0.6));
    cut.push_back(turn * Eigen::Vector2d(0.6, 1.0));
  }
  const auto square = [](double t) {
    // Side k runs from corner (1, −1) turned by k × 90°, anticlockwise.
    const int k = std::min(3, static_cast<int>(t / 2.0));
    return Eigen::Vector2d(Eigen::Rotation2Dd(k * M_PI / 2) *
                           Eigen::Vector2d(1.0, -1.0 + (t - 2.0 * k)));
  };
  ExpectSeenHalfSupported(Prism(cut), LowerHalfSamples(square, 8.0, spacing), "square");
}

// Reconstructs the generated scan of `part` (`points`, draw `seed`; the
// covering's draw `covering`) and expects accuracy p95 ≤ 3.5 sp and visible
// completeness p95 ≤ 5.5 sp.
void ExpectScanMeetsTheBar(const std::string& part, int points, uint64_t seed,
                           uint64_t covering = ReconstructParams{}.seed) {
  ScanParams sp;
  sp.points = points;
  sp.seed = seed;
  const auto scan = ScanPart(part, sp);
  ASSERT_TRUE(scan.ok()) << scan.status();
  ReconstructParams params;
  params.seed = covering;
  const auto rec = Reconstruct(scan->cloud, params);
  ASSERT_TRUE(rec.ok()) << rec.status();
  EXPECT_GT(rec->stats.filled_area, 0.0) << part << ": the underside is closed";
  const double spacing = test::MedianSpacing(scan->cloud.points);
  const auto mesh = test::Triangles(rec->mesh.tri);
  const auto truth = test::Triangles(scan->part.mesh.tri);
  const test::SurfaceDistance to_mesh(mesh), to_truth(truth);
  const mesh_internal::PointIndex index(scan->cloud.points);
  std::vector<Eigen::Vector3d> visible;
  for (const Eigen::Vector3d& p : test::AreaSamples(truth, 20000)) {
    if ((scan->cloud.points[index.Closest(p)] - p).norm() <= 3.0 * spacing) visible.push_back(p);
  }
  const double accuracy =
      test::Quantile(test::SortedDistances(test::AreaSamples(mesh, 20000), to_truth), 0.95);
  const double completeness = test::Quantile(test::SortedDistances(visible, to_mesh), 0.95);
  EXPECT_LE(accuracy, 3.5 * spacing)
      << part << ", covering draw " << covering << ": accuracy p95 " << accuracy / spacing << " sp";
  EXPECT_LE(completeness, 5.5 * spacing)
      << part << ": completeness p95 " << completeness / spacing << " sp";
  ::testing::Test::RecordProperty(part + "_accuracy_p95_sp_draw_" + std::to_string(seed),
                                  std::to_string(accuracy / spacing));
}

// Issue 38 item 1, through the whole reconstruction: generated scans (four
// views 35° above the part, range noise, grazing rays lost) of a turned part
// never see its flat underside, which the reconstruction closes with a
// patch. Measured in the cloud's median spacing sp against the part's truth:
// accuracy p95 (the whole mesh, patches included) ≤ 3.5 sp and completeness
// p95 of the visible truth (within 3 sp of a point) ≤ 5.5 sp, at once. With
// the support reaching 2 s + band past the last samples, the walls ran on
// below the true bottom and the patch closed there: accuracy p95 10.0 and
// 9.5 sp on these two draws. (A curved underside, or one whose loop spans
// more than the cubic search takes, still misses the bar.)
TEST(SupportedFaces, TheUnseenFlatUndersideOfAScanIsClosedAtTheSeenBorder) {
  for (const uint64_t seed : {1, 2}) ExpectScanMeetsTheBar("stepped_shaft", 15000, seed);
}

// The same bar on a machined block whose walls the views see down to
// different heights: the loop round its unseen underside zigzags along the
// walls' lowest seen rows (about 400 vertices) and climbs them. A fan closed
// it before (CGAL's Delaunay search fails on it, and the cubic one was
// skipped past 150 vertices), and a membrane cuts the corners between the
// walls and the underside: accuracy p95 3.76 sp. Now the cubic search
// triangulates it and the patch is bent onto the walls extended and the
// underside's plane (seen_planes.h).
TEST(SupportedFaces, TheUnseenUndersideBelowWallsSeenToDifferentHeightsMeetsTheBar) {
  ExpectScanMeetsTheBar("test_piece", 15000, 1);
}

// The same block scanned at 40K points: the loop round the unseen underside
// has about 580 vertices, past what the cubic search takes, and a fan closed
// it (accuracy p95 5.73 sp). Now it is split by a chord between the two loop
// vertices nearest each other across the underside, and each half is
// triangulated and bent onto the seen planes.
TEST(SupportedFaces, AnUndersideLoopTooLongForTheCubicSearchIsSplitByAChord) {
  ExpectScanMeetsTheBar("test_piece", 40000, 2);
}


// A plate 8 thick with a boss and two through-holes, scanned from above: its
// bottom is unseen, and a hull ball grown in the empty space under it holds
// a handful of the seen top's points through the solid, all of them facing
// away from its centre (cover.h CoveringWeights). Kept at r² (a sparse
// ball's fit does not read its side), its power cell took in the plate and
// the surface closed just under the seen top, a second sheet the bottom's
// patch climbed to: accuracy p95 6.08 and 5.16 sp at these two covering
// draws (the scan table's plate_boss, 15000 points, scan draw 1).
TEST(SupportedFaces, AHullBallUnderAPlatesUnseenBottomDoesNotHollowThePlate) {
  for (const uint64_t covering : {1, 3}) ExpectScanMeetsTheBar("plate_boss", 15000, 1, covering);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
