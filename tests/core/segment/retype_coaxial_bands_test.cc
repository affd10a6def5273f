// RetypeCoaxialBands on stepped_shaft's chamfer as a sheet (sheet_context.h)
// with normal noise: the band beside its cylinder, typed torus or sphere.
#include "segment/retype_coaxial_bands.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
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

constexpr double kSigma = 0.01;
constexpr int kBand[] = {0};
// The chamfer for PlaceCoaxialBands: noise sigma 0.04, at which the rows
// of its neighbours (0.18 off the cone) are within th_dis, and a ripple of
// 2.25 sigma, for which the cone on the shaft's axis misses the band's
// interior by 0.33 sigma (stepped_shaft's chamfer at 0.15 h, seed 388:
// cone 0.31 sigma, sphere 0.31).
constexpr double kRowsInlierSigma = 0.04;
constexpr double kRippleSigmas = 2.25;

// Normal noise of kSigma along the normals (mt19937 draw `seed`).
void AddNoise(unsigned seed, Sheet* s) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, kSigma);
  for (std::size_t v = 0; v < s->u.size(); ++v) {
    s->c.graph.positions[v] += noise(random) * s->field.normal[v];
  }
}

// Label 0 on the rows from `first` to `last`, 1 below (the cylinder), 2
// above (the top).
std::vector<int> BandLabels(const Sheet& s, int first, int last) {
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) {
    labels[v] = s.u[v] < first ? 1 : (s.u[v] > last ? 2 : 0);
  }
  return labels;
}

// The chamfer with noise (draw `seed`): its band labelled 0 of type `band`,
// what lies below it 1 of type `below`, the top 2, a plane.
std::vector<RegionState> NoisyChamfer(unsigned seed, SurfaceType band, SurfaceType below, Sheet* s,
                                      std::vector<int>* labels) {
  testing::BuildChamfer(kSigma, 0.0, s);
  AddNoise(seed, s);
  *labels = BandLabels(*s, testing::kChamferConeStart, testing::kChamferConeEnd);
  return RegionsFromLabels(s->c, *labels, {band, below, SurfaceType::kPlane});
}

TEST(RetypeCoaxialBandsTest, TorusOnAChamferBesideItsShaftBecomesACone) {
  // A torus has no valid fit to a straight profile: the region keeps the
  // torus it was typed on, and the cone on the shaft's axis lowers E.
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions =
      NoisyChamfer(7, SurfaceType::kTorus, SurfaceType::kCylinder, &s, &labels);
  ASSERT_FALSE(FitType(s.c, SurfaceType::kTorus, regions[0].vertices).ok());
  // The torus it was typed on: a tube of radius 1 touching the band's middle
  // row (r 4.25, z 69.25), which the band's outer rows leave by over th_dis.
  const double inward = 1.0 / std::sqrt(2.0);
  regions[0].surface = Torus{.center = Eigen::Vector3d(0.0, 0.0, 69.25 - inward),
                             .axis_direction = Eigen::Vector3d::UnitZ(),
                             .major_radius = 4.25 - inward,
                             .minor_radius = 1.0};

  EXPECT_EQ(RetypeCoaxialBands(s.c, labels, &regions), std::vector<int>{0});
  ASSERT_EQ(regions[0].type, SurfaceType::kCone);
  const Cone& cone = std::get<Cone>(regions[0].surface);
  EXPECT_NEAR(cone.half_angle, std::numbers::pi / 4, 0.2 * std::numbers::pi / 180);
  // On the cylinder's axis, the z axis.
  EXPECT_GT(std::abs(cone.axis_direction.z()), std::cos(0.1 * std::numbers::pi / 180));
  EXPECT_NEAR(cone.apex.x(), 0.0, 0.01);
  EXPECT_NEAR(cone.apex.y(), 0.0, 0.01);
  EXPECT_EQ(regions[1].type, SurfaceType::kCylinder);
}

TEST(RetypeCoaxialBandsTest, SphereOnAChamferBecomesACone) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions =
      NoisyChamfer(8, SurfaceType::kSphere, SurfaceType::kCylinder, &s, &labels);
  EXPECT_EQ(RetypeCoaxialBands(s.c, labels, &regions), std::vector<int>{0});
  EXPECT_EQ(regions[0].type, SurfaceType::kCone);
  // Its axis is the shaft's: the label counts the apex along it and the
  // half angle.
  EXPECT_EQ(FreeParameters(regions[0]), kCoaxialConeParameters);
}

