// Joint hypotheses of the exact-facet path (segment/exact_joint_hypotheses.h)
// through the public entry, on solids of revolution tessellated in bands
// between parallel circles, as CAD exporters do: a torus read as one
// surface, not a stack of cones; coaxial cylinders and cones that meet at
// circles stay apart.
#include "segment/exact_joint_hypotheses.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "meshseg/segment.h"
#include "segment/exact_fit.h"
#include "segment/exact_hypotheses.h"
#include "segment/facet_mesh.h"

namespace meshseg {
namespace {

// The solid swept by the meridian polyline `profile` (rho > 0, z) about the
// z axis in `around` steps, every vertex exact, each band between two
// circles in long quads split in two, closed by discs fanned from a point
// off the axis (a centre on the axis lies on the chords between opposite
// rim vertices: exact_facets_test's disabled disc case).
Mesh Revolved(const std::vector<Eigen::Vector2d>& profile, int around) {
  const int rings = static_cast<int>(profile.size());
  std::vector<Eigen::Vector3d> v;
  for (const Eigen::Vector2d& p : profile) {
    for (int k = 0; k < around; ++k) {
      const double a = 2.0 * std::numbers::pi * k / around;
      v.emplace_back(p.x() * std::cos(a), p.x() * std::sin(a), p.y());
    }
  }
  const int bottom = static_cast<int>(v.size());
  v.emplace_back(0.3, 0.2, profile.front().y());
  v.emplace_back(0.3, 0.2, profile.back().y());
  std::vector<std::array<int, 3>> f;
  for (int i = 0; i + 1 < rings; ++i) {
    for (int k = 0; k < around; ++k) {
      const int a = i * around + k, b = i * around + (k + 1) % around;
      f.push_back({a, b, b + around});
      f.push_back({a, b + around, a + around});
    }
  }
  for (int k = 0; k < around; ++k) {
    f.push_back({bottom, (k + 1) % around, k});
    const int top = (rings - 1) * around;
    f.push_back({bottom + 1, top + k, top + (k + 1) % around});
  }
  absl::StatusOr<Mesh> mesh = BuildMesh(std::move(v), f, "revolved");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

std::map<std::string, int> TypeCounts(const Segmentation& seg) {
  std::map<std::string, int> counts;
  for (const Region& r : seg.regions) ++counts[SurfaceTypeName(r.type)];
  return counts;
}

// The meridian of a torus R 8 r 2 from `from_deg` to `to_deg` of its tube
// (0 at the outer equator) in steps of 15 degrees: each band an exact cone.
std::vector<Eigen::Vector2d> TubeArc(int from_deg, int to_deg) {
  std::vector<Eigen::Vector2d> profile;
  for (int deg = from_deg; deg <= to_deg; deg += 15) {
    const double t = deg * std::numbers::pi / 180.0;
    profile.emplace_back(8.0 + 2.0 * std::cos(t), 2.0 * std::sin(t));
  }
  return profile;
}

// A barrel: the outer half of a torus R 8 r 2 between -60 and 60 degrees of
// its tube in bands of 15 degrees (each an exact cone), with flat ends.
TEST(RevolvedBands, TheBandsOfATorusAreOneTorus) {
  const absl::StatusOr<Segmentation> seg = SegmentExactFacets(Revolved(TubeArc(-60, 60), 36));
  ASSERT_TRUE(seg.ok()) << seg.status();
  EXPECT_EQ(TypeCounts(*seg), (std::map<std::string, int>{{"plane", 2}, {"torus", 1}}));
  for (const Region& r : seg->regions) {
    if (const auto* t = std::get_if<Torus>(&r.surface)) {
      EXPECT_NEAR(t->major_radius, 8.0, 1e-9);
      EXPECT_NEAR(t->minor_radius, 2.0, 1e-9);
      EXPECT_EQ(r.face_count, 8 * 2 * 36);
    }
  }
}

// The joint hypothesis itself, from one exact cone per band (what the seeds
// give on a CAD export's torus, whose seed groups stay inside a band): one
// torus R 8 r 2 over every band facet.
TEST(RevolvedBands, ConesOfTheBandsOfATorusSeedTheTorus) {
  using namespace segment_internal;
  const std::vector<Eigen::Vector2d> profile = TubeArc(-60, 60);
  constexpr int kAround = 36;
  const Mesh mesh = Revolved(profile, kAround);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  const double tau = 1e-12 * fm.diagonal;
  std::vector<Hypothesis> cones;
  for (int band = 0; band + 1 < static_cast<int>(profile.size()); ++band) {
    std::vector<int> facets;
    for (int k = 0; k < 2 * kAround; ++k) facets.push_back(band * 2 * kAround + k);
    const std::optional<Surface> cone = FitExactly(fm, SurfaceType::kCone, facets, tau);
    ASSERT_TRUE(cone.has_value()) << "band " << band;
    cones.push_back({.type = SurfaceType::kCone, .surface = *cone, .support = facets});
  }
  const std::vector<Hypothesis> joint = RevolvedBandHypotheses(fm, cones, tau);
  ASSERT_EQ(joint.size(), 1u);
  ASSERT_EQ(joint[0].type, SurfaceType::kTorus);
  const Torus& torus = std::get<Torus>(joint[0].surface);
  EXPECT_NEAR(torus.major_radius, 8.0, 1e-9);
  EXPECT_NEAR(torus.minor_radius, 2.0, 1e-9);
  EXPECT_EQ(joint[0].support.size(), 8u * 2 * kAround);
  // Two of the bands alone (three circles) seed nothing.
  EXPECT_TRUE(RevolvedBandHypotheses(fm, {cones[3], cones[4]}, tau).empty());
}

// A shaft stepped by a chamfer: cylinder r 5, a 45-degree cone, cylinder
// r 7, coaxial and adjacent. Their four circles lie on no one circle of the
// meridian half-plane, so no torus explains them: three regions, not one.
TEST(RevolvedBands, ACylinderAConeAndACylinderStayThree) {
  const std::vector<Eigen::Vector2d> profile = {{5.0, 0.0}, {5.0, 4.0}, {7.0, 6.0}, {7.0, 10.0}};
  const absl::StatusOr<Segmentation> seg = SegmentExactFacets(Revolved(profile, 36));
  ASSERT_TRUE(seg.ok()) << seg.status();
  EXPECT_EQ(TypeCounts(*seg),
            (std::map<std::string, int>{{"cone", 1}, {"cylinder", 2}, {"plane", 2}}));
}

// Two bands of a torus (three circles) lie on a torus whatever they are,
// and on a cone each: they hold no evidence of the torus and stay cones.
TEST(RevolvedBands, TwoBandsAreNoEvidenceOfATorus) {
  const absl::StatusOr<Segmentation> seg = SegmentExactFacets(Revolved(TubeArc(-15, 15), 36));
  ASSERT_TRUE(seg.ok()) << seg.status();
  EXPECT_EQ(TypeCounts(*seg), (std::map<std::string, int>{{"cone", 2}, {"plane", 2}}));
}

// Two small pieces of one cone band, a quarter turn apart, each too small
// to fix the cone alone: fitted together they are one cone, grown over the
// band; a piece of the band with a piece of the flat end is no surface.
TEST(JointPieces, TwoPiecesOfOneConeAreThatCone) {
  using namespace segment_internal;
  constexpr int kAround = 36;
  // A cone of half angle 60 degrees (rho grows by tan 60 per unit of z).
  const std::vector<Eigen::Vector2d> profile = {{5.0, 0.0}, {5.0 + std::sqrt(3.0), 1.0}};
  const Mesh mesh = Revolved(profile, kAround);
  const FacetMesh fm = BuildFacetMesh(mesh.tri);
  const double tau = 1e-12 * fm.diagonal;
  const std::vector<int> first = {0, 1, 2, 3}, second = {18, 19, 20, 21};
  for (const std::vector<int>& piece : {first, second}) {
    EXPECT_FALSE(FitExactly(fm, SurfaceType::kCone, piece, tau).has_value());
  }
  const std::vector<Hypothesis> joint = JointPieceHypotheses(fm, {first, second}, tau);
  ASSERT_EQ(joint.size(), 1u);
  EXPECT_EQ(joint[0].type, SurfaceType::kCone);
  EXPECT_TRUE(joint[0].joint);
  EXPECT_NEAR(std::get<Cone>(joint[0].surface).half_angle, std::numbers::pi / 3.0, 1e-9);
  EXPECT_EQ(joint[0].support.size(), 2u * kAround);
  // The end disc's facets follow the band's (two rings of 2 * kAround).
  const std::vector<int> disc = {2 * kAround, 2 * kAround + 2, 2 * kAround + 4};
  EXPECT_TRUE(JointPieceHypotheses(fm, {first, disc}, tau).empty());
}

}  // namespace
}  // namespace meshseg
