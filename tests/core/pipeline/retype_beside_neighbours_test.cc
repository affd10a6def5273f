#include "pipeline/retype_beside_neighbours.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "gtest/gtest.h"
#include "meshseg/fit.h"
#include "pipeline/refit_regions.h"

namespace meshseg::pipeline_internal {
namespace {

// A scan's spacing and range noise, as at 40K points on a turned part of
// about 30 x 15 (noise 0.22 spacings).
constexpr double kSpacing = 0.3;
constexpr double kSigma = 0.066;
// No band: every type judged on all the points as given.
constexpr double kNoBand = std::numeric_limits<double>::infinity();

// A point of a surface of revolution about the z axis: `profile(s)` gives
// (radius, z, normal's radial part, normal's z part) at arc length s.
struct ProfilePoint {
  double r, z, nr, nz;
};
using Profile = std::function<ProfilePoint(double)>;

// `count` points spread evenly over arc lengths [0, length) of `profile`
// and all angles, with Gaussian noise `kSigma` along the normal; their
// true normals in `normals`.
std::vector<Eigen::Vector3d> Revolve(const Profile& profile, double length, int count,
                                     unsigned seed, std::vector<Eigen::Vector3d>* normals) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, kSigma);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < count; ++k) {
    const double t = 2.0 * std::numbers::pi * unit(random);
    const ProfilePoint q = profile(length * unit(random));
    const Eigen::Vector3d radial(std::cos(t), std::sin(t), 0.0);
    const Eigen::Vector3d n = q.nr * radial + Eigen::Vector3d(0, 0, q.nz);
    points.push_back(q.r * radial + Eigen::Vector3d(0, 0, q.z) + noise(random) * n);
    if (normals != nullptr) normals->push_back(n);
  }
  return points;
}

// Region `id` of `type` with `surface`; distances measured on `points`.
Region RegionOn(int id, SurfaceType type, const Surface& surface,
                const std::vector<Eigen::Vector3d>& points) {
  Region r;
  r.id = id;
  r.surface_id = id;
  r.type = type;
  r.surface = surface;
  for (const Eigen::Vector3d& p : points) {
    const double d = std::abs(SignedDistance(surface, p));
    r.rms_distance += d * d;
    r.max_distance = std::max(r.max_distance, d);
  }
  r.rms_distance = std::sqrt(r.rms_distance / static_cast<double>(points.size()));
  return r;
}

// One shared surface per region.
std::vector<SharedSurface> OwnSurfaces(const std::vector<Region>& regions) {
  std::vector<SharedSurface> surfaces;
  for (const Region& r : regions) {
    surfaces.push_back({.id = r.id, .type = r.type, .surface = r.surface, .regions = {r.id}});
  }
  return surfaces;
}

// A torus fitted to `points` (with their true normals) as region 0.
Region TorusRegion(const std::vector<Eigen::Vector3d>& points,
                   const std::vector<Eigen::Vector3d>& normals) {
  const FitResult fit =
      FitOfType(SurfaceType::kTorus, {.points = points, .normals = normals, .weights = {}});
  EXPECT_TRUE(fit.ok());
  return RegionOn(0, SurfaceType::kTorus, fit.surface, points);
}

// A turned end: the cylinder of radius 5 (z <= 0), a 45-degree chamfer to
// radius 3.5 at z = 1.5, the flat top; the chamfer's profile from `reach`
// down the cylinder to `reach` in on the top (arc length kChamferSlant + 2
// reach).
const double kChamferSlant = 1.5 * std::numbers::sqrt2;
Profile ChamferBand(double reach) {
  return [reach](double s) -> ProfilePoint {
    const double h = std::sqrt(0.5);
    if (s < reach) return {5.0, s - reach, 1.0, 0.0};  // the cylinder
    if (s < reach + kChamferSlant) {                     // the chamfer
      const double u = (s - reach) * h;
      return {5.0 - u, u, h, h};
    }
    return {3.5 - (s - reach - kChamferSlant), 1.5, 0.0, 1.0};  // the top
  };
}