// The chamfer's band fitted as a free cone (6 parameters), and the cone on
// the shaft's axis fitted to its interior (BestCoaxialCone).
struct ConeBand {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions;
  Surface on_axis;
};

void BuildConeBand(unsigned seed, ConeBand* b) {
  b->regions = NoisyChamfer(seed, SurfaceType::kCone, SurfaceType::kCylinder, &b->s, &b->labels);
  const std::vector<int> interior =
      InteriorVertices(b->s.c, b->labels, kBand, b->regions[0].vertices);
  const std::optional<CoaxialFit> best =
      BestCoaxialCone(b->s.c, b->labels, b->regions, 0, interior);
  ASSERT_TRUE(best.has_value());
  b->on_axis = best->fit.surface;
}

TEST(SharedParametersTest, ConeOnItsShaftsAxisLowersEOnlyWithItsOwnParametersCounted) {
  // The free cone follows the noise with the 4 parameters of its axis, a
  // gain of about chi^2_4 / 2 in the data term; the label cost of those
  // parameters, (4 / 2f) ln (f n), is several times that on a band of 400
  // vertices. Priced as a free cone, the cone on the shaft's axis loses
  // the data and saves no label: E refuses it. Priced with the 2 parameters
  // its own vertices estimate (the axis is the shaft's, energy.h), E takes
  // it.
  for (const unsigned seed : {7u, 8u, 9u}) {
    ConeBand b;
    BuildConeBand(seed, &b);
    const RegionState free_cone = Reestimated(b.s.c, b.regions[0]);
    std::vector<RegionState> as_free = b.regions, as_shared = b.regions;
    as_free[0] = free_cone;
    const double e_free = TotalEnergy(b.s.c, b.labels, as_free);
    RegionState axis_free_count = free_cone;
    axis_free_count.surface = b.on_axis;
    as_free[0] = axis_free_count;
    EXPECT_GT(TotalEnergy(b.s.c, b.labels, as_free), e_free) << seed;
    as_shared[0] = CoaxialConeRegion(free_cone, b.on_axis);
    EXPECT_LT(TotalEnergy(b.s.c, b.labels, as_shared), e_free) << seed;
    // The two differ by the label of the 4 shared parameters.
    const double f = b.s.c.evidence_share;
    const double n = static_cast<double>(free_cone.vertices.size());
    EXPECT_NEAR(TotalEnergy(b.s.c, b.labels, as_free) - TotalEnergy(b.s.c, b.labels, as_shared),
                2.0 * std::log(f * n) / f, 1e-6)
        << seed;
    // Re-estimation keeps the shared axis: the free refit gains less than
    // the label it adds.
    const RegionState kept = Reestimated(b.s.c, as_shared[0]);
    EXPECT_EQ(kept.shared_parameters, as_shared[0].shared_parameters) << seed;
  }
}

TEST(SharedParametersTest, ReestimationFreesASharedSurfaceItsVerticesLeave) {
  // The cone on the shaft's axis moved 0.1 (10 sigma) along it: its
  // vertices pay far more than the label of the freed axis, and the
  // re-estimation refits it free (shared_parameters 0).
  ConeBand b;
  BuildConeBand(7, &b);
  Cone moved = std::get<Cone>(b.on_axis);
  moved.apex += 0.1 * moved.axis_direction;
  const RegionState shared = CoaxialConeRegion(b.regions[0], moved);
  const RegionState freed = Reestimated(b.s.c, shared);
  EXPECT_EQ(freed.shared_parameters, 0);
  EXPECT_EQ(FreeParameters(freed), ParameterCount(SurfaceType::kCone));
  EXPECT_LT(DataCost(b.s.c, freed.surface, freed.vertices),
            DataCost(b.s.c, shared.surface, shared.vertices));
}

