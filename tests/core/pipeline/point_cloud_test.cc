// RunPipeline on a point cloud: the vertices of a generated stepped shaft
// (known cylinders and planes) with a little noise and a few far outliers,
// written as XYZ. The pipeline reconstructs a mesh, segments it, and labels
// every input point.
#include "meshseg/point_cloud.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "meshseg/generate.h"
#include "meshseg/pipeline.h"

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
  out.path = (std::filesystem::path(::testing::TempDir()) / "stepped_shaft_points.xyz").string();
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

}  // namespace
}  // namespace meshseg
