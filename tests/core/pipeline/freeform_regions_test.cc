// FitFreeformRegions (#35, ALGORITHMS.md S5): a freeform region, and a
// quadric region whose quadric misses it by more than the noise, get a Loop
// control mesh fitted to their faces whose limit surface lies on the true
// surface within the bound; analytic regions and quadrics that fit
// to the noise get none.
#include "pipeline/freeform_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/subdiv/shapes.h"

namespace meshseg::pipeline_internal {
namespace {

TEST(NeedsSubdivision, FreeformAndQuadricsWorseThanTheNoiseOfEnoughFaces) {
  const FreeformFitParams params;
  const double noise = 0.1;
  Region r;
  r.type = SurfaceType::kFreeform;
  r.face_count = 200;
  r.rms_distance = 0.01;
  EXPECT_TRUE(NeedsSubdivision(r, noise, params));
  r.face_count = params.min_region_faces - 1;
  EXPECT_FALSE(NeedsSubdivision(r, noise, params));
  r.type = SurfaceType::kQuadric;
  r.face_count = 200;
  r.rms_distance = 0.14;
  EXPECT_FALSE(NeedsSubdivision(r, noise, params));  // the noise explains 1.4 sigma
  r.rms_distance = 0.16;
  EXPECT_TRUE(NeedsSubdivision(r, noise, params));
  r.type = SurfaceType::kTorus;  // analytic types keep their surface alone
  EXPECT_FALSE(NeedsSubdivision(r, noise, params));
}

TEST(FitFreeformRegions, FitsFreeformRegionsWithinTheNoiseBound) {
  // |x|^3 + |y|^3 + |z|^3 = 10^3, 5120 faces, noise 0.05 h along the normal,
  // cut by two planes z = +-3 into a freeform cap, a quadric band that fits
  // to the noise and a quadric cap that does not.
  const testing::Superellipsoid shape;
  const testing::NoisySample sample = testing::NoisySuperellipsoid(shape, 4, 0.05, 5);
  const testing::Triangles& t = sample.mesh;
  const double h = sample.h, sigma = sample.sigma;
  absl::StatusOr<Mesh> mesh = testing::ToMesh(t, "body");
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  std::vector<int> labels;
  std::vector<Region> regions(3);
  for (const auto& f : t.faces) {
    const double z = (t.vertices[f[0]] + t.vertices[f[1]] + t.vertices[f[2]]).z() / 3.0;
    labels.push_back(z > 3.0 ? 0 : (z < -3.0 ? 2 : 1));
    ++regions[labels.back()].face_count;
  }
  regions[0].type = SurfaceType::kFreeform;
  regions[1].type = SurfaceType::kQuadric;
  regions[1].rms_distance = sigma;
  regions[2].type = SurfaceType::kQuadric;
  regions[2].rms_distance = 3.0 * sigma;
  for (int r = 0; r < 3; ++r) regions[r].id = r;

  FreeformFitParams off;
  off.enabled = false;
  absl::StatusOr<std::vector<RegionSubdivision>> none =
      FitFreeformRegions(*mesh, labels, regions, sigma, off, {});
  ASSERT_TRUE(none.ok()) << none.status();
  EXPECT_TRUE(none->empty());

  absl::StatusOr<std::vector<RegionSubdivision>> fits =
      FitFreeformRegions(*mesh, labels, regions, sigma, {}, {});
  ASSERT_TRUE(fits.ok()) << fits.status();
  ASSERT_EQ(fits->size(), 2u);
  EXPECT_EQ((*fits)[0].region, 0);
  EXPECT_EQ((*fits)[1].region, 2);
  for (const RegionSubdivision& s : *fits) {
    const int64_t faces = regions[s.region].face_count;
    EXPECT_LE(s.control.faces.size(), 0.05 * faces + 2) << s.region;
    // The region's border is the control mesh's boundary (a sharp edge of
    // the limit surface), so no interior creases are needed on a smooth body.
    EXPECT_TRUE(s.control.creases.empty()) << s.region;
    absl::StatusOr<LimitMesh> limit = EvaluateLimitSurface(s.control, 2);
    ASSERT_TRUE(limit.ok()) << limit.status();
    double sum = 0.0;
    for (const Eigen::Vector3d& p : limit->vertices) sum += std::pow(shape.Distance(p), 2);
    const double rms = std::sqrt(sum / limit->vertices.size());
    EXPECT_LE(rms, 1.2 * sigma + 0.05 * h) << "region " << s.region << " h " << h;
    EXPECT_LE(s.rms_distance, 1.5 * sigma) << s.region;  // the data to the limit: the noise
  }
}

}  // namespace
}  // namespace meshseg::pipeline_internal