TEST(RetypeCoaxialBandsTest, FilletBesideItsShaftStaysATorus) {
  // A quarter round of radius 1.5 from the cylinder to the top in place of
  // the chamfer: no cone on the shaft's axis comes near it.
  constexpr int kCylinderRows = 10, kRoundRows = 10, kTopRows = 10;
  Sheet s;
  BuildSheet(
      [](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row <= kCylinderRows) {
          return std::pair{Eigen::Vector3d(5.0 * radial + (66.0 + 0.25 * row) * z), radial};
        }
        if (row <= kCylinderRows + kRoundRows) {
          const double t = (row - kCylinderRows) / kRoundRows * std::numbers::pi / 2;
          const Eigen::Vector3d n = std::cos(t) * radial + std::sin(t) * z;
          return std::pair{Eigen::Vector3d(3.5 * radial + 68.5 * z + 1.5 * n), n};
        }
        return std::pair{
            Eigen::Vector3d((3.5 - 0.25 * (row - kCylinderRows - kRoundRows)) * radial + 70.0 * z),
            z};
      },
      0.0, kCylinderRows + kRoundRows + kTopRows, kCylinderRows + kRoundRows + kTopRows + 1, 0.0,
      1.5 * std::numbers::pi, 48, /*distance=*/5.0 * kSigma, /*angle_deg=*/10.0, &s);
  s.c.noise_sigma = kSigma;
  AddNoise(7, &s);
  const std::vector<int> labels = BandLabels(s, kCylinderRows + 1, kCylinderRows + kRoundRows - 1);
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kTorus, SurfaceType::kCylinder, SurfaceType::kPlane});
  EXPECT_TRUE(RetypeCoaxialBands(s.c, labels, &regions).empty());
  EXPECT_EQ(regions[0].type, SurfaceType::kTorus);
}

TEST(SphereOnConeAxisTest, FitsASphereZoneWithItsCentreOnTheAxis) {
  // A zone of a sphere of radius 12 centred at z = -3 on the z axis, from
  // 30 to 60 degrees off the pole, with noise; the axis given by a cone on
  // it. The centre is found on the axis and the radius within the noise,
  // and the label counts 2 parameters.
  constexpr double kRadius = 12.0, kCenterZ = -3.0;
  Sheet s;
  BuildSheet(
      [&](double row, double phi) {
        const double t = (30.0 + 1.5 * row) * std::numbers::pi / 180.0;
        const Eigen::Vector3d n(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi),
                                std::cos(t));
        return std::pair{Eigen::Vector3d(kCenterZ * Eigen::Vector3d::UnitZ() + kRadius * n), n};
      },
      0.0, 20.0, 21, 0.0, 1.5 * std::numbers::pi, 48, /*distance=*/5.0 * kSigma,
      /*angle_deg=*/10.0, &s);
  s.c.noise_sigma = kSigma;
  AddNoise(7, &s);
  const std::vector<int> labels(s.u.size(), 0);
  const std::vector<RegionState> regions = RegionsFromLabels(s.c, labels, {SurfaceType::kSphere});
  const Cone axis{.apex = Eigen::Vector3d(0.0, 0.0, 5.0),
                  .axis_direction = Eigen::Vector3d::UnitZ(),
                  .half_angle = 0.5};
  const std::optional<RegionState> on_axis = SphereOnConeAxis(s.c, regions[0], axis);
  ASSERT_TRUE(on_axis.has_value());
  const Sphere& sphere = std::get<Sphere>(on_axis->surface);
  EXPECT_NEAR(sphere.center.x(), 0.0, 1e-12);
  EXPECT_NEAR(sphere.center.y(), 0.0, 1e-12);
  EXPECT_NEAR(sphere.center.z(), kCenterZ, 0.01);
  EXPECT_NEAR(sphere.radius, kRadius, 0.01);
  EXPECT_EQ(FreeParameters(*on_axis), 2);
  // Not for another type.
  RegionState torus = regions[0];
  torus.type = SurfaceType::kTorus;
  EXPECT_FALSE(SphereOnConeAxis(s.c, torus, axis).has_value());
}

TEST(RetypeCoaxialBandsTest, BandWithoutAnAxialNeighbourStays) {
  // The chamfer's band with a plane below it in place of the cylinder.
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions =
      NoisyChamfer(7, SurfaceType::kTorus, SurfaceType::kPlane, &s, &labels);
  EXPECT_TRUE(RetypeCoaxialBands(s.c, labels, &regions).empty());
  EXPECT_EQ(regions[0].type, SurfaceType::kTorus);
}

