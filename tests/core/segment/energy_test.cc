// The segmentation energy on generated parts: the true labeling, each
// primitive a region of its true type, costs less than the labelings one
// wrong decision makes of it (a surface in two regions, two surfaces in
// one, a region of the wrong type), at noise 0, 0.05 h and 0.15 h; and the
// priced moves change E by what they say.
#include "segment/energy.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "segment/absorb_leftovers.h"
#include "segment/decide_type.h"
#include "segment/estimate_noise.h"
#include "segment/facet_mesh.h"
#include "cylinder_band.h"
#include "sheet_context.h"
#include "true_labels.h"

namespace meshseg::segment_internal {
namespace {

// Relative agreement of a priced move with the change of TotalEnergy (sums
// of many terms in a different order).
constexpr double kRelative = 1e-9;

// `name` at `noise` h (draw 7; voxel size `voxel`, 0 for the part's own)
// with the true labels, each region fitted with its true type for least
// energy.
void BuildTrue(const std::string& name, double noise, Labeled* t, double voxel = 0.0) {
  BuildTrueLabels(name, noise, voxel, t);
  if (::testing::Test::HasFatalFailure()) return;
  for (RegionState& r : t->regions) {
    if (r.vertices.empty()) continue;
    const std::optional<Surface> fit = FitForEnergy(t->c, r.type, r.vertices);
    ASSERT_TRUE(fit.has_value()) << SurfaceTypeName(r.type);
    r.surface = *fit;
  }
}

// Pairs of primitives a mesh edge joins, each with kMinRegionVertices.
std::set<std::pair<int, int>> AdjacentPairs(const Labeled& t) {
  std::set<std::pair<int, int>> pairs;
  for (int v = 0; v < t.c.vertex_count(); ++v) {
    for (const int u : t.c.graph.Neighbors(v)) {
      const int a = t.labels[v];
      const int b = t.labels[u];
      if (a < 0 || b < 0 || a >= b) continue;
      if (t.regions[a].vertices.size() < kMinRegionVertices ||
          t.regions[b].vertices.size() < kMinRegionVertices) {
        continue;
      }
      pairs.insert({a, b});
    }
  }
  return pairs;
}

// test_piece at the voxel size of the segment tests (1.0; its own is 0.6).
double VoxelOf(const std::string& name) { return name == "test_piece" ? 1.0 : 0.0; }

class EnergyOnParts : public ::testing::TestWithParam<std::tuple<std::string, double>> {
 protected:
  void SetUp() override {
    const auto& [name, noise] = GetParam();
    BuildTrue(name, noise, &t_, VoxelOf(name));
    true_energy_ = TotalEnergy(t_.c, t_.labels, t_.regions);
  }
  Labeled t_;
  double true_energy_ = 0.0;
};

// The largest primitive cut in two across its widest extent, each half
// refitted with its type, costs more, and merging the halves back is priced
// as the difference.
TEST_P(EnergyOnParts, OneSurfaceInTwoRegionsCostsMore) {
  int largest = 0;
  for (int r = 0; r < static_cast<int>(t_.regions.size()); ++r) {
    if (t_.regions[r].vertices.size() > t_.regions[largest].vertices.size()) largest = r;
  }
  const std::vector<int>& vertices = t_.regions[largest].vertices;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (const int v : vertices) {
    lo = lo.cwiseMin(t_.c.position(v));
    hi = hi.cwiseMax(t_.c.position(v));
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const double middle = 0.5 * (lo[axis] + hi[axis]);
  std::vector<int> labels = t_.labels;
  std::vector<RegionState> regions = t_.regions;
  const int half = static_cast<int>(regions.size());
  regions.push_back({.type = regions[largest].type, .surface = regions[largest].surface, .vertices = {}});
  for (const int v : vertices) {
    if (t_.c.position(v)[axis] > middle) labels[v] = half;
  }
  RebuildVertexLists(labels, &regions);
  for (const int r : {largest, half}) {
    ASSERT_GE(regions[r].vertices.size(), kMinRegionVertices);
    const std::optional<Surface> fit = FitForEnergy(t_.c, regions[r].type, regions[r].vertices);
    ASSERT_TRUE(fit.has_value());
    regions[r].surface = *fit;
  }
  const double split = TotalEnergy(t_.c, labels, regions);
  EXPECT_GT(split, true_energy_) << t_.part.primitives[largest].name;

  const SurfaceType type[] = {regions[largest].type};
  const std::optional<Move> merge = MergeDelta(t_.c, labels, regions, largest, half, type);
  ASSERT_TRUE(merge.has_value());
  EXPECT_LT(merge->delta, 0.0);
  // Merged with that move's surface, E is what the move said.
  regions[largest].surface = merge->surface;
  regions[half].alive = false;
  for (const int v : vertices) labels[v] = largest;
  RebuildVertexLists(labels, &regions);
  const double merged = TotalEnergy(t_.c, labels, regions);
  EXPECT_NEAR(merged - split, merge->delta, kRelative * std::abs(split));
}

// Two different primitives across any edge, merged into the surface of any
// type that costs least on both, cost more than the two apart.
TEST_P(EnergyOnParts, TwoSurfacesInOneRegionCostMore) {
  const std::set<std::pair<int, int>> pairs = AdjacentPairs(t_);
  ASSERT_FALSE(pairs.empty());
  for (const auto& [a, b] : pairs) {
    const std::vector<SurfaceType> types = MergeTypes(t_.regions[a].type, t_.regions[b].type);
    const std::optional<Move> merge = MergeDelta(t_.c, t_.labels, t_.regions, a, b, types);
    if (!merge) continue;  // no type fits both at all
    EXPECT_GT(merge->delta, 0.0) << t_.part.primitives[a].name << " + "
                                 << t_.part.primitives[b].name << " as "
                                 << SurfaceTypeName(merge->type);
  }
}

// Every primitive refitted as any other analytic type costs more, and the
// move is priced as the change of E.
TEST_P(EnergyOnParts, WrongTypeCostsMore) {
  constexpr SurfaceType kTypes[] = {SurfaceType::kPlane, SurfaceType::kCylinder,
                                    SurfaceType::kSphere, SurfaceType::kCone, SurfaceType::kTorus};
  for (int r = 0; r < static_cast<int>(t_.regions.size()); ++r) {
    const RegionState& region = t_.regions[r];
    if (region.vertices.size() < kMinRegionVertices) continue;
    for (const SurfaceType type : kTypes) {
      if (type == region.type) continue;
      const std::optional<Move> retype = RetypeDelta(t_.c, region, type);
      if (!retype) continue;
      EXPECT_GT(retype->delta, 0.0) << t_.part.primitives[r].name << " as "
                                    << SurfaceTypeName(type);
      std::vector<RegionState> regions = t_.regions;
      regions[r].type = type;
      regions[r].surface = retype->surface;
      const double retyped = TotalEnergy(t_.c, t_.labels, regions);
      EXPECT_NEAR(retyped - true_energy_, retype->delta, kRelative * std::abs(true_energy_));
    }
  }
}

// Dropping a true region, its vertices given to its neighbours' surfaces,
// costs more, by what DropDelta says.
TEST_P(EnergyOnParts, DroppingARegionCostsMore) {
  for (int r = 0; r < static_cast<int>(t_.regions.size()); ++r) {
    const RegionState& region = t_.regions[r];
    if (region.vertices.size() < kMinRegionVertices) continue;
    const double delta = DropDelta(t_.c, t_.labels, t_.regions, r).delta;
    EXPECT_GT(delta, 0.0) << t_.part.primitives[r].name;
  }
}

INSTANTIATE_TEST_SUITE_P(Parts, EnergyOnParts,
                         ::testing::Combine(::testing::Values("rounded_prism", "stepped_shaft",
                                                              "plate_boss", "test_piece"),
                                            ::testing::Values(0.0, 0.05, 0.15)),
                         [](const auto& info) {
                           const double noise = std::get<1>(info.param);
                           return std::get<0>(info.param) +
                                  (noise == 0.0 ? "_noise_0" : noise < 0.1 ? "_low" : "_high");
                         });

// DropDelta matches the change of TotalEnergy when the move is made: the
// vertices relabelled as it says, its takers refitted as it says.
TEST(EnergyDrop, DeltaIsTheChangeOfTheTotal) {
  Labeled t;
  BuildTrue("rounded_prism", 0.05, &t);
  int smallest = -1;
  for (int r = 0; r < static_cast<int>(t.regions.size()); ++r) {
    if (t.regions[r].vertices.size() < kMinRegionVertices) continue;
    if (smallest < 0 || t.regions[r].vertices.size() < t.regions[smallest].vertices.size()) {
      smallest = r;
    }
  }
  ASSERT_GE(smallest, 0);
  const double before = TotalEnergy(t.c, t.labels, t.regions);
  const DropMove move = DropDelta(t.c, t.labels, t.regions, smallest);
  ASSERT_FALSE(move.takers.empty());
  std::vector<int> labels = t.labels;
  for (std::size_t k = 0; k < t.regions[smallest].vertices.size(); ++k) {
    labels[t.regions[smallest].vertices[k]] = move.next[k];
  }
  std::vector<RegionState> regions = t.regions;
  for (std::size_t k = 0; k < move.takers.size(); ++k) {
    regions[move.takers[k]].surface = move.surfaces[k];
  }
  regions[smallest].alive = false;
  RebuildVertexLists(labels, &regions);
  const double after = TotalEnergy(t.c, labels, regions);
  EXPECT_NEAR(after - before, move.delta, kRelative * std::abs(before));
}

// A merge keeps either member's own type (a cone in two pieces, one read as
// a cylinder, is joined as the cone) but adds no generalisation neither
// member has (two cylinders do not become a cone or a torus).
TEST(MergeTypes, EitherMembersOwnTypeButNoNewGeneralisation) {
  auto has = [](const std::vector<SurfaceType>& types, SurfaceType t) {
    return std::find(types.begin(), types.end(), t) != types.end();
  };
  const std::vector<SurfaceType> cylinder_cone =
      MergeTypes(SurfaceType::kCylinder, SurfaceType::kCone);
  EXPECT_TRUE(has(cylinder_cone, SurfaceType::kCone));
  EXPECT_TRUE(has(cylinder_cone, SurfaceType::kCylinder));
  EXPECT_FALSE(has(cylinder_cone, SurfaceType::kTorus));
  EXPECT_EQ(MergeTypes(SurfaceType::kCone, SurfaceType::kCylinder), cylinder_cone);
  const std::vector<SurfaceType> two_cylinders =
      MergeTypes(SurfaceType::kCylinder, SurfaceType::kCylinder);
  EXPECT_TRUE(has(two_cylinders, SurfaceType::kCylinder));
  EXPECT_TRUE(has(two_cylinders, SurfaceType::kPlane));
  EXPECT_FALSE(has(two_cylinders, SurfaceType::kCone));
  EXPECT_FALSE(has(two_cylinders, SurfaceType::kTorus));
  EXPECT_FALSE(has(two_cylinders, SurfaceType::kQuadric));
  const std::vector<SurfaceType> with_quadric =
      MergeTypes(SurfaceType::kQuadric, SurfaceType::kCylinder);
  EXPECT_TRUE(has(with_quadric, SurfaceType::kQuadric));
  EXPECT_TRUE(has(with_quadric, SurfaceType::kTorus));
}

// The heights of a plane z = 0.1 u over a 31 x 31 unit grid: with
// independent normal noise of sigma 0.1; rounded to a unit grid (the
// staircase a surface from binary voxels follows: terraces 10 vertices
// wide); or exact but for a smooth error of 1e-9 (a fit's rounding on
// exact vertices, far below the data term's resolution).
enum class Heights { kNoisy, kStaircase, kSmoothTinyError };

// That sheet labelled one plane region fitted to it; th_dis 1 (the
// staircase's residuals are within 0.5).
std::vector<RegionState> TiltedPlane(Heights heights, testing::Sheet* s, std::vector<int>* labels) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.1);
  testing::BuildSheet(
      [&](double u, double v) {
        const double plane = 0.1 * u;
        const double z = heights == Heights::kStaircase ? std::round(plane)
                         : heights == Heights::kNoisy   ? plane + noise(random)
                                                        : plane + 1e-9 * std::sin(0.3 * u + 0.2 * v);
        return std::pair{Eigen::Vector3d(u, v, z), Eigen::Vector3d(-0.1, 0.0, 1.0).normalized()};
      },
      0.0, 30.0, 31, 0.0, 30.0, 31, /*distance=*/1.0, /*angle_deg=*/10.0, s);
  labels->assign(s->u.size(), 0);
  std::vector<RegionState> regions = {
      {.type = SurfaceType::kPlane, .surface = Plane{}, .vertices = {}}};
  RebuildVertexLists(*labels, &regions);
  const std::optional<Surface> fit = FitForEnergy(s->c, SurfaceType::kPlane, regions[0].vertices);
  EXPECT_TRUE(fit.has_value());
  if (fit) regions[0].surface = *fit;
  return regions;
}

// Independent noise leaves nearly every vertex an independent sample; the
// staircase's residuals are equal along each terrace and change slowly
// across it (correlation 0.6 over the grid's edges): a quarter of the
// vertices' evidence (0.23), under the 0.35 bound.
TEST(EvidenceShare, NearOneForIndependentNoiseSmallOnAStaircase) {
  testing::Sheet noisy, stairs;
  std::vector<int> labels;
  const std::vector<RegionState> noisy_regions = TiltedPlane(Heights::kNoisy, &noisy, &labels);
  EXPECT_GT(EvidenceShare(noisy.c, labels, noisy_regions), 0.85);
  const std::vector<RegionState> stair_regions = TiltedPlane(Heights::kStaircase, &stairs, &labels);
  EXPECT_LT(EvidenceShare(stairs.c, labels, stair_regions), 0.35);
}

// A smooth error of 1e-9 is correlated over the grid's edges (rho near 1,
// f near 0 measured alone) but far below what the data term resolves
// (th_dis / k / 10 = 0.033): it proves no correlation, f stays near 1.
TEST(EvidenceShare, NearOneForResidualsBelowTheDataTermsResolution) {
  testing::Sheet s;
  std::vector<int> labels;
  const std::vector<RegionState> regions = TiltedPlane(Heights::kSmoothTinyError, &s, &labels);
  EXPECT_GT(EvidenceShare(s.c, labels, regions), 0.99);
}

// Exact vertices (noise 0) with the true labels and surfaces refitted to
// them: the fits' errors are smooth and far below th_dis, f is near 1 and
// the energy finite (measured alone, rho of those errors gave f 0 to 0.001
// and lambda / f without bound).
TEST(EvidenceShare, NearOneOnExactVerticesWithTheTrueSurfaces) {
  for (const char* name : {"rounded_prism", "stepped_shaft"}) {
    Labeled t;
    BuildTrue(name, 0.0, &t);
    const double f = EvidenceShare(t.c, t.labels, t.regions);
    EXPECT_GT(f, 0.9) << name;
    t.c.evidence_share = f;
    EXPECT_TRUE(std::isfinite(TotalEnergy(t.c, t.labels, t.regions))) << name;
  }
}

// With f = 1 the label cost is the BIC's (p / 2) ln n and an edge between
// labels costs lambda; with fewer independent samples (f < 1) the label
// costs (p / (2 f)) ln (f n), nothing once f n <= 1, and the edge lambda / f
// (the data term's evidence is f times what it sums).
TEST(LabelCost, IsTheBicOnTheEffectiveSampleCount) {
  testing::Sheet s;
  testing::BuildSheet(testing::Fold45(5.0), 0.0, 10.0, 3, 0.0, 10.0, 3, 1.0, 10.0, &s);
  const double p = ParameterCount(SurfaceType::kCone);
  EXPECT_NEAR(LabelCost(s.c, SurfaceType::kCone, 100), 0.5 * p * std::log(100.0), 1e-12);
  EXPECT_NEAR(EdgeCost(s.c, 0, 1), kBoundaryCost, 1e-12);
  s.c.evidence_share = 0.25;
  EXPECT_NEAR(LabelCost(s.c, SurfaceType::kCone, 100), 2.0 * p * std::log(25.0), 1e-12);
  EXPECT_EQ(LabelCost(s.c, SurfaceType::kCone, 4), 0.0);
  EXPECT_NEAR(EdgeCost(s.c, 0, 1), 4.0 * kBoundaryCost, 1e-12);
}

// E with exact vertices (energy.h): the data term of a facet of an exactly
// tessellated cylinder band is 0 on the band's cylinder and infinite on a
// cylinder of a radius off by 1e-3 (far above tau = 1e-6) and on the
// facet's own neighbour's plane; the label cost is the BIC with f = 1.
TEST(ExactEnergy, DataTermIsZeroOnTheSurfaceAndInfiniteOff) {
  const Mesh band = testing::CylinderBand(0.0);
  const FacetMesh fm = BuildFacetMesh(band.tri);
  const Eigen::Vector3d axis_origin = -fm.origin;  // the band's axis, in fm's frame
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Surface cylinder = Cylinder{axis_origin, z, testing::kBandRadius};
  const Surface wider = Cylinder{axis_origin, z, testing::kBandRadius + 1e-3};
  const Surface next_plane = Plane{fm.Centroid(2), fm.normal[2]};
  constexpr double kTau = 1e-6;
  for (int facet = 0; facet < fm.facet_count(); ++facet) {
    EXPECT_EQ(ExactFacetCost(fm, facet, cylinder, kTau), 0.0) << facet;
    EXPECT_TRUE(std::isinf(ExactFacetCost(fm, facet, wider, kTau))) << facet;
  }
  EXPECT_TRUE(std::isinf(ExactFacetCost(fm, 0, next_plane, kTau)));
  EXPECT_EQ(ExactFacetCost(fm, 3, next_plane, kTau), 0.0);  // quad 1's other half
  const double p = ParameterCount(SurfaceType::kCylinder);
  EXPECT_NEAR(ExactLabelCost(SurfaceType::kCylinder, 48), 0.5 * p * std::log(48.0), 1e-12);
}

// The greedy cover's price (label cost per corner newly explained) falls
// as a surface explains more corners (from 3, a facet's), orders the types
// by their parameters at one count, and stays below the outlier cost of a
// corner for every analytic type: every hypothesis holding evidence lowers
// E. Joining regions onto one surface lowers E by the label cost saved iff
// the joint fit keeps the data term 0.
TEST(ExactEnergy, PricePerCornerFallsWithCornersAndRisesWithParameters) {
  constexpr SurfaceType kTypes[] = {SurfaceType::kPlane, SurfaceType::kSphere,
                                    SurfaceType::kCylinder, SurfaceType::kCone,
                                    SurfaceType::kTorus};
  for (const SurfaceType type : kTypes) {
    for (std::size_t n = 3; n < 2000; ++n) {
      EXPECT_LT(ExactPricePerCorner(type, n + 1), ExactPricePerCorner(type, n)) << n;
      EXPECT_LT(ExactPricePerCorner(type, n), kExactOutlierCost) << n;
    }
    EXPECT_TRUE(std::isinf(ExactPricePerCorner(type, 0)));
  }
  for (std::size_t i = 0; i + 1 < std::size(kTypes); ++i) {
    EXPECT_LT(ExactPricePerCorner(kTypes[i], 40), ExactPricePerCorner(kTypes[i + 1], 40));
  }
  const double saved = ExactLabelCost(SurfaceType::kPlane, 10) +
                       ExactLabelCost(SurfaceType::kPlane, 30) -
                       ExactLabelCost(SurfaceType::kPlane, 40);
  EXPECT_GT(saved, 0.0);
  EXPECT_NEAR(ExactJoinDelta(SurfaceType::kPlane, 10, 30, 0.0), -saved, 1e-12);
  EXPECT_TRUE(std::isinf(ExactJoinDelta(SurfaceType::kPlane, 10, 30,
                                        std::numeric_limits<double>::infinity())));
}

}  // namespace
}  // namespace meshseg::segment_internal