// The turned end's chamfer band (its region reaching 2.5 spacings over both
// creases), the cylinder below it and the top: points drawn from each, the
// band's with their true normals in `band_normals`.
struct ChamferScene {
  std::vector<std::vector<Eigen::Vector3d>> points;
  std::vector<Eigen::Vector3d> band_normals;
};
ChamferScene MakeChamferScene() {
  constexpr double kReach = 2.5 * kSpacing;
  ChamferScene scene;
  scene.points.resize(3);
  scene.points[0] = Revolve(ChamferBand(kReach), kChamferSlant + 2.0 * kReach, 2000, 3,
                            &scene.band_normals);
  scene.points[1] = Revolve([](double s) -> ProfilePoint { return {5.0, -s, 1.0, 0.0}; }, 4.0,
                            3000, 4, nullptr);
  scene.points[2] = Revolve([](double s) -> ProfilePoint { return {s, 1.5, 0.0, 1.0}; }, 3.5,
                            1500, 5, nullptr);
  return scene;
}

// Expects region 0 (the band, beside regions 1 and 2) retyped to the
// chamfer's 45-degree cone on the z axis.
void ExpectBandRetypedToTheChamferCone(const std::vector<std::vector<Eigen::Vector3d>>& points,
                                       std::vector<Region>* regions,
                                       std::vector<SharedSurface>* surfaces) {
  const std::vector<std::vector<int>> neighbours = {{1, 2}, {0}, {0}};
  EXPECT_EQ(RetypeBesideNeighbours(points, neighbours, kSigma, regions, surfaces), 1);
  ASSERT_EQ((*regions)[0].type, SurfaceType::kCone);
  const Cone& cone = std::get<Cone>((*regions)[0].surface);
  EXPECT_NEAR(cone.half_angle, std::numbers::pi / 4, 0.02);
  EXPECT_NEAR(std::abs(cone.axis_direction.z()), 1.0, 1e-3);
}

TEST(RetypeBesideNeighbours, AChamferWhoseRegionReachesOverBothCreasesIsACone) {
  // The turned end's chamfer: its region reaches 2.5 spacings over both
  // creases, into the cylinder and the top, as a reconstruction's rounded
  // creases let it (41 % of its points are theirs), and is typed a torus,
  // which bends into both. Ground truth: which surface each point was
  // drawn from.
  const ChamferScene scene = MakeChamferScene();
  const std::vector<std::vector<Eigen::Vector3d>>& points = scene.points;
  const std::vector<Eigen::Vector3d>& normals = scene.band_normals;
  std::vector<Region> regions = {
      TorusRegion(points[0], normals),
      RegionOn(1, SurfaceType::kCylinder, Cylinder{.radius = 5.0}, points[1]),
      RegionOn(2, SurfaceType::kPlane, Plane{.point = {0, 0, 1.5}}, points[2])};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  // On its band alone the torus stays: its points are the data it bent to.
  std::vector<Region> alone = regions;
  EXPECT_EQ(RetypeToPoints(points, kNoBand, kSigma, &alone, &surfaces), 0);
  ASSERT_EQ(alone[0].type, SurfaceType::kTorus);

  ExpectBandRetypedToTheChamferCone(points, &regions, &surfaces);
  if (regions[0].type != SurfaceType::kCone) return;
  // Fitted on the chamfer's own points: at the noise there.
  EXPECT_LT(regions[0].rms_distance, 1.2 * kSigma);
  EXPECT_EQ(regions[1].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[2].type, SurfaceType::kPlane);
  EXPECT_EQ(surfaces[0].type, SurfaceType::kCone);
  EXPECT_EQ(surfaces[0].regions, std::vector<int>{0});
}

// A sphere fitted to `points` (with their true normals) as region 0.
Region SphereRegion(const std::vector<Eigen::Vector3d>& points,
                    const std::vector<Eigen::Vector3d>& normals) {
  const FitResult fit =
      FitOfType(SurfaceType::kSphere, {.points = points, .normals = normals, .weights = {}});
  EXPECT_TRUE(fit.ok());
  return RegionOn(0, SurfaceType::kSphere, fit.surface, points);
}

