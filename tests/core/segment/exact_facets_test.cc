#include "segment/exact_facets.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "segment/estimate_noise.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kLength = 20.0;

// A prism along x, length kLength, over the closed convex polygon `profile`
// (y, z), with fan caps: every vertex exact, the side triangles long and
// thin like a CAD export's; side facet i runs from profile[i] to the next.
// With `chord_facet` >= 0, that side facet has a vertex in the middle of its
// edge on the x = 0 cap, on the chord under the arc, in three triangles: a
// CAD tessellator adds such a vertex to meet the cap's triangulation.
Mesh ProfilePrism(const std::vector<Eigen::Vector2d>& profile, int chord_facet = -1) {
  const int count = static_cast<int>(profile.size());
  std::vector<Eigen::Vector3d> v;
  for (const double x : {0.0, kLength}) {
    for (const Eigen::Vector2d& p : profile) v.emplace_back(x, p.x(), p.y());
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i) centre += v[i] / count;
  v.push_back(centre);
  v.push_back(centre + Eigen::Vector3d(kLength, 0, 0));
  const int c0 = 2 * count;
  const int c1 = c0 + 1;
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i < count; ++i) {
    const int j = (i + 1) % count;
    if (i == chord_facet) {
      const int m = static_cast<int>(v.size());
      v.push_back(0.5 * (v[i] + v[j]));
      f.push_back({i, m, count + i});
      f.push_back({m, j, count + j});
      f.push_back({m, count + j, count + i});
      f.push_back({c0, m, i});
      f.push_back({c0, j, m});
    } else {
      f.push_back({i, j, count + j});
      f.push_back({i, count + j, count + i});
      f.push_back({c0, j, i});
    }
    f.push_back({c1, count + i, count + j});
  }
  absl::StatusOr<Mesh> mesh = BuildMesh(std::move(v), f, "prism");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

// The prism over `count` points on a circle of `radius` from angle 0 to
// `arc_deg`, closed by the chord when arc_deg < 360.
Mesh ArcPrism(double radius, int count, double arc_deg, int chord_facet = -1) {
  const bool closed = arc_deg >= 360.0;
  const double step = arc_deg / (closed ? count : count - 1) * std::numbers::pi / 180.0;
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i < count; ++i) {
    profile.emplace_back(radius * std::cos(i * step), radius * std::sin(i * step));
  }
  return ProfilePrism(profile, chord_facet);
}

