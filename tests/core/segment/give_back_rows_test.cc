// GiveBackRows on sheets: a countersink (a 45-degree cone band) whose
// region took rows of the flat face around it, and a boss top whose region
// took rows of the boss side.
#include "segment/give_back_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "segment/absorb_leftovers.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::RegionsFromLabels;
using testing::Sheet;

constexpr double kSigma = 0.001;
constexpr double kStep = 0.25;  // between rows
constexpr int kFlatRows = 13;   // the face: radius 8 in to 5
constexpr int kConeRows = 12;   // the countersink: 2.75 down its side
constexpr int kTakenRows = 5;   // face rows the countersink's region took
constexpr int kAround = 64;

// A flat face (z = 0) from radius 8 in to 5 and, inside its rim, a cone
// band going down at 45 degrees: row u at radius 8 - u kStep on the face.
void BuildCountersink(Sheet* s) {
  BuildSheet(
      [](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row < kFlatRows) return std::pair{Eigen::Vector3d((8.0 - kStep * row) * radial), z};
        const double t = kStep * (row - (kFlatRows - 1)) / std::numbers::sqrt2;
        return std::pair{Eigen::Vector3d((5.0 - t) * radial - t * z),
                         Eigen::Vector3d((z - radial) / std::numbers::sqrt2)};
      },
      0.0, kFlatRows + kConeRows - 1, kFlatRows + kConeRows, 0.0,
      2.0 * std::numbers::pi * (kAround - 1) / kAround, kAround, /*distance=*/5.0 * kSigma,
      /*angle_deg=*/10.0, s);
  s->c.noise_sigma = kSigma;
}

// Label 0 (the face) on rows before `first`, 1 (the countersink) on the rest.
std::vector<int> LabelsFrom(const Sheet& s, int first) {
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.u[v] < first - 0.5 ? 0 : 1;
  return labels;
}

TEST(GiveBackRowsTest, CountersinkGivesTheFaceItsRowsBack) {
  // As a torus the region bends from the face into the band and meets
  // both within the tolerances, but not at the noise.
  Sheet s;
  BuildCountersink(&s);
  std::vector<int> labels = LabelsFrom(s, kFlatRows - kTakenRows);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus});

  EXPECT_EQ(GiveBackRows(s.c, &labels, &regions), std::vector<int>{1});
  EXPECT_EQ(regions[1].type, SurfaceType::kCone);
  // The face's rows are the face's again, the band's stay.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], s.u[v] < kFlatRows - 0.5 ? 0 : 1) << "row " << s.u[v];
  }
}

TEST(GiveBackRowsTest, AFragmentOfTheRegionsSurfaceTakesNothing) {
  // A fragment of 32 vertices (under kMinRegionVertices) inside the band,
  // typed cone, meets the whole band; were it asked, it would take all of
  // the region's band rows and leave no rest (test_piece at 0.15 h, seed
  // 171: a sphere piece of the countersink).
  Sheet s;
  BuildCountersink(&s);
  std::vector<int> labels = LabelsFrom(s, kFlatRows - kTakenRows);
  const auto in_fragment = [&](std::size_t v) {
    return s.u[v] > kFlatRows + 3.5 && s.v[v] < 3.5 * 2.0 * std::numbers::pi / kAround;
  };
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (in_fragment(v)) labels[v] = 2;
  }
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus, SurfaceType::kCone});
  ASSERT_LT(regions[2].vertices.size(), kMinRegionVertices);

  EXPECT_EQ(GiveBackRows(s.c, &labels, &regions), std::vector<int>{1});
  EXPECT_EQ(regions[1].type, SurfaceType::kCone);
  for (std::size_t v = 0; v < labels.size(); ++v) {
    EXPECT_EQ(labels[v], in_fragment(v) ? 2 : s.u[v] < kFlatRows - 0.5 ? 0 : 1) << "row " << s.u[v];
  }
}

TEST(GiveBackRowsTest, ARegionItsTypeFitsKeepsItsVertices) {
  // The countersink's region holds the band and nothing else; the face
  // next to it could take its rim row (within the distance tolerance) but
  // is not asked to.
  Sheet s;
  BuildCountersink(&s);
  std::vector<int> labels = LabelsFrom(s, kFlatRows);
  const std::vector<int> before = labels;
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kCone});
  EXPECT_TRUE(GiveBackRows(s.c, &labels, &regions).empty());
  EXPECT_EQ(labels, before);
}

// test_piece's boss (sheet_context.h): the top from radius 2 out to 5 and
// the boss side below its rim.
constexpr int kTopRows = 13;
constexpr int kSideRows = 12;
constexpr int kSideRowsTaken = 2;  // side rows the top's region took

TEST(GiveBackRowsTest, TopBentOverTheRimGivesTheRowsBackAndTurnsPlane) {
  // The top's region, typed sphere, took two rows of the side, and its
  // sphere bends to meet them; a flatter sphere meets the top's interior,
  // so only the surface, not the type, tells that the rows bent it.
  Sheet s;
  testing::BuildBoss(kTopRows, kSideRows, kSigma, &s);
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) {
    labels[v] = s.u[v] < kTopRows + kSideRowsTaken - 0.5 ? 0 : 1;
  }
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kSphere, SurfaceType::kCone});

  EXPECT_EQ(GiveBackRows(s.c, &labels, &regions), std::vector<int>{0});
  EXPECT_EQ(regions[0].type, SurfaceType::kPlane);
  // The side's rows are the side's again, the top's stay (the rim row lies
  // on both).
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (std::abs(s.u[v] - (kTopRows - 1)) < 0.5) continue;
    EXPECT_EQ(labels[v], s.u[v] < kTopRows - 0.5 ? 0 : 1) << "row " << s.u[v];
  }
}

TEST(GiveBackRowsTest, NothingHappensWithoutANoiseScale) {
  Sheet s;
  BuildCountersink(&s);
  s.c.noise_sigma = 0.0;
  std::vector<int> labels = LabelsFrom(s, kFlatRows - kTakenRows);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kTorus});
  EXPECT_TRUE(GiveBackRows(s.c, &labels, &regions).empty());
}

}  // namespace
}  // namespace meshseg::segment_internal
