// The surface a curved region's interior proposes (ProposeInteriorSurfaces),
// and the move E makes of it with the expansion (RefitToInterior), on
// plate_boss's boss edge as a sheet: a flat top out to radius 8, a convex
// round of radius 2 (the torus of major radius 8 and tube radius 2) and the
// boss's cylinder of radius 10 below it.
#include "segment/refit_to_interior.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
#include "segment/retype_by_interior.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::RegionsFromLabels;
using testing::Sheet;

// Rows 0.5 apart (plate_boss's voxel h) on the top and the cylinder, and
// kRoundRows rows over the round's quarter turn (0.45 apart); noise 0.15 h.
constexpr double kStep = 0.5;
constexpr double kMajor = 8.0, kTube = 2.0;
constexpr int kTopRows = 8, kRoundRows = 7, kSideRows = 8;
constexpr int kRoundStart = kTopRows - 1;  // the row where the round meets the top
constexpr int kRoundEnd = kRoundStart + kRoundRows;
constexpr int kAround = 120;
constexpr double kSigma = 0.15 * kStep;

// The boss edge, a full turn but for one step (the sheet has a seam), with
// noise of kSigma along the normals (mt19937 draw `draw`); th_dis 3.5
// sigma, th_nm 10 degrees.
void BuildBossEdge(unsigned draw, Sheet* s) {
  constexpr double kPi = std::numbers::pi;
  BuildSheet(
      [](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row <= kRoundStart) {
          const double radius = kMajor - kStep * (kRoundStart - row);
          return std::pair{Eigen::Vector3d(radius * radial + (18.0 + kTube) * z), z};
        }
        if (row <= kRoundEnd) {
          const double t = (row - kRoundStart) / kRoundRows * kPi / 2.0;
          const Eigen::Vector3d n = std::sin(t) * radial + std::cos(t) * z;
          return std::pair{Eigen::Vector3d(kMajor * radial + 18.0 * z + kTube * n), n};
        }
        const double depth = kStep * (row - kRoundEnd);
        return std::pair{Eigen::Vector3d((kMajor + kTube) * radial + (18.0 - depth) * z), radial};
      },
      0.0, kRoundEnd + kSideRows, kRoundEnd + kSideRows + 1, 0.0, 2.0 * kPi * (kAround - 1) / kAround,
      kAround, /*distance=*/3.5 * kSigma, /*angle_deg=*/10.0, s);
  s->c.noise_sigma = kSigma;
  std::mt19937 random(draw);
  std::normal_distribution<double> noise(0.0, kSigma);
  for (std::size_t v = 0; v < s->u.size(); ++v) {
    s->c.graph.positions[v] += noise(random) * s->field.normal[v];
  }
}

// The round region (0) from row `first` to the round's last row, the top
// (1) before it and the cylinder (2) after; each fitted to its vertices.
std::vector<int> EdgeLabels(const Sheet& s, int first) {
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) {
    const double row = s.u[v];
    labels[v] = row < first - 0.5 ? 1 : (row > kRoundEnd + 0.5 ? 2 : 0);
  }
  return labels;
}

const std::vector<SurfaceType> kTypes = {SurfaceType::kTorus, SurfaceType::kPlane,
                                         SurfaceType::kCylinder};

// The model error of `surface` over `vertices`, in sigmas.
double SigmasOff(const SegmentContext& c, const Surface& surface,
                 const std::vector<int>& vertices) {
  double sum = 0.0;
  for (const int v : vertices) {
    const double d = SignedDistance(surface, c.position(v), c.curvature->smooth_normal[v]);
    sum += d * d;
  }
  return ModelErrorOfMeanSquare(c, sum / vertices.size()) / c.noise_sigma;
}

// The vertices of region 0 on the top short of the row where it meets the
// round (that row lies within the noise of both surfaces).
int TopVerticesInTheRound(const Sheet& s, const std::vector<int>& labels) {
  int count = 0;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    count += s.u[v] < kRoundStart - 1.5 && labels[v] == 0;
  }
  return count;
}

