// Sphere bands beside a turned face: a narrow 45-degree cone band on a
// cylinder's axis, fitted as a sphere, becomes the coaxial cone; a true
// sphere zone on the same axis stays a sphere.
#include "pipeline/binary_types.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <variant>
#include <vector>

#include "gtest/gtest.h"
#include "meshseg/fit.h"

namespace meshseg::pipeline_internal {
namespace {

constexpr int kSegments = 96;

// A tube of radius 5 along z (z 0..6, 13 rings) continued by a band of
// `band_rings` rings whose radius at height z is `profile(z)`; every vertex
// moved +-0.03 along the radius in a checkerboard (terrace-like offsets of
// either sign). Faces of the tube are labelled 0, of the band 1.
TriMesh TubeWithBand(const std::function<double(double)>& profile, std::vector<int>* labels) {
  TriMesh m;
  std::vector<double> heights, radii;
  for (int i = 0; i <= 12; ++i) heights.push_back(0.5 * i), radii.push_back(5.0);
  for (int i = 1; i <= 8; ++i) {
    const double z = 6.0 + 0.25 * i;
    heights.push_back(z);
    radii.push_back(profile(z));
  }
  std::vector<TriMesh::VertexHandle> v;
  for (size_t ring = 0; ring < heights.size(); ++ring) {
    for (int k = 0; k < kSegments; ++k) {
      const double t = 2.0 * std::numbers::pi * k / kSegments;
      const double r = radii[ring] + ((ring + k) % 2 ? 0.03 : -0.03);
      v.push_back(m.add_vertex({r * std::cos(t), r * std::sin(t), heights[ring]}));
    }
  }
  for (size_t ring = 0; ring + 1 < heights.size(); ++ring) {
    for (int k = 0; k < kSegments; ++k) {
      const int a = ring * kSegments + k, b = ring * kSegments + (k + 1) % kSegments;
      m.add_face(v[a], v[b], v[b + kSegments]);
      m.add_face(v[a], v[b + kSegments], v[a + kSegments]);
      labels->push_back(ring < 12 ? 0 : 1);
      labels->push_back(ring < 12 ? 0 : 1);
    }
  }
  return m;
}

// Regions 0 (cylinder, as fitted) and 1 (typed sphere, as fitted).
std::vector<Region> Regions(const TriMesh& m, const std::vector<int>& labels) {
  std::vector<Region> regions(2);
  for (int r = 0; r < 2; ++r) {
    std::vector<Eigen::Vector3d> points;
    for (const auto f : m.faces()) {
      if (labels[f.idx()] != r) continue;
      for (const auto u : m.fv_range(f)) points.push_back(ToEigen(m.point(u)));
    }
    const SurfaceType type = r == 0 ? SurfaceType::kCylinder : SurfaceType::kSphere;
    const FitResult fit = FitOfType(type, {.points = points, .normals = {}, .weights = {}});
    EXPECT_TRUE(fit.ok());
    regions[r] = Region{.id = r, .type = type, .surface = fit.surface};
    regions[r].rms_distance = fit.rms_distance;
  }
  return regions;
}

TEST(RetypeCoaxialSpheres, AChamferBandBecomesTheCoaxialCone) {
  std::vector<int> labels;
  // 45 degrees inwards from radius 5 at z = 6: radius 5 - (z - 6).
  const TriMesh m = TubeWithBand([](double z) { return 5.0 - (z - 6.0); }, &labels);
  std::vector<Region> regions = Regions(m, labels);
  RetypeCoaxialSpheresOnInputVertices(m, labels, &regions);
  ASSERT_EQ(regions[1].type, SurfaceType::kCone);
  const Cone& cone = std::get<Cone>(regions[1].surface);
  EXPECT_NEAR(cone.half_angle, std::numbers::pi / 4, 0.02);
  EXPECT_GT(std::abs(cone.axis_direction.normalized().z()), 0.9999);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
}

TEST(RetypeCoaxialSpheres, ASphereZoneStaysASphere) {
  std::vector<int> labels;
  // The sphere of radius 5.5 centred on the axis at z = 6 - sqrt(5.5^2 - 25).
  const double c = 6.0 - std::sqrt(5.5 * 5.5 - 25.0);
  const TriMesh m =
      TubeWithBand([c](double z) { return std::sqrt(5.5 * 5.5 - (z - c) * (z - c)); }, &labels);
  std::vector<Region> regions = Regions(m, labels);
  RetypeCoaxialSpheresOnInputVertices(m, labels, &regions);
  EXPECT_EQ(regions[1].type, SurfaceType::kSphere);
}

}  // namespace
}  // namespace meshseg::pipeline_internal
