#include "pipeline/refit_regions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "gtest/gtest.h"

namespace meshseg::pipeline_internal {
namespace {

constexpr double kTolerance = 0.1;  // th_dis
// No band: every type judged on all the points as given.
constexpr double kNoBand = std::numeric_limits<double>::infinity();

// An open tube of radius 5 along z, its vertices exactly on the cylinder:
// 24 segments, 4 rings 2 apart.
TriMesh Tube() {
  TriMesh m;
  constexpr int kSegments = 24, kRings = 4;
  std::vector<TriMesh::VertexHandle> v;
  for (int ring = 0; ring < kRings; ++ring) {
    for (int k = 0; k < kSegments; ++k) {
      const double t = 2.0 * std::numbers::pi * k / kSegments;
      v.push_back(m.add_vertex({5.0 * std::cos(t), 5.0 * std::sin(t), 2.0 * ring}));
    }
  }
  for (int ring = 0; ring + 1 < kRings; ++ring) {
    for (int k = 0; k < kSegments; ++k) {
      const int a = ring * kSegments + k, b = ring * kSegments + (k + 1) % kSegments;
      m.add_face(v[a], v[b], v[b + kSegments]);
      m.add_face(v[a], v[b + kSegments], v[a + kSegments]);
    }
  }
  return m;
}

TEST(RefitOnInputVertices, ChordFitBecomesExactOnTheInputVertices) {
  const TriMesh tube = Tube();
  // As fitted on a remesh lying on the chords: radius too small, axis tilted.
  Region region;
  region.type = SurfaceType::kCylinder;
  region.surface = Cylinder{.axis_origin = {0.05, 0.0, 3.0},
                            .axis_direction = Eigen::Vector3d(0.01, 0.0, 1.0).normalized(),
                            .radius = 4.95};
  std::vector<Region> regions = {region};
  RefitOnInputVertices(tube, std::vector<int>(tube.n_faces(), 0), kTolerance, &regions);
  const Cylinder& c = std::get<Cylinder>(regions[0].surface);
  EXPECT_NEAR(c.radius, 5.0, 1e-9);
  EXPECT_NEAR(std::abs(c.axis_direction.z()), 1.0, 1e-12);
  EXPECT_LT(regions[0].rms_distance, 1e-9);
  EXPECT_LT(regions[0].max_distance, 1e-9);
}

TEST(RefitOnInputVertices, KeepsTheSurfaceWhenTheRefitIsNoCloser) {
  const TriMesh tube = Tube();
  Region region;
  region.type = SurfaceType::kCylinder;
  region.surface = Cylinder{.axis_origin = {0, 0, 0}, .axis_direction = {0, 0, 1}, .radius = 5.0};
  region.rms_distance = 123.0;  // stale value from the remesh
  std::vector<Region> regions = {region};
  RefitOnInputVertices(tube, std::vector<int>(tube.n_faces(), 0), kTolerance, &regions);
  // Already exact: whichever is kept, the distances are those of the input.
  EXPECT_NEAR(std::get<Cylinder>(regions[0].surface).radius, 5.0, 1e-9);
  EXPECT_LT(regions[0].rms_distance, 1e-9);
}

TEST(RefitOnInputVertices, AConeThatDoesNotWidenOnTheInputIsACylinder) {
  // As fitted on a remesh's chords: a cone of half angle 0.2 degrees, 0.02
  // wider over the tube's 6 of length than at its start, under th_dis 0.1.
  const TriMesh tube = Tube();
  const double half_angle = 0.2 * std::numbers::pi / 180.0;
  Region region;
  region.type = SurfaceType::kCone;
  region.surface = Cone{.apex = {0.0, 0.0, -5.0 / std::tan(half_angle)},
                        .axis_direction = {0, 0, 1},
                        .half_angle = half_angle};
  std::vector<Region> regions = {region};
  RefitOnInputVertices(tube, std::vector<int>(tube.n_faces(), 0), kTolerance, &regions);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
  const auto* cylinder = std::get_if<Cylinder>(&regions[0].surface);
  ASSERT_NE(cylinder, nullptr);
  EXPECT_NEAR(cylinder->radius, 5.0, 1e-9);
  EXPECT_LT(regions[0].rms_distance, 1e-9);
}

TEST(RefitOnInputVertices, AConeNoCloserThanTheCylinderIsACylinder) {
  // A quarter of the tube (its first 6 segments), as plate_holes.stl's
  // corner rounds in a jitter draw: a cone of 7.7 degrees on an axis 8.5
  // degrees off. The cone refit from there stops at rms 0.59; the
  // cylinder's own fit is exact.
  const TriMesh tube = Tube();
  std::vector<int> labels(tube.n_faces(), 1);
  for (const auto f : tube.faces()) {
    bool quarter = true;
    for (const auto v : tube.fv_range(f)) {
      const auto& p = tube.point(v);
      quarter = quarter && p[0] > -1e-9 && p[1] > -1e-9;
    }
    if (quarter) labels[f.idx()] = 0;
  }
  const double half_angle = 7.7 * std::numbers::pi / 180.0;
  const double tilt = 8.5 * std::numbers::pi / 180.0;
  const Eigen::Vector3d axis(std::sin(tilt) / std::sqrt(2.0), std::sin(tilt) / std::sqrt(2.0),
                             std::cos(tilt));
  std::vector<Region> regions(2);
  regions[0].type = SurfaceType::kCone;
  regions[0].surface = Cone{.apex = Eigen::Vector3d(0, 0, 3) - 5.0 / std::tan(half_angle) * axis,
                            .axis_direction = axis,
                            .half_angle = half_angle};
  regions[1].id = 1;
  regions[1].type = SurfaceType::kCylinder;
  regions[1].surface =
      Cylinder{.axis_origin = {0, 0, 0}, .axis_direction = {0, 0, 1}, .radius = 5.0};
  RefitOnInputVertices(tube, labels, kTolerance, &regions);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder) << regions[0].rms_distance;
  EXPECT_LT(regions[0].rms_distance, 1e-9);
}

TEST(RefitOnInputVertices, RegionWithoutFacesKeepsItsSurface) {
  const TriMesh tube = Tube();
  std::vector<Region> regions(2);
  regions[1].id = 1;
  regions[1].type = SurfaceType::kPlane;
  regions[1].surface = Plane{.point = {0, 0, 7}, .normal = {0, 0, 1}};
  RefitOnInputVertices(tube, std::vector<int>(tube.n_faces(), 0), kTolerance, &regions);
  const Plane& p = std::get<Plane>(regions[1].surface);
  EXPECT_EQ(p.point.z(), 7.0);
  EXPECT_EQ(regions[1].rms_distance, 0.0);
}

// The tube as one cylinder region (0) and a plane (1) tangent to it along
// the line at angle 0: x = 5.
std::vector<Region> CylinderAndTangentPlane() {
  std::vector<Region> regions(2);
  regions[0].type = SurfaceType::kCylinder;
  regions[0].surface =
      Cylinder{.axis_origin = {0, 0, 0}, .axis_direction = {0, 0, 1}, .radius = 5.0};
  regions[1].id = 1;
  regions[1].type = SurfaceType::kPlane;
  regions[1].surface = Plane{.point = {5, 0, 0}, .normal = {1, 0, 0}};
  return regions;
}

TEST(RelabelFacesOffTheirSurface, AFaceOnItsNeighboursSurfaceGoesThere) {
  // Face 0 spans angles 0 to 15 degrees: one edge on the tangent line, the
  // other 5 (1 - cos 15) = 0.17 inside the plane; its corners are on the
  // cylinder. Labelled with the plane, it goes to the cylinder.
  const TriMesh tube = Tube();
  std::vector<int> labels(tube.n_faces(), 0);
  labels[0] = 1;
  EXPECT_EQ(RelabelFacesOffTheirSurface(tube, CylinderAndTangentPlane(), 1e-6, &labels), 1);
  EXPECT_EQ(labels, std::vector<int>(tube.n_faces(), 0));
}

TEST(RelabelFacesOffTheirSurface, AFaceOnItsOwnSurfaceStays) {
  // Face 0 labelled with the plane through its own corners: exact, it stays,
  // though the cylinder beside it holds its corners too.
  const TriMesh tube = Tube();
  std::vector<Region> regions = CylinderAndTangentPlane();
  const double t = std::numbers::pi / 12;  // 15 degrees
  regions[1].surface = Plane{.point = {5, 0, 0}, .normal = {std::cos(t / 2), std::sin(t / 2), 0}};
  std::vector<int> labels(tube.n_faces(), 0);
  labels[0] = 1;
  EXPECT_EQ(RelabelFacesOffTheirSurface(tube, regions, 1e-6, &labels), 0);
  EXPECT_EQ(labels[0], 1);
}

// `count` points on the cylinder of radius `radius` about the z axis, over
// the angles [0, arc) and the heights between 0 and `length` (negative:
// below z = 0), with Gaussian noise `sigma` across it, drawn from `seed`.
std::vector<Eigen::Vector3d> NoisyCylinderPoints(unsigned seed, int count, double radius,
                                                 double arc, double length, double sigma) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < count; ++k) {
    const double t = arc * unit(random);
    const double r = radius + noise(random);
    points.emplace_back(r * std::cos(t), r * std::sin(t), length * unit(random));
  }
  return points;
}