TEST(RetypeBesideNeighbours, AChamferTypedASphereIsACone) {
  // The turned end's chamfer band as above, typed a sphere: over a band a
  // few spacings wide a sphere meets a cone's straight profile within its
  // sagitta (about 0.09 over the 2.1 slant, for a sphere of radius 6 on
  // the axis), and with the neighbours' points beyond both creases it fits
  // the band about as well as the cone does, with 2 parameters fewer. Set
  // beside its neighbours, the cone explains the band at the noise and the
  // sphere's sagitta stays: the cone scores kScoreMargin below it.
  const ChamferScene scene = MakeChamferScene();
  const std::vector<std::vector<Eigen::Vector3d>>& points = scene.points;
  const std::vector<Eigen::Vector3d>& normals = scene.band_normals;
  std::vector<Region> regions = {
      SphereRegion(points[0], normals),
      RegionOn(1, SurfaceType::kCylinder, Cylinder{.radius = 5.0}, points[1]),
      RegionOn(2, SurfaceType::kPlane, Plane{.point = {0, 0, 1.5}}, points[2])};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  // On its band alone the sphere stays.
  std::vector<Region> alone = regions;
  EXPECT_EQ(RetypeToPoints(points, kNoBand, kSigma, &alone, &surfaces), 0);
  ASSERT_EQ(alone[0].type, SurfaceType::kSphere);

  ExpectBandRetypedToTheChamferCone(points, &regions, &surfaces);
  if (regions[0].type != SurfaceType::kCone) return;
  EXPECT_LT(regions[0].rms_distance, 1.2 * kSigma);
  EXPECT_EQ(regions[1].type, SurfaceType::kCylinder);
  EXPECT_EQ(regions[2].type, SurfaceType::kPlane);
}

TEST(RetypeBesideNeighbours, ASphericalCapStaysASphere) {
  // A cylinder of radius 15 capped by a sphere of radius 20 meeting its rim
  // at a crease (about 41 degrees); the cap's region reaches 2.5 spacings
  // down the cylinder. Beside the cylinder an axial type leaves the cap's
  // curvature (its profile turns 49 degrees over 17 units) far above the
  // noise: the sphere stays.
  constexpr double kReach = 2.5 * kSpacing;
  constexpr double kRadius = 20.0;
  const double rim_angle = std::asin(15.0 / kRadius);  // from the pole
  const double rim_z = kRadius * std::cos(rim_angle);   // sphere centred at 0
  const Profile cap = [&](double s) -> ProfilePoint {
    if (s < kReach) return {15.0, rim_z - (kReach - s), 1.0, 0.0};  // the cylinder
    const double phi = rim_angle - (s - kReach) / kRadius;          // from the pole
    return {kRadius * std::sin(phi), kRadius * std::cos(phi), std::sin(phi), std::cos(phi)};
  };
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::vector<Eigen::Vector3d>> points(2);
  points[0] = Revolve(cap, kReach + kRadius * rim_angle, 4000, 11, &normals);
  const Profile side = [&](double s) -> ProfilePoint {
    return {15.0, rim_z - kReach - s, 1.0, 0.0};
  };
  points[1] = Revolve(side, 5.0, 3000, 12, nullptr);
  std::vector<Region> regions = {
      SphereRegion(points[0], normals),
      RegionOn(1, SurfaceType::kCylinder, Cylinder{.radius = 15.0}, points[1])};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  const std::vector<std::vector<int>> neighbours = {{1}, {0}};
  EXPECT_EQ(RetypeBesideNeighbours(points, neighbours, kSigma, &regions, &surfaces), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kSphere);
}

TEST(RetypeBesideNeighbours, ARoundTangentToItsNeighboursStaysATorus) {
  // A boss of radius 6 with its top edge (z = 0) rounded, tube radius 2
  // (about 10 spacings across): tangent to the top (r <= 4) and to the
  // side (z <= -2). Its region reaches a spacing beyond both tangent edges.
  // A cone fitted beside the two neighbours meets the round's middle and
  // leaves its curvature between them (0.15 at most, a tenth of a radian
  // from the tangencies); the torus fits at the noise.
  constexpr double kTube = 2.0;
  const double quarter = 0.5 * std::numbers::pi * kTube;
  const Profile band = [&](double s) -> ProfilePoint {
    if (s < kSpacing) return {4.0 - (kSpacing - s), 0.0, 0.0, 1.0};  // the top
    if (s < kSpacing + quarter) {                                      // the round
      const double phi = (s - kSpacing) / kTube;
      return {4.0 + kTube * std::sin(phi), -kTube + kTube * std::cos(phi), std::sin(phi),
              std::cos(phi)};
    }
    return {6.0, -kTube - (s - kSpacing - quarter), 1.0, 0.0};  // the side
  };
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::vector<Eigen::Vector3d>> points(3);
  points[0] = Revolve(band, quarter + 2.0 * kSpacing, 2000, 6, &normals);
  points[1] = Revolve([](double s) -> ProfilePoint { return {s, 0.0, 0.0, 1.0}; }, 4.0, 1500, 7,
                      nullptr);
  points[2] = Revolve([&](double s) -> ProfilePoint { return {6.0, -kTube - s, 1.0, 0.0}; }, 4.0,
                      3000, 8, nullptr);
  std::vector<Region> regions = {
      TorusRegion(points[0], normals),
      RegionOn(1, SurfaceType::kPlane, Plane{}, points[1]),
      RegionOn(2, SurfaceType::kCylinder, Cylinder{.radius = 6.0}, points[2])};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  const std::vector<std::vector<int>> neighbours = {{1, 2}, {0}, {0}};
  EXPECT_EQ(RetypeBesideNeighbours(points, neighbours, kSigma, &regions, &surfaces), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kTorus);
  EXPECT_NEAR(std::get<Torus>(regions[0].surface).minor_radius, kTube, 0.05);
}

