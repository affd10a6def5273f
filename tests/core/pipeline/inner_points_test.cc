#include "pipeline/inner_points.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "gtest/gtest.h"
#include "meshseg/fit.h"
#include "pipeline/point_labels.h"
#include "pipeline/refit_regions.h"

namespace meshseg::pipeline_internal {
namespace {

// A turned end seen as a scan: a cylinder of radius 5 (z from -4 to 0), a
// 45-degree chamfer to radius 3.5 at z = 1.5, and the flat top (radius 3.5
// down to 1, open inside). Profile point at arc length s from the bottom
// (the chamfer from s = 4 to 4 + 1.5 sqrt 2) and its outward normal.
constexpr double kSpacing = 0.3;  // h: the mesh's edges and the points'
constexpr double kSigma = 0.03;   // the points' noise across the surface
const double kChamferLength = 1.5 * std::numbers::sqrt2;
const double kProfileLength = 4.0 + kChamferLength + 2.5;

struct ProfilePoint {
  double r = 0.0, z = 0.0, nr = 0.0, nz = 0.0;
};

ProfilePoint Profile(double s) {
  if (s < 4.0) return {5.0, s - 4.0, 1.0, 0.0};
  if (s < 4.0 + kChamferLength) {
    const double u = (s - 4.0) / std::numbers::sqrt2;
    return {5.0 - u, u, std::sqrt(0.5), std::sqrt(0.5)};
  }
  return {3.5 - (s - 4.0 - kChamferLength), 1.5, 0.0, 1.0};
}

Eigen::Vector3d At(const ProfilePoint& p, double t) {
  return {p.r * std::cos(t), p.r * std::sin(t), p.z};
}

// The surface of revolution, with rings every kSpacing along the profile
// (and at both edges) and segments about kSpacing apart at radius 5.
TriMesh TurnedEnd(std::vector<double>* ring_s) {
  for (double s = 0.0; s <= kProfileLength + 1e-9; s += kSpacing) ring_s->push_back(s);
  ring_s->push_back(4.0);
  ring_s->push_back(4.0 + kChamferLength);
  std::sort(ring_s->begin(), ring_s->end());
  const int segments = static_cast<int>(2.0 * std::numbers::pi * 5.0 / kSpacing);
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (const double s : *ring_s) {
    for (int k = 0; k < segments; ++k) {
      const Eigen::Vector3d p = At(Profile(s), 2.0 * std::numbers::pi * k / segments);
      v.push_back(m.add_vertex({p.x(), p.y(), p.z()}));
    }
  }
  for (int ring = 0; ring + 1 < static_cast<int>(ring_s->size()); ++ring) {
    for (int k = 0; k < segments; ++k) {
      const int a = ring * segments + k, b = ring * segments + (k + 1) % segments;
      m.add_face(v[a], v[b], v[b + segments]);
      m.add_face(v[a], v[b + segments], v[a + segments]);
    }
  }
  return m;
}

TEST(RetypeOnInnerPoints, AChamferWhoseRegionReachesOverBothEdgesIsACone) {
  // The segmentation's chamfer region (label 1) reaches 2.5 spacings beyond
  // each edge, onto the cylinder (label 0) and the top (label 2), as the
  // chamfer of a scanned shaft's region did. Its points then bend the same
  // way at both ends: a torus follows them, the cone does not.
  std::vector<double> ring_s;
  const TriMesh mesh = TurnedEnd(&ring_s);
  constexpr double kReach = 2.5 * kSpacing;
  const int segments = static_cast<int>(mesh.n_faces() / (2 * (ring_s.size() - 1)));
  std::vector<int> face_labels(mesh.n_faces());
  for (int f = 0; f < static_cast<int>(face_labels.size()); ++f) {
    const double s = ring_s[f / (2 * segments)];
    face_labels[f] = s < 4.0 - kReach ? 0 : s < 4.0 + kChamferLength + kReach ? 1 : 2;
  }
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, kSigma);
  std::vector<Eigen::Vector3d> cloud, normals;
  for (int k = 0; k < 12000; ++k) {
    const ProfilePoint p = Profile(kProfileLength * unit(random));
    const double t = 2.0 * std::numbers::pi * unit(random);
    const Eigen::Vector3d n(p.nr * std::cos(t), p.nr * std::sin(t), p.nz);
    cloud.push_back(At(p, t) + noise(random) * n);
    normals.push_back(n);
  }
  std::vector<uint32_t> nearest_vertex;
  const std::vector<int> nearest = PointLabels(mesh, face_labels, cloud, {}, &nearest_vertex);
  // The regions as the segmentation types them, fitted to their points.
  constexpr SurfaceType kTypes[] = {SurfaceType::kCylinder, SurfaceType::kTorus,
                                    SurfaceType::kPlane};
  std::vector<Region> regions(3);
  std::vector<SharedSurface> surfaces;
  std::vector<std::vector<Eigen::Vector3d>> points(3);
  for (int r = 0; r < 3; ++r) {
    std::vector<Eigen::Vector3d> own_normals;
    for (std::size_t k = 0; k < cloud.size(); ++k) {
      if (nearest[k] != r) continue;
      points[r].push_back(cloud[k]);
      own_normals.push_back(normals[k]);
    }
    const FitResult fit =
        FitOfType(kTypes[r], {.points = points[r], .normals = own_normals, .weights = {}});
    ASSERT_TRUE(fit.ok()) << SurfaceTypeName(kTypes[r]);
    regions[r].id = r;
    regions[r].type = kTypes[r];
    regions[r].surface = fit.surface;
    regions[r].rms_distance = fit.rms_distance;
    regions[r].max_distance = fit.max_distance;
    regions[r].surface_id = r;
    SharedSurface& surface = surfaces.emplace_back();
    surface.id = r;
    surface.type = kTypes[r];
    surface.surface = fit.surface;
    surface.regions = {r};
  }
  // On all its points the torus fits better than the cone by far more than
  // the noise: the decision on them keeps it (what this test guards).
  std::vector<Region> on_all = regions;
  std::vector<SharedSurface> surfaces_on_all = surfaces;
  RetypeToPoints(points, kSigma, &on_all, &surfaces_on_all);
  ASSERT_EQ(on_all[1].type, SurfaceType::kTorus);

  const double band = 3.0 * kSigma;
  for (int r = 0; r < 3; ++r) {
    std::erase_if(points[r], [&](const Eigen::Vector3d& p) {
      return !(std::abs(SignedDistance(regions[r].surface, p)) <= band);
    });
  }
  EXPECT_EQ(RetypeOnInnerPoints(mesh, face_labels, cloud, nearest, nearest_vertex,
                                {.spacing = kSpacing,
                                 .noise = kSigma,
                                 .band = band,
                                 .distance_tolerance = 2.0 * kSigma},
                                points, &regions, &surfaces),
            1);
  ASSERT_EQ(regions[1].type, SurfaceType::kCone);
  // The cone is the chamfer's: half angle 45 degrees, within the noise of
  // its points, and the region's surface is its own.
  const Cone& cone = std::get<Cone>(regions[1].surface);
  EXPECT_NEAR(cone.half_angle, std::numbers::pi / 4.0, 0.02);
  EXPECT_LT(regions[1].rms_distance, 1.5 * kSigma);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[2].type, SurfaceType::kPlane);
  EXPECT_EQ(surfaces[regions[1].surface_id].type, SurfaceType::kCone);
}

}  // namespace
}  // namespace meshseg::pipeline_internal