// Points on the wall of a bore of radius 3.5 around the z axis, from its rim
// (z = 0) down to depth `depth`, all around, with Gaussian noise `sigma`
// across the wall: the band a scan from above sees near a rim.
std::vector<Eigen::Vector3d> BoreBand(double depth, double sigma) {
  return NoisyCylinderPoints(7, 1500, 3.5, 2.0 * std::numbers::pi, -depth, sigma);
}

// One region of `type`, fitted to `points`.
std::vector<Region> RegionFittedAs(SurfaceType type, const std::vector<Eigen::Vector3d>& points) {
  const FitResult fit = FitOfType(type, {.points = points, .normals = {}, .weights = {}});
  EXPECT_TRUE(fit.ok()) << SurfaceTypeName(type);
  std::vector<Region> regions(1);
  regions[0].type = type;
  regions[0].surface = fit.surface;
  regions[0].rms_distance = fit.rms_distance;
  regions[0].max_distance = fit.max_distance;
  return regions;
}

TEST(RetypeToPoints, ABoreBandTypedAsASphereIsACylinderOnItsPoints) {
  // Depth 3: a sphere of the bore's radius leaves the band by about
  // d^2 / 2R = 1.3 at the bottom, and its best fit misses the points by
  // three times the noise 0.03 the cylinder meets. Depth 1: the sphere's rms
  // is only 5 % above the cylinder's, but 1500 points tell the two apart (a
  // likelihood ratio of about e^65). The cylinder has a parameter more and
  // takes over all the same.
  constexpr double kSigma = 0.03;
  for (const double depth : {3.0, 1.0}) {
    const std::vector<std::vector<Eigen::Vector3d>> points = {BoreBand(depth, kSigma)};
    std::vector<Region> regions = RegionFittedAs(SurfaceType::kSphere, points[0]);
    std::vector<SharedSurface> surfaces;
    EXPECT_EQ(RetypeToPoints(points, kNoBand, kSigma, &regions, &surfaces), 1) << depth;
    ASSERT_EQ(regions[0].type, SurfaceType::kCylinder) << depth;
    EXPECT_NEAR(std::get<Cylinder>(regions[0].surface).radius, 3.5, 0.01) << depth;
    EXPECT_LT(regions[0].rms_distance, 1.1 * kSigma) << depth;
    ASSERT_EQ(surfaces.size(), 1u);
    EXPECT_EQ(surfaces[0].type, SurfaceType::kCylinder);
    EXPECT_EQ(surfaces[0].regions, std::vector<int>{0});
  }
}

