// RecognizeFeatures on CT-like generated parts with their ground-truth
// segmentation (surfaces refitted by the fit stage from noisy vertices).
#include <cmath>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../topology/ground_truth_regions.h"
#include "meshseg/features.h"
#include "meshseg/generate.h"
#include "meshseg/topology.h"

namespace meshseg {
namespace {

using ::testing::Contains;

constexpr double kRadiusTol = 0.2;      // x voxel size h
constexpr double kAxisTolDeg = 0.5;
constexpr double kNoise = 0.05;         // x h, along the normals

struct PartFeatures {
  GeneratedPart part;
  testing::TruthSegmentation truth;
  std::vector<Feature> features;
};

PartFeatures Recognize(const std::string& name, double h) {
  PartFeatures out;
  absl::StatusOr<GeneratedPart> part = GeneratePart(name, {.voxel_size = h, .noise = kNoise});
  EXPECT_TRUE(part.ok()) << part.status();
  if (!part.ok()) return out;
  out.part = *std::move(part);
  out.truth = testing::TruthOf(out.part);
  const absl::StatusOr<Topology> topo =
      ExtractTopology(out.part.mesh, out.truth.face_labels, out.truth.regions);
  EXPECT_TRUE(topo.ok()) << topo.status();
  if (!topo.ok()) return out;
  absl::StatusOr<std::vector<Feature>> features = RecognizeFeatures(*topo, out.truth.regions);
  EXPECT_TRUE(features.ok()) << features.status();
  if (features.ok()) out.features = *std::move(features);
  return out;
}

// The fillet whose blend region is the primitive `name`, or nullptr.
const Feature* FilletOf(const PartFeatures& p, const std::string& name) {
  const int id = testing::PrimitiveId(p.part, name);
  for (const Feature& f : p.features) {
    if (f.type <= FeatureType::kFilletCylinderPlanes && f.regions.front() == id) return &f;
  }
  return nullptr;
}

std::vector<const Feature*> OfType(const PartFeatures& p, FeatureType type) {
  std::vector<const Feature*> out;
  for (const Feature& f : p.features) {
    if (f.type == type) out.push_back(&f);
  }
  return out;
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::abs(a.normalized().dot(b.normalized()));
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

TEST(RecognizeFeaturesOnParts, PlateBossTorusFilletIsFlt2WithItsRadius) {
  const double h = 1.0;
  const PartFeatures p = Recognize("plate_boss", h);
  const Feature* root = FilletOf(p, "boss_fillet");
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(root->type, FeatureType::kFilletTorusCylinderPlane);
  EXPECT_NEAR(root->radius, 4.0, kRadiusTol * h);
  EXPECT_FALSE(root->convex);
  EXPECT_EQ(root->regions[1], testing::PrimitiveId(p.part, "boss"));
  EXPECT_EQ(root->regions[2], testing::PrimitiveId(p.part, "plate_top"));
  const Feature* round = FilletOf(p, "boss_edge_round");
  ASSERT_NE(round, nullptr);
  EXPECT_EQ(round->type, FeatureType::kFilletTorusCylinderPlane);
  EXPECT_TRUE(round->convex);
  // The boss with its fillets, top and bore is one surface of revolution.
  const auto revolutions = OfType(p, FeatureType::kRevolution);
  ASSERT_EQ(revolutions.size(), 1u);
  EXPECT_THAT(revolutions[0]->regions, Contains(testing::PrimitiveId(p.part, "boss")));
  EXPECT_THAT(revolutions[0]->regions, Contains(testing::PrimitiveId(p.part, "boss_fillet")));
}

TEST(RecognizeFeaturesOnParts, BlendBlockHasThreeFlt3Fillets) {
  const double h = 0.8;
  const PartFeatures p = Recognize("blend_block", h);
  struct Expected {
    std::string name;
    double radius;
    bool convex;
  };
  for (const Expected& e : {Expected{"inner_fillet", 5.0, false}, Expected{"end_round", 4.0, true},
                            Expected{"top_round", 3.0, true}}) {
    const Feature* f = FilletOf(p, e.name);
    ASSERT_NE(f, nullptr) << e.name;
    EXPECT_EQ(f->type, FeatureType::kFilletCylinderPlanes) << e.name;
    EXPECT_NEAR(f->radius, e.radius, kRadiusTol * h) << e.name;
    EXPECT_EQ(f->convex, e.convex) << e.name;
    EXPECT_NEAR(f->opening_angle_deg, 90.0, kAxisTolDeg) << e.name;
  }
}

TEST(RecognizeFeaturesOnParts, SteppedShaftIsOneSurfaceOfRevolution) {
  const double h = 0.7;
  const PartFeatures p = Recognize("stepped_shaft", h);
  const auto revolutions = OfType(p, FeatureType::kRevolution);
  ASSERT_EQ(revolutions.size(), 1u);
  const Feature& r = *revolutions[0];
  int with_faces = 0;
  for (const Region& region : p.truth.regions) with_faces += region.face_count > 0;
  EXPECT_EQ(static_cast<int>(r.regions.size()), with_faces);
  const auto& truth_axis =
      std::get<Cylinder>(p.part.primitives[testing::PrimitiveId(p.part, "cylinder_12")].surface);
  EXPECT_LE(AngleDeg(r.direction, truth_axis.axis_direction), kAxisTolDeg);
  const Eigen::Vector3d off = r.point - truth_axis.axis_origin;
  const double axis_distance =
      (off - off.dot(truth_axis.axis_direction) * truth_axis.axis_direction).norm();
  EXPECT_LE(axis_distance, kRadiusTol * h);
}

TEST(RecognizeFeaturesOnParts, RoundedPrismIsALinearExtrusion) {
  const double h = 0.7;
  const PartFeatures p = Recognize("rounded_prism", h);
  const auto extrusions = OfType(p, FeatureType::kLinearExtrusion);
  ASSERT_EQ(extrusions.size(), 1u);
  const Feature& e = *extrusions[0];
  EXPECT_EQ(e.regions.size(), 12u);  // six sides, six rounds
  const auto& bore = std::get<Cylinder>(p.part.primitives[testing::PrimitiveId(p.part, "bore")].surface);
  EXPECT_LE(AngleDeg(e.direction, bore.axis_direction), kAxisTolDeg);
}

TEST(RecognizeFeaturesOnParts, TestPieceHasItsThreeRoundsAndTwoRevolutionsOnly) {
  const double h = 1.0;
  const PartFeatures p = Recognize("test_piece", h);
  const auto fillets = OfType(p, FeatureType::kFilletCylinderPlanes);
  ASSERT_EQ(fillets.size(), 3u);
  for (const auto& [name, radius] : {std::pair<std::string, double>{"round_front_right", 6.0},
                                     {"round_back_right", 6.0},
                                     {"round_top_left", 5.0}}) {
    const Feature* f = FilletOf(p, name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_NEAR(f->radius, radius, kRadiusTol * h) << name;
    EXPECT_TRUE(f->convex) << name;
  }
  // The half-cylinder groove joins its planes at 180 degrees: no fillet.
  EXPECT_EQ(FilletOf(p, "groove"), nullptr);
  const auto revolutions = OfType(p, FeatureType::kRevolution);
  ASSERT_EQ(revolutions.size(), 2u);
  const int bore = testing::PrimitiveId(p.part, "bore");
  const int countersink = testing::PrimitiveId(p.part, "countersink");
  EXPECT_EQ(revolutions[0]->regions, (std::vector<int>{std::min(bore, countersink),
                                                       std::max(bore, countersink)}));
  EXPECT_TRUE(OfType(p, FeatureType::kLinearExtrusion).empty());
}

}  // namespace
}  // namespace meshseg