TEST(BestCoaxialConeTest, ConeBandOnItsShaftsAxisScoresBelowItsFreeCone) {
  // The chamfer's band typed cone: the cone on the cylinder's axis meets it
  // at the noise with 4 parameters fewer than a free cone, so it scores
  // below the free cone's fit (the score RetypeByInterior holds a cone
  // region to); the plane above has no axis.
  Sheet s;
  std::vector<int> labels;
  const std::vector<RegionState> regions =
      NoisyChamfer(7, SurfaceType::kCone, SurfaceType::kCylinder, &s, &labels);
  const std::vector<int> interior = InteriorVertices(s.c, labels, kBand, regions[0].vertices);
  ASSERT_GE(interior.size(), kMinInteriorVertices);
  const std::optional<CoaxialFit> best = BestCoaxialCone(s.c, labels, regions, 0, interior);
  ASSERT_TRUE(best.has_value());
  EXPECT_LE(std::sqrt(best->mean_square), 1.5 * kSigma);
  const Cone& cone = std::get<Cone>(best->fit.surface);
  EXPECT_NEAR(cone.half_angle, std::numbers::pi / 4, 0.2 * std::numbers::pi / 180);
  EXPECT_NEAR(cone.apex.x(), 0.0, 0.01);
  EXPECT_NEAR(cone.apex.y(), 0.0, 0.01);
  EXPECT_LT(best->score, ScoreType(s.c, SurfaceType::kCone, interior).score);
  // With a plane below in place of the cylinder there is no axis to share.
  Sheet flat;
  const std::vector<RegionState> beside_planes =
      NoisyChamfer(7, SurfaceType::kCone, SurfaceType::kPlane, &flat, &labels);
  EXPECT_FALSE(BestCoaxialCone(flat.c, labels, beside_planes, 0,
                               InteriorVertices(flat.c, labels, kBand, beside_planes[0].vertices))
                   .has_value());
}


// The E of `regions` on `labels` with region 0 made `model`, re-estimated,
// and the expansion made (what PlaceCoaxialBands prices a model at).
double PricedWithExpansion(const SegmentContext& c, std::vector<int> labels,
                           std::vector<RegionState> regions, const RegionState& model) {
  regions[0] = Reestimated(c, model);
  EXPECT_TRUE(ExpandRegions(c, &labels, &regions).ok());
  return TotalEnergy(c, labels, regions);
}

TEST(PlaceCoaxialBandsTest, SphereOnARippledChamferBecomesItsConeWithTheExpansion) {
  // The chamfer's band with a ripple (a stand-in for a mesh's error) took
  // one row of the cylinder and one of the top. On its interior the cone
  // on the shaft's axis misses the noise (not at it), and on the labels as
  // they stand the rows side with the sphere: RetypeCoaxialBands keeps it.
  // Each model placed by its expansion, the cone gives the rows back and
  // lowers E below the sphere on the same axis.
  Sheet s;
  constexpr double sigma = kRowsInlierSigma;
  testing::BuildChamfer(sigma, /*ripple=*/kRippleSigmas * sigma, &s);
  std::vector<int> labels =
      BandLabels(s, testing::kChamferConeStart - 1, testing::kChamferConeEnd + 1);
  std::vector<RegionState> regions = RegionsFromLabels(
      s.c, labels, {SurfaceType::kSphere, SurfaceType::kCylinder, SurfaceType::kPlane});
  const std::vector<int> interior =
      Sample(InteriorVertices(s.c, labels, kBand, regions[0].vertices));
  const std::optional<CoaxialFit> cone = BestCoaxialCone(s.c, labels, regions, 0, interior);
  ASSERT_TRUE(cone.has_value());
  const double cone_error = ModelErrorOfMeanSquare(s.c, cone->mean_square);
  ASSERT_GT(cone_error, kMinModelError * sigma);
  ASSERT_LE(cone_error, kScoredNearError * sigma);
  {
    std::vector<RegionState> unplaced = regions;
    ASSERT_TRUE(RetypeCoaxialBands(s.c, labels, &unplaced).empty());
  }
  const double before = TotalEnergy(s.c, labels, regions);

  const absl::StatusOr<std::vector<int>> moved = PlaceCoaxialBands(s.c, &labels, &regions);
  ASSERT_TRUE(moved.ok()) << moved.status();
  EXPECT_EQ(*moved, std::vector<int>{0});
  ASSERT_EQ(regions[0].type, SurfaceType::kCone);
  const Cone& placed = std::get<Cone>(regions[0].surface);
  EXPECT_NEAR(placed.half_angle, std::numbers::pi / 4, 0.5 * std::numbers::pi / 180);
  EXPECT_NEAR(placed.apex.x(), 0.0, 0.01);
  EXPECT_NEAR(placed.apex.y(), 0.0, 0.01);
  EXPECT_LT(TotalEnergy(s.c, labels, regions), before);
  // The rows of the cylinder and the top went back to them.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] < testing::kChamferConeStart - 0.5 || s.u[v] > testing::kChamferConeEnd + 0.5) {
      EXPECT_NE(labels[v], 0) << v;
    }
  }
}