TEST(RetypeToPoints, ABandTooShortToTellKeepsItsType) {
  // Depth 0.3: the sphere through the band's rims leaves it by at most
  // d^2 / 8R = 0.003 in between, a tenth of the noise: the points do not
  // decide, and the region keeps the type it has, either way.
  constexpr double kSigma = 0.03;
  const std::vector<std::vector<Eigen::Vector3d>> points = {BoreBand(0.3, kSigma)};
  for (const SurfaceType type : {SurfaceType::kSphere, SurfaceType::kCylinder}) {
    std::vector<Region> regions = RegionFittedAs(type, points[0]);
    std::vector<SharedSurface> surfaces;
    EXPECT_EQ(RetypeToPoints(points, kNoBand, kSigma, &regions, &surfaces), 0)
        << SurfaceTypeName(type);
    EXPECT_EQ(regions[0].type, type);
  }
}

TEST(RetypeToPoints, ACylinderBandStaysACylinder) {
  // No more general type of its family (cone, torus) takes over by fitting
  // the noise.
  constexpr double kSigma = 0.03;
  const std::vector<std::vector<Eigen::Vector3d>> points = {BoreBand(3.0, kSigma)};
  std::vector<Region> regions = RegionFittedAs(SurfaceType::kCylinder, points[0]);
  std::vector<SharedSurface> surfaces;
  EXPECT_EQ(RetypeToPoints(points, kNoBand, kSigma, &regions, &surfaces), 0);
  EXPECT_EQ(regions[0].type, SurfaceType::kCylinder);
}