TEST(RefitToInteriorTest, ARoundHoldingRowsOfTheTopTakesItsInteriorsSurface) {
  // The round grew over four rows of the top, and the expansion with
  // re-estimation settled with rows of the top kept: the round's torus,
  // refitted to them, bends its tube to hold them (R 7.76 r 2.39), so they
  // cost no more on it than on the plane. Its interior misses that torus
  // beyond the noise, and the torus fitted to the interior alone meets it.
  Sheet s;
  BuildBossEdge(/*draw=*/40, &s);
  std::vector<int> labels = EdgeLabels(s, kRoundStart - 4);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, kTypes);
  ASSERT_TRUE(ExpandRegions(s.c, &labels, &regions).ok());
  {
    // A fixed point of the expansion: it moves nothing more.
    std::vector<int> again_labels = labels;
    std::vector<RegionState> again = regions;
    const absl::StatusOr<int> moved = ExpandRegions(s.c, &again_labels, &again);
    ASSERT_TRUE(moved.ok());
    ASSERT_EQ(*moved, 0);
  }
  const int top_before = TopVerticesInTheRound(s, labels);
  ASSERT_GT(top_before, 0);
  const double major_before = std::get<Torus>(regions[0].surface).major_radius;
  const double minor_before = std::get<Torus>(regions[0].surface).minor_radius;
  const int round[] = {0};
  const std::vector<int> interior = InteriorVertices(s.c, labels, round, regions[0].vertices);
  ASSERT_GT(SigmasOff(s.c, regions[0].surface, interior), kMinModelError);
  ASSERT_TRUE(FitsAtNoise(s.c, FitType(s.c, SurfaceType::kTorus, interior)));
  // The type is right: the interior proposes no other (retype_by_interior.h).
  EXPECT_TRUE(ProposeInteriorTypes(s.c, labels, regions).empty());

  const std::vector<InteriorSurface> proposed = ProposeInteriorSurfaces(s.c, labels, regions);
  ASSERT_FALSE(proposed.empty());
  EXPECT_EQ(proposed[0].id, 0);

  const double before = TotalEnergy(s.c, labels, regions);
  const absl::StatusOr<std::vector<int>> refitted = RefitToInterior(s.c, &labels, &regions);
  ASSERT_TRUE(refitted.ok()) << refitted.status();
  ASSERT_FALSE(refitted->empty());
  EXPECT_EQ(refitted->front(), 0);
  EXPECT_LT(TotalEnergy(s.c, labels, regions), before);
  // The torus within 0.5 h of its radii (the part tests' bound at 0.15 h
  // noise) and nearer them than before; rows of the top gone back to it.
  ASSERT_EQ(regions[0].type, SurfaceType::kTorus);
  const Torus& torus = std::get<Torus>(regions[0].surface);
  EXPECT_NEAR(torus.major_radius, kMajor, 0.25);
  EXPECT_NEAR(torus.minor_radius, kTube, 0.25);
  EXPECT_LT(std::abs(torus.major_radius - kMajor), std::abs(major_before - kMajor));
  EXPECT_LT(std::abs(torus.minor_radius - kTube), std::abs(minor_before - kTube));
  EXPECT_LT(TopVerticesInTheRound(s, labels), top_before);
}

TEST(RefitToInteriorTest, ARoundOnItsOwnRowsIsNotMoved) {
  // Labelled as it is, the round's torus meets its interior at the noise:
  // nothing is proposed, labels and surfaces stay.
  Sheet s;
  BuildBossEdge(/*draw=*/3, &s);
  std::vector<int> labels = EdgeLabels(s, kRoundStart);
  std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, kTypes);
  EXPECT_TRUE(ProposeInteriorSurfaces(s.c, labels, regions).empty());
  const std::vector<int> labels_before = labels;
  const absl::StatusOr<std::vector<int>> refitted = RefitToInterior(s.c, &labels, &regions);
  ASSERT_TRUE(refitted.ok()) << refitted.status();
  EXPECT_TRUE(refitted->empty());
  EXPECT_EQ(labels, labels_before);
}

TEST(RefitToInteriorTest, ARegionWhoseTypeMissesItsInteriorIsLeftToTheRetypes) {
  // The round over the same rows typed a cylinder: no cylinder meets its
  // interior at the noise, so no cylinder is proposed (the type is the
  // retypes' to change, retype_by_interior.h).
  Sheet s;
  BuildBossEdge(/*draw=*/3, &s);
  const std::vector<int> labels = EdgeLabels(s, kRoundStart - 2);
  const std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kCylinder, SurfaceType::kPlane, SurfaceType::kCylinder});
  ASSERT_TRUE(TypeMissesInterior(s.c, labels, 0, regions[0]));
  EXPECT_TRUE(ProposeInteriorSurfaces(s.c, labels, regions).empty());
}


}  // namespace
}  // namespace meshseg::segment_internal