// A shaft of radius 5 (rows 0.25 apart up to z 68.5) under a shallow dome:
// a sphere of radius kDomeRadius centred on the shaft's axis, from the
// shaft's rim in to radius 1 (rows 0.25 apart in radius), three quarters
// of a turn: its cone on the axis misses it by 0.05 sigma at noise sigma
// kDomeSigma (none added), th_dis 5 sigma. Labelled 0 on the dome, 1 on
// the shaft.
constexpr int kShaftRows = 10, kDomeRows = 16;
constexpr double kDomeRadius = 250.0, kDomeSigma = 0.05;

void BuildDomeOnShaft(Sheet* s, std::vector<int>* labels) {
  const double center_z = 68.5 - std::sqrt(kDomeRadius * kDomeRadius - 25.0);
  BuildSheet(
      [&](double row, double phi) {
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
        if (row <= kShaftRows) {
          return std::pair{Eigen::Vector3d(5.0 * radial + (66.0 + 0.25 * row) * z), radial};
        }
        const double r = 5.0 - 0.25 * (row - kShaftRows);
        const Eigen::Vector3d p =
            r * radial + (center_z + std::sqrt(kDomeRadius * kDomeRadius - r * r)) * z;
        return std::pair{p, Eigen::Vector3d((p - center_z * z) / kDomeRadius)};
      },
      0.0, kShaftRows + kDomeRows, kShaftRows + kDomeRows + 1, 0.0, 1.5 * std::numbers::pi, 48,
      /*distance=*/5.0 * kDomeSigma, /*angle_deg=*/10.0, s);
  s->c.noise_sigma = kDomeSigma;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) (*labels)[v] = s->u[v] < kShaftRows ? 1 : 0;
}

TEST(PlaceCoaxialBandsTest, SphereCentredOnItsShaftsAxisStaysASphere) {
  // The dome's cone on the shaft's axis meets it near the noise, and placed
  // by its expansion it lowers E below the free sphere, which pays for the
  // 2 parameters of its centre's offset from the axis: weighed against it
  // alone, the dome would become a cone. The sphere on the axis estimates
  // no more than the cone and fits the dome: it stays a sphere, on the axis.
  Sheet s;
  std::vector<int> labels;
  BuildDomeOnShaft(&s, &labels);
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kSphere, SurfaceType::kCylinder});
  const std::vector<int> interior =
      Sample(InteriorVertices(s.c, labels, kBand, regions[0].vertices));
  const std::optional<CoaxialFit> cone = BestCoaxialCone(s.c, labels, regions, 0, interior);
  ASSERT_TRUE(cone.has_value());
  ASSERT_LE(ModelErrorOfMeanSquare(s.c, cone->mean_square), kScoredNearError * kDomeSigma);
  ASSERT_LT(PricedWithExpansion(s.c, labels, regions,
                                CoaxialConeRegion(regions[0], cone->fit.surface)),
            TotalEnergy(s.c, labels, regions));

  const absl::StatusOr<std::vector<int>> moved = PlaceCoaxialBands(s.c, &labels, &regions);
  ASSERT_TRUE(moved.ok()) << moved.status();
  ASSERT_EQ(regions[0].type, SurfaceType::kSphere);
  const Sphere& sphere = std::get<Sphere>(regions[0].surface);
  EXPECT_NEAR(sphere.center.x(), 0.0, 0.01);
  EXPECT_NEAR(sphere.center.y(), 0.0, 0.01);
  EXPECT_NEAR(sphere.radius, kDomeRadius, 0.05 * kDomeRadius);
}

}  // namespace
}  // namespace meshseg::segment_internal