TEST(RetypeToPoints, AChamferWithItsCreaseBandsStaysACone) {
  // A 45-degree chamfer from radius 5 at z = 0 to 3.5 at z = 1.5, and the
  // points a reconstruction's rounded creases give it from beyond its
  // edges: the cylinder below (z from -0.4 to 0) and the flat top (radius
  // 3.1 to 3.5). Both flanks turn the same way, so a sphere bends to them
  // and fits these points better than the cone; it is not taken.
  constexpr double kSigma = 0.03;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, kSigma);
  std::vector<std::vector<Eigen::Vector3d>> points(1);
  for (int k = 0; k < 1500; ++k) {
    const double t = 2.0 * std::numbers::pi * unit(random);
    const Eigen::Vector3d radial(std::cos(t), std::sin(t), 0.0);
    const double e = noise(random);
    const double u = unit(random);
    if (k % 5 == 0) {  // the cylinder's crease band
      points[0].push_back((5.0 + e) * radial + Eigen::Vector3d(0, 0, -0.4 * u));
    } else if (k % 5 == 1) {  // the top's
      points[0].push_back((3.1 + 0.4 * u) * radial + Eigen::Vector3d(0, 0, 1.5 + e));
    } else {
      const Eigen::Vector3d n(std::sqrt(0.5) * std::cos(t), std::sqrt(0.5) * std::sin(t),
                              std::sqrt(0.5));
      points[0].push_back((5.0 - 1.5 * u) * radial + Eigen::Vector3d(0, 0, 1.5 * u) + e * n);
    }
  }
  // Also with each type on its own band of 3 sigma.
  for (const double band : {kNoBand, 3.0 * kSigma}) {
    std::vector<Region> regions = RegionFittedAs(SurfaceType::kCone, points[0]);
    std::vector<SharedSurface> surfaces;
    EXPECT_EQ(RetypeToPoints(points, band, kSigma, &regions, &surfaces), 0) << band;
    EXPECT_EQ(regions[0].type, SurfaceType::kCone) << band;
  }
}

// A region's points as a reconstruction gives them where a flat side meets
// a flat top at a right angle: the side x = 0 seen from z = 0 up to the
// crease at z = kSideHeight (y from 0 to 20), and the top's points within
// `crease_width` of the crease (x from -crease_width to 0), which fall
// nearest to the side's faces where the mesh rounds the crease. Uniform
// over the area, Gaussian noise `sigma` across each plane.
std::vector<Eigen::Vector3d> SideWithCreaseBand(double crease_width, double sigma) {
  constexpr double kSideHeight = 4.0;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  const double side_share = kSideHeight / (kSideHeight + crease_width);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 2500; ++k) {
    const double y = 20.0 * unit(random);
    if (unit(random) < side_share) {
      points.emplace_back(noise(random), y, kSideHeight * unit(random));
    } else {
      points.emplace_back(-crease_width * unit(random), y, kSideHeight + noise(random));
    }
  }
  return points;
}

// One region of `type` fitted as the pipeline fits a region to its points:
// to all of them, then again to those within `band` of that fit (returned
// in `band_points`).
std::vector<Region> RegionFittedToItsBand(SurfaceType type,
                                          const std::vector<Eigen::Vector3d>& points, double band,
                                          std::vector<Eigen::Vector3d>* band_points) {
  std::vector<Region> regions = RegionFittedAs(type, points);
  band_points->clear();
  for (const Eigen::Vector3d& p : points) {
    if (std::abs(SignedDistance(regions[0].surface, p)) <= band) band_points->push_back(p);
  }
  RefitToPoints(std::vector<std::vector<Eigen::Vector3d>>{*band_points}, kTolerance, &regions);
  return regions;
}