TEST(RetypeBesideNeighbours, ARegionWithoutNeighboursIsLeftToRetypeToPoints) {
  // The chamfer's band as above but no neighbour with points: nothing here
  // sets its neighbours' points aside, and it keeps its type.
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::vector<Eigen::Vector3d>> points(2);
  points[0] = Revolve(ChamferBand(2.5 * kSpacing), kChamferSlant + 5.0 * kSpacing, 2000, 3,
                      &normals);
  std::vector<Region> regions = {TorusRegion(points[0], normals),
                                 RegionOn(1, SurfaceType::kCylinder, Cylinder{.radius = 5.0},
                                          {Eigen::Vector3d(5, 0, -1)})};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  // Region 1 touches it but has no points of its own (a patch closing an
  // unscanned area).
  const std::vector<std::vector<int>> neighbours = {{1}, {0}};
  EXPECT_EQ(RetypeBesideNeighbours(points, neighbours, kSigma, &regions, &surfaces), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kTorus);
}

TEST(RetypeBesideNeighbours, AFragmentOfANeighboursSurfaceKeepsItsType) {
  // A small region typed a torus (tube 1 around a circle of radius 4, its
  // outer equator on the cylinder of radius 5) whose points lie on its
  // neighbour, that cylinder, within a spacing of the equator: the
  // neighbour explains them without it, and a cylinder fitted to those its
  // own surface happens to be nearer is no evidence of a type.
  std::vector<std::vector<Eigen::Vector3d>> points(2);
  points[0] = Revolve([](double s) -> ProfilePoint { return {5.0, s - kSpacing, 1.0, 0.0}; },
                      2.0 * kSpacing, 300, 9, nullptr);
  points[1] = Revolve([](double s) -> ProfilePoint { return {5.0, -kSpacing - s, 1.0, 0.0}; },
                      4.0, 3000, 10, nullptr);
  std::vector<Region> regions = {
      RegionOn(0, SurfaceType::kTorus, Torus{.major_radius = 4.0, .minor_radius = 1.0},
               points[0]),
      RegionOn(1, SurfaceType::kCylinder, Cylinder{.radius = 5.0}, points[1])};
  std::vector<SharedSurface> surfaces = OwnSurfaces(regions);
  const std::vector<std::vector<int>> neighbours = {{1}, {0}};
  EXPECT_EQ(RetypeBesideNeighbours(points, neighbours, kSigma, &regions, &surfaces), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kTorus);
}

TEST(RegionNeighbours, RegionsSharingAnEdge) {
  // A strip of 4 unit squares in a row, two triangles each, labelled
  // 0, 1, -1, 2 by square: 1 and 2 do not touch (the unlabelled square
  // lies between them).
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (int x = 0; x <= 4; ++x) {
    v.push_back(m.add_vertex({static_cast<double>(x), 0.0, 0.0}));
    v.push_back(m.add_vertex({static_cast<double>(x), 1.0, 0.0}));
  }
  for (int x = 0; x < 4; ++x) {
    m.add_face(v[2 * x], v[2 * x + 2], v[2 * x + 3]);
    m.add_face(v[2 * x], v[2 * x + 3], v[2 * x + 1]);
  }
  const std::vector<int> labels = {0, 0, 1, 1, -1, -1, 2, 2};
  const std::vector<std::vector<int>> n = RegionNeighbours(m, labels, 4);
  EXPECT_EQ(n[0], std::vector<int>{1});
  EXPECT_EQ(n[1], std::vector<int>{0});
  EXPECT_TRUE(n[2].empty());
  EXPECT_TRUE(n[3].empty());
}

}  // namespace
}  // namespace meshseg::pipeline_internal