// A square of side `side` with its corners rounded by `radius` in `steps`
// facets each; the first side facet is the flat bottom side.
std::vector<Eigen::Vector2d> RoundedSquare(double side, double radius, int steps) {
  const double inner = side / 2 - radius;
  std::vector<Eigen::Vector2d> profile = {{-inner, -side / 2}};
  const Eigen::Vector2d centres[] = {
      {inner, -inner}, {inner, inner}, {-inner, inner}, {-inner, -inner}};
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j <= steps; ++j) {
      if (k == 3 && j == steps) break;  // the first point
      const double a = (k - 1 + static_cast<double>(j) / steps) * std::numbers::pi / 2;
      profile.push_back(centres[k] + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  return profile;
}

struct ExactRun {
  CurvatureField field;
  SegmentEstimates estimates;
  FaceRegions regions;
};

ExactRun SegmentExact(const Mesh& mesh) {
  ExactRun run;
  absl::StatusOr<CurvatureField> field = EstimateCurvature(mesh);
  EXPECT_TRUE(field.ok()) << field.status();
  run.field = *std::move(field);
  run.estimates = EstimateNoise(run.field, MeanEdgeLength(mesh.tri), {});
  const RunContext ctx;
  const SegmentContext c = MakeSegmentContext(mesh.tri, run.field, run.estimates, 0.9, ctx);
  absl::StatusOr<FaceRegions> regions = SegmentExactFacets(c, mesh.tri);
  EXPECT_TRUE(regions.ok()) << regions.status();
  run.regions = *std::move(regions);
  return run;
}

// A half round in 8 facets on a flat bottom: one exact cylinder (all 16 side
// triangles of the arc) and three planes. The bottom's corners lie on the
// cylinder too; its normal, at 90° to the cylinder's there, keeps it out.
TEST(SegmentExactFacets, FindsTheCylinderOfACoarseHalfRound) {
  const Mesh mesh = ArcPrism(2.0, 9, 180.0);
  const ExactRun run = SegmentExact(mesh);
  ASSERT_EQ(run.regions.regions.size(), 4u);
  int cylinders = 0;
  for (std::size_t r = 0; r < run.regions.regions.size(); ++r) {
    const RegionState& region = run.regions.regions[r];
    if (const auto* cyl = std::get_if<Cylinder>(&region.surface)) {
      ++cylinders;
      EXPECT_EQ(region.type, SurfaceType::kCylinder);
      EXPECT_NEAR(cyl->radius, 2.0, 1e-6);
      EXPECT_NEAR(std::abs(cyl->axis_direction.x()), 1.0, 1e-9);
      EXPECT_EQ(std::count(run.regions.face_labels.begin(), run.regions.face_labels.end(),
                           static_cast<int>(r)),
                16);
    } else {
      EXPECT_EQ(region.type, SurfaceType::kPlane);
    }
  }
  EXPECT_EQ(cylinders, 1);
}

// A half round in 18 facets of 10 degrees, one of them with a vertex on its
// cap edge 0.0076 under the arc (tray_bottom_1002.stl's slot ends and holes
// are so): one cylinder still holds all 37 side triangles.
TEST(SegmentExactFacets, AFacetWithAVertexOnItsChordStaysOnTheCylinder) {
  const Mesh mesh = ArcPrism(2.0, 19, 180.0, /*chord_facet=*/8);
  const ExactRun run = SegmentExact(mesh);
  int cylinders = 0;
  for (std::size_t r = 0; r < run.regions.regions.size(); ++r) {
    const RegionState& region = run.regions.regions[r];
    if (region.type != SurfaceType::kCylinder) continue;
    ++cylinders;
    EXPECT_NEAR(std::get<Cylinder>(region.surface).radius, 2.0, 1e-6);
    EXPECT_EQ(std::count(run.regions.face_labels.begin(), run.regions.face_labels.end(),
                         static_cast<int>(r)),
              37);
  }
  EXPECT_EQ(cylinders, 1);
  EXPECT_EQ(run.regions.regions.size(), 4u);  // the cylinder, two caps, the flat bottom
}

// A flat side between the last facets of two equal rounds is an isosceles
// trapezoid in section, and so lies on a circle exactly: tray_bottom_1002.stl
// read in micrometres got a slot side as a cylinder of radius 46 mm with its
// rounds' end facets, when the fit through them happened to converge. Each
// round keeps its facets, and the sides are planes. (Side, round radius,
// facets per round: all four gave such a cylinder before seeds stepping
// evenly around their axis went first.)
struct RoundedSquareCase {
  const char* name;
  double side;
  double radius;
  int steps;
};

void PrintTo(const RoundedSquareCase& square, std::ostream* os) { *os << square.name; }

class SegmentExactRoundedSquare : public ::testing::TestWithParam<RoundedSquareCase> {};

TEST_P(SegmentExactRoundedSquare, FlatSidesBetweenRoundsStayPlanes) {
  const RoundedSquareCase& square = GetParam();
  const Mesh mesh = ProfilePrism(RoundedSquare(square.side, square.radius, square.steps));
  const ExactRun run = SegmentExact(mesh);
  int cylinders = 0, planes = 0;
  for (std::size_t r = 0; r < run.regions.regions.size(); ++r) {
    const RegionState& region = run.regions.regions[r];
    const auto faces = std::count(run.regions.face_labels.begin(), run.regions.face_labels.end(),
                                  static_cast<int>(r));
    if (region.type == SurfaceType::kCylinder) {
      ++cylinders;
      EXPECT_NEAR(std::get<Cylinder>(region.surface).radius, square.radius, 1e-6);
      EXPECT_EQ(faces, 2 * square.steps);
    } else {
      ++planes;
      EXPECT_EQ(region.type, SurfaceType::kPlane);
    }
  }
  EXPECT_EQ(cylinders, 4);
  EXPECT_EQ(planes, 6);  // four sides, two caps
}

INSTANTIATE_TEST_SUITE_P(Squares, SegmentExactRoundedSquare,
                         ::testing::Values(RoundedSquareCase{"slot_like", 7.5, 2.54, 9},
                                           RoundedSquareCase{"fine_rounds", 5.0, 2.0, 18},
                                           RoundedSquareCase{"coarse_rounds", 20.0, 2.0, 3},
                                           RoundedSquareCase{"small_rounds", 12.0, 1.0, 9}),
                         [](const auto& info) { return std::string(info.param.name); });

// A pentagonal prism's sides meet at 72 degrees: seven planes, no cylinder.
TEST(SegmentExactFacets, KeepsThePlanesOfAPentagonalPrism) {
  const Mesh mesh = ArcPrism(2.0, 5, 360.0);
  const ExactRun run = SegmentExact(mesh);
  ASSERT_EQ(run.regions.regions.size(), 7u);
  for (const RegionState& region : run.regions.regions) {
    EXPECT_EQ(region.type, SurfaceType::kPlane);
  }
}

// Asked to segment facet by facet (SegmentParams::exact_facets), a noisy
// mesh is refused by name: nearly every face is a plane of its own.
TEST(SegmentExactFacets, RefusesAMeshThatIsNotExact) {
  absl::StatusOr<GeneratedPart> part =
      GeneratePart("small_block", {.voxel_size = 1.0, .noise = 0.05});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<CurvatureField> field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  SegmentParams params;
  params.exact_facets = true;
  const absl::StatusOr<Segmentation> seg = Segment(part->mesh, *field, params);
  ASSERT_EQ(seg.status().code(), absl::StatusCode::kFailedPrecondition) << seg.status();
  EXPECT_NE(seg.status().message().find("\"" + part->mesh.name + "\" is not an exact tessellation"),
            std::string::npos)
      << seg.status();
}

// Dense meshes keep the curvature-seeded path: a noise-free generated part
// is exact, but few of its vertices are sharp. (abc_00007974_5.obj, the
// case this path is for, is in tests/core/pipeline/real_files_test.cc.)
TEST(IsCoarseExact, OnlyForCoarseExactMeshes) {
  absl::StatusOr<GeneratedPart> part = GeneratePart("small_block", {.noise = 0.0});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<CurvatureField> field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  const SegmentEstimates estimates = EstimateNoise(*field, MeanEdgeLength(part->mesh.tri), {});
  EXPECT_FALSE(IsCoarseExact(*field, estimates));
}

}  // namespace
}  // namespace meshseg::segment_internal