TEST(RetypeToPoints, AFlatSideWithACreaseBandTypedAsACylinderIsAPlane) {
  // A cylinder bent into the crease band: within its band it keeps the
  // crease's points and drops side points it misses, so on that band a
  // plane fits worse than it and the cylinder stays (the old criterion).
  // Each type on its own band, scored on all the points: the plane explains
  // the side at the noise and leaves only the crease band's points at the
  // band's edge, the cylinder leaves side points there.
  constexpr double kSigma = 0.077, kBand = 0.31;
  const std::vector<std::vector<Eigen::Vector3d>> points = {SideWithCreaseBand(1.2, kSigma)};
  std::vector<std::vector<Eigen::Vector3d>> band_points(1);
  std::vector<Region> regions =
      RegionFittedToItsBand(SurfaceType::kCylinder, points[0], kBand, &band_points[0]);
  ASSERT_EQ(regions[0].type, SurfaceType::kCylinder);
  std::vector<Region> on_its_band = regions;
  std::vector<SharedSurface> surfaces;
  EXPECT_EQ(RetypeToPoints(band_points, kNoBand, kSigma, &on_its_band, &surfaces), 0)
      << "rms " << regions[0].rms_distance << " of " << band_points[0].size();

  // The side's points below the crease band, and how many a band holds.
  auto side_points = [](const std::vector<Eigen::Vector3d>& points) {
    return std::count_if(points.begin(), points.end(),
                         [](const Eigen::Vector3d& p) { return p.z() < 4.0 - kBand; });
  };
  const double side = static_cast<double>(side_points(points[0]));
  const auto cylinder_side = side_points(band_points[0]);
  const double cylinder_rms = regions[0].rms_distance;
  EXPECT_EQ(RetypeToPoints(points, kBand, kSigma, &regions, &surfaces, &band_points), 1);
  ASSERT_EQ(regions[0].type, SurfaceType::kPlane);
  // The side's plane, tilted by the crease band's points within kBand of
  // it (up to 0.31 inside the top): within 5 degrees, through the side's
  // middle within the noise.
  const Plane& plane = std::get<Plane>(regions[0].surface);
  EXPECT_GT(std::abs(plane.normal.x()), std::cos(5.0 * std::numbers::pi / 180.0))
      << plane.normal.transpose();
  EXPECT_LT(std::abs(SignedDistance(plane, Eigen::Vector3d(0.0, 10.0, 2.0))), kSigma);
  EXPECT_LT(regions[0].rms_distance, cylinder_rms);
  // Its band holds more of the side's points than the cylinder's: all but
  // the noise's tail across the tilted plane (it may hold fewer of the
  // crease band's).
  EXPECT_GT(side_points(band_points[0]), cylinder_side);
  EXPECT_GT(side_points(band_points[0]), 0.99 * side);
}

// Points on a strip of the cylinder of radius 6 around the y axis, over
// `degrees` of arc from the top (z = 6) down its side, y from 0 to 20, with
// Gaussian noise `sigma` across it.
std::vector<Eigen::Vector3d> CylinderStrip(double degrees, double sigma) {
  std::vector<Eigen::Vector3d> points =
      NoisyCylinderPoints(9, 2500, 6.0, degrees * std::numbers::pi / 180.0, 20.0, sigma);
  // (r cos t, r sin t, y) about z to (r sin t, y, r cos t) about y.
  for (Eigen::Vector3d& p : points) p = Eigen::Vector3d(p.y(), p.z(), p.x());
  return points;
}

TEST(RetypeToPoints, ACylinderStripOnItsOwnBandStaysACylinder) {
  // 40 and 90 degrees of a radius-6 cylinder: a plane's band keeps the
  // strip's middle and leaves its ends at the band's edge (sagitta 0.7 and
  // 1.8 over the band's 0.31), the cylinder explains them all at the noise.
  constexpr double kSigma = 0.077, kBand = 0.31;
  for (const double degrees : {40.0, 90.0}) {
    const std::vector<std::vector<Eigen::Vector3d>> points = {CylinderStrip(degrees, kSigma)};
    std::vector<std::vector<Eigen::Vector3d>> band_points(1);
    std::vector<Region> regions =
        RegionFittedToItsBand(SurfaceType::kCylinder, points[0], kBand, &band_points[0]);
    const std::vector<std::vector<Eigen::Vector3d>> its_band = band_points;
    std::vector<SharedSurface> surfaces;
    EXPECT_EQ(RetypeToPoints(points, kBand, kSigma, &regions, &surfaces, &band_points), 0)
        << degrees;
    EXPECT_EQ(regions[0].type, SurfaceType::kCylinder) << degrees;
    EXPECT_TRUE(band_points == its_band) << degrees;
  }
}

}  // namespace
}  // namespace meshseg::pipeline_internal
