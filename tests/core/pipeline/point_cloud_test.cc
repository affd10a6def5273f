// RunPipeline on a point cloud: the vertices of a generated stepped shaft
// (known cylinders and planes) with a little noise and a few far outliers,
// and issue 6's hard cloud of the generated test piece (part_clouds.h),
// written as XYZ. The pipeline reconstructs a mesh, segments it, and labels
// every input point.
#include "meshseg/point_cloud.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "clouds.h"
#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "part_clouds.h"
#include "scratch_dir.h"

namespace meshseg {
namespace {

constexpr double kVoxel = 0.5;           // h of the generated part, mm
constexpr double kNoise = 0.05;          // Gaussian noise per coordinate, in h
constexpr int kOutliers = 30;            // uniform in the bounding box ...
constexpr double kOutlierClearance = 4;  // ... but at least this far from the part, in h
// Tolerances on what the segmentation of the reconstructed mesh recovers.
constexpr double kRadiusTol = 0.3;   // in h (the reconstruction smooths)
constexpr double kAxisTolDeg = 3.0;  // cylinder axis vs the true axis
constexpr double kPlaneNormalTolDeg = 5.0;
constexpr double kLabelledSurfacePoints = 0.95;  // fraction of non-outliers with a label

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::abs(a.normalized().dot(b.normalized()));  // either orientation
  return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

struct Cloud {
  std::string path;
  int64_t surface_points = 0;  // the first ones; the outliers follow
  Eigen::Vector3d axis;        // of the shaft
};

Cloud WriteShaftCloud(const GeneratedPart& part) {
  const TriMesh& m = part.mesh.tri;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, kNoise * kVoxel);
  PointCloud cloud;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const auto v : m.vertices()) {
    const Eigen::Vector3d p = ToEigen(m.point(v));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    cloud.points.push_back(p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  Cloud out;
  out.surface_points = static_cast<int64_t>(cloud.points.size());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int64_t n = out.surface_points;
  while (static_cast<int64_t>(cloud.points.size()) < n + kOutliers) {
    const Eigen::Vector3d p =
        lo + (hi - lo).cwiseProduct(Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
    double nearest = std::numeric_limits<double>::max();
    for (int64_t i = 0; i < n; ++i) nearest = std::min(nearest, (cloud.points[i] - p).norm());
    if (nearest > kOutlierClearance * kVoxel) cloud.points.push_back(p);
  }
  out.path = testing_files::ScratchPath("stepped_shaft_points.xyz");
  EXPECT_TRUE(WritePointCloud(cloud, out.path).ok());
  for (const PrimitiveTruth& t : part.primitives) {
    if (const auto* c = std::get_if<Cylinder>(&t.surface)) out.axis = c->axis_direction;
  }
  return out;
}

TEST(RunPipelineOnPoints, FindsTheShaftCylindersAndPlanesAndLabelsEveryPoint) {
  const absl::StatusOr<GeneratedPart> part =
      GeneratePart("stepped_shaft", {.voxel_size = kVoxel, .noise = 0.0, .seed = 1});
  ASSERT_TRUE(part.ok()) << part.status();
  const Cloud cloud = WriteShaftCloud(*part);

  const absl::StatusOr<PipelineResult> r = RunPipeline(cloud.path);
  std::filesystem::remove(cloud.path);  // read once; the files are a few MB
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->from_point_cloud);
  ASSERT_EQ(r->point_count, cloud.surface_points + kOutliers);
  ASSERT_EQ(static_cast<int64_t>(r->point_labels.size()), r->point_count);
  EXPECT_EQ(static_cast<int64_t>(r->face_labels.size()), r->mesh.face_count);
  EXPECT_EQ(r->mesh.boundary_edge_count, 0) << "the reconstructed mesh is closed";

  // Every true cylinder (radii 12, 8, 5) is a cylinder region with its
  // radius and axis; the flat ends and the step show up as planes normal to
  // the axis.
  for (const PrimitiveTruth& t : part->primitives) {
    const auto* truth = std::get_if<Cylinder>(&t.surface);
    if (truth == nullptr) continue;
    bool found = false;
    for (const Region& region : r->regions) {
      const auto* c = std::get_if<Cylinder>(&region.surface);
      if (c != nullptr && std::abs(c->radius - truth->radius) < kRadiusTol * kVoxel &&
          AngleDeg(c->axis_direction, truth->axis_direction) < kAxisTolDeg) {
        found = true;
      }
    }
    EXPECT_TRUE(found) << t.name << ": no cylinder region of radius " << truth->radius;
  }
  int planes = 0;
  for (const Region& region : r->regions) {
    if (const auto* p = std::get_if<Plane>(&region.surface)) {
      planes += AngleDeg(p->normal, cloud.axis) < kPlaneNormalTolDeg;
    }
  }
  EXPECT_GE(planes, 2) << "the shaft's flat faces";

  // Far outliers get -1; nearly all surface points get the label of a region.
  for (int64_t i = cloud.surface_points; i < r->point_count; ++i) {
    EXPECT_EQ(r->point_labels[i], -1) << "outlier point " << i;
  }
  int64_t labelled = 0;
  for (int64_t i = 0; i < cloud.surface_points; ++i) {
    ASSERT_GE(r->point_labels[i], -1);
    ASSERT_LT(r->point_labels[i], static_cast<int>(r->regions.size()));
    labelled += r->point_labels[i] >= 0;
  }
  EXPECT_GE(labelled, kLabelledSurfacePoints * cloud.surface_points);
}

// The test piece as issue 6's hard cloud: 5 % uniform outliers in the
// bounding box, Gaussian noise 0.2 × spacing, a patch of radius 5 spacings
// missing from the front face; 40 000 surface points with normals, h ≈ 0.68 mm
// (about 4 edges of the reconstructed mesh across its quarter-rounds).
constexpr int kTestPiecePoints = 40000;

struct PartCloud {
  std::string path;
  int64_t point_count = 0;
  // One per surface point (the first ones; the outliers follow): the true
  // primitive it was sampled from, by the nearest vertex of the part.
  std::vector<int> primitive;
};

PartCloud WriteHardCloud(const GeneratedPart& part, unsigned seed) {
  const test::Shape shape = test::PartShape(part);
  const double h = test::Spacing(shape, kTestPiecePoints);
  const test::CloudSpec spec{.points = kTestPiecePoints,
                             .noise = 0.2,
                             .outliers = 0.05,
                             .hole_radius = 5 * h,
                             .hole_center = test::PrimitiveCenter(part, "front"),
                             .seed = seed};
  const PointCloud cloud = test::MakeCloud(shape, spec);
  PartCloud out;
  out.point_count = static_cast<int64_t>(cloud.points.size());
  const auto surface_end = cloud.points.end() - static_cast<int>(spec.outliers * spec.points);
  out.primitive = test::NearestPrimitive(part, {cloud.points.begin(), surface_end});
  out.path = testing_files::ScratchPath("test_piece_hard_" + std::to_string(seed) + ".xyz");
  EXPECT_TRUE(WritePointCloud(cloud, out.path).ok());
  return out;
}

// Per true primitive: the region holding most of its surface points.
struct Found {
  int region = -1;
  double share = 0.0;  // of the primitive's points in that region
};

std::vector<Found> MajorityRegions(const GeneratedPart& part, const PartCloud& cloud,
                                   const PipelineResult& r) {
  std::vector<std::map<int, int64_t>> votes(part.primitives.size());
  std::vector<int64_t> total(part.primitives.size(), 0);
  for (size_t i = 0; i < cloud.primitive.size(); ++i) {
    if (cloud.primitive[i] < 0) continue;
    ++total[cloud.primitive[i]];
    if (r.point_labels[i] >= 0) ++votes[cloud.primitive[i]][r.point_labels[i]];
  }
  std::vector<Found> out(part.primitives.size());
  for (size_t p = 0; p < votes.size(); ++p) {
    int64_t best = 0;
    for (const auto& [region, count] : votes[p]) {
      if (count > best) best = count, out[p].region = region;
    }
    out[p].share = total[p] > 0 ? static_cast<double>(best) / total[p] : 0.0;
  }
  return out;
}

std::string Describe(const Region& region) {
  std::ostringstream s;
  s << SurfaceTypeName(region.type) << " region " << region.id << " (area " << region.area
    << ", rms " << region.rms_distance;
  if (const auto* c = std::get_if<Cylinder>(&region.surface)) s << ", radius " << c->radius;
  s << ")";
  return s.str();
}

// The part of the criterion below that holds on every cloud tried (18 clouds
// of 40 000 points, with and without normals, cut or sign of f): the full bore (radius 8) and the
// half-cylinder groove (radius 7) end up in cylinder regions of their radius and axis. Measured on
// this cloud: radius 7.99 and 7.08, axes within 0.2 degrees.
TEST(RunPipelineOnPoints, FindsTheTestPieceBoreAndGrooveAsCylinders) {
  constexpr double kRadiusTolMm = 0.3;  // about 0.45 h
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece");
  ASSERT_TRUE(part.ok()) << part.status();
  const PartCloud cloud = WriteHardCloud(*part, 1);
  const absl::StatusOr<PipelineResult> r = RunPipeline(cloud.path);
  std::filesystem::remove(cloud.path);  // read once; the files are a few MB
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_EQ(r->point_count, cloud.point_count);
  EXPECT_EQ(r->mesh.boundary_edge_count, 0);
  const std::vector<Found> found = MajorityRegions(*part, cloud, *r);
  for (const PrimitiveTruth& t : part->primitives) {
    if (t.name != "bore" && t.name != "groove") continue;
    ASSERT_GE(found[t.id].region, 0) << t.name;
    const Region& region = r->regions[found[t.id].region];
    const auto* c = std::get_if<Cylinder>(&region.surface);
    ASSERT_NE(c, nullptr) << t.name << ": " << Describe(region);
    EXPECT_NEAR(c->radius, std::get<Cylinder>(t.surface).radius, kRadiusTolMm) << t.name;
    EXPECT_LT(AngleDeg(c->axis_direction, std::get<Cylinder>(t.surface).axis_direction),
              kAxisTolDeg)
        << t.name;
  }
}

// Issue 6: "segmenting the reconstructed test piece finds its cylinders and
// planes with the right types": for each of six clouds, the region holding
// most of the points of each plane and cylinder has its type.
// This failed on 5 of the 6 clouds while the pipeline segmented the marching-
// tetrahedra mesh itself (edges of 3.6 h, slivers, 40 % of the vertices sharp:
// planes merged into cones, planes typed as cylinders of radius 50-700). It
// passes on the refined mesh (reconstruct/refine.h): edges of 1.5 h on the
// points, 16 regions for the 15 true faces on cloud 2. Remeshing alone, without
// the projection onto the points, still failed on all six (boss_top typed as
// a cylinder, sphere or quadric).
TEST(RunPipelineOnPoints, FindsTheTestPieceCylindersAndPlanesWithTheRightTypes) {
  const absl::StatusOr<GeneratedPart> part = GeneratePart("test_piece");
  ASSERT_TRUE(part.ok()) << part.status();
  for (const unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    SCOPED_TRACE("cloud seed " + std::to_string(seed));
    const PartCloud cloud = WriteHardCloud(*part, seed);
    const absl::StatusOr<PipelineResult> r = RunPipeline(cloud.path);
    std::filesystem::remove(cloud.path);  // read once; the files are a few MB
    ASSERT_TRUE(r.ok()) << r.status();
    const std::vector<Found> found = MajorityRegions(*part, cloud, *r);
    for (const PrimitiveTruth& t : part->primitives) {
      const SurfaceType type = TypeOf(t.surface);
      if (type != SurfaceType::kPlane && type != SurfaceType::kCylinder) continue;
      ASSERT_GE(found[t.id].region, 0) << t.name << ": no region";
      const Region& region = r->regions[found[t.id].region];
      EXPECT_STREQ(SurfaceTypeName(region.type), SurfaceTypeName(type))
          << t.name << " (" << SurfaceTypeName(type) << ") is mostly in " << Describe(region)
          << ", " << found[t.id].share << " of its points";
    }
  }
}

// A box cloud: the points of a regular grid on the six sides of a 2 x 1.5 x 1
// box, `n` intervals per edge, each point once, written as XYZ (no normals).
std::string WriteBoxCloud(int n, const std::string& name) {
  const Eigen::Vector3d size(2.0, 1.5, 1.0);
  PointCloud cloud;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      for (int k = 0; k <= n; ++k) {
        if (i != 0 && i != n && j != 0 && j != n && k != 0 && k != n) continue;  // inside
        cloud.points.push_back(size.cwiseProduct(Eigen::Vector3d(i, j, k)) / n);
      }
    }
  }
  const std::string path = testing_files::ScratchPath(name);
  EXPECT_TRUE(WritePointCloud(cloud, path).ok());
  return path;
}

// A noise-free box cloud, once reconstructed, is six planes on the box's
// sides. Its smallest side (1.0) is 15 mean edges of the reconstructed mesh
// wide at 32 points per edge, wider than the curvature stage's pass-2 window
// (2 W2 = 10 edges), so the segmentation's noise estimate sees faces and not
// edges (at 16 points per edge, 7 edges wide, every window straddles an edge
// and the estimate is the edges' bend, a third of the box's thickness as
// th_dis, under which one torus fits the whole closed surface).
TEST(RunPipelineOnPoints, ABoxCloudIsSixPlanesOnItsSides) {
  constexpr double kNormalTolDeg = 1.0;
  constexpr double kOffsetTol = 0.01;  // the side's centre off the plane (grid step 0.031-0.0625)
  const std::string path = WriteBoxCloud(32, "box_points.xyz");
  const absl::StatusOr<PipelineResult> r = RunPipeline(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(r.ok()) << r.status();
  ASSERT_EQ(r->regions.size(), 6u);
  const Eigen::Vector3d size(2.0, 1.5, 1.0);
  std::set<std::pair<int, int>> sides;  // (axis, low 0 / high 1)
  for (const Region& region : r->regions) {
    const auto* p = std::get_if<Plane>(&region.surface);
    ASSERT_NE(p, nullptr) << SurfaceTypeName(region.type);
    int axis = 0;
    p->normal.cwiseAbs().maxCoeff(&axis);
    EXPECT_LT(AngleDeg(p->normal, Eigen::Vector3d::Unit(axis)), kNormalTolDeg);
    const int high = p->point[axis] > 0.5 * size[axis];
    Eigen::Vector3d centre = 0.5 * size;  // of the side
    centre[axis] = high * size[axis];
    EXPECT_LT(std::abs(p->normal.normalized().dot(centre - p->point)), kOffsetTol)
        << "axis " << axis << " side " << high;
    sides.emplace(axis, high);
  }
  EXPECT_EQ(sides.size(), 6u) << "one plane per side";
}

}  // namespace
}  // namespace meshseg
