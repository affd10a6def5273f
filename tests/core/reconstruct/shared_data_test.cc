// Reconstruction of the real point clouds in shared/data, compared with their
// ground-truth meshes (SOURCES.md there).
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "clouds.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/reconstruct.h"

namespace meshseg {
namespace {

std::string DataPath(const std::string& name) {
  return std::string(MESHSEG_SHARED_DATA_DIR) + "/" + name;
}

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                             const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// Returns `count` points spread uniformly by area over the surface of `m`
// (fixed seed).
std::vector<Eigen::Vector3d> AreaSamples(const TriMesh& m, int count) {
  std::vector<std::array<Eigen::Vector3d, 3>> tris;
  std::vector<double> area;
  for (const auto f : m.faces()) {
    std::array<Eigen::Vector3d, 3> t;
    int i = 0;
    for (const auto v : f.vertices()) t[i++] = ToEigen(m.point(v));
    tris.push_back(t);
    area.push_back(0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm());
  }
  std::mt19937 rng(5);
  std::discrete_distribution<size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < count; ++i) {
    const auto& t = tris[pick(rng)];
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    out.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
  }
  return out;
}

// Sorted distances from `points` to the surface of `to` (brute force, with
// triangles skipped by their bounding boxes).
std::vector<double> PointsToSurface(const std::vector<Eigen::Vector3d>& points, const TriMesh& to) {
  struct Tri {
    Eigen::Vector3d a, b, c, lo, hi;
  };
  std::vector<Tri> tris;
  for (const auto f : to.faces()) {
    std::array<Eigen::Vector3d, 3> t;
    int i = 0;
    for (const auto v : f.vertices()) t[i++] = ToEigen(to.point(v));
    tris.push_back(
        {t[0], t[1], t[2], t[0].cwiseMin(t[1]).cwiseMin(t[2]), t[0].cwiseMax(t[1]).cwiseMax(t[2])});
  }
  std::vector<double> d;
  for (const auto& p : points) {
    double best = 1e300;
    for (const auto& t : tris) {
      const double box = (t.lo - p).cwiseMax(p - t.hi).cwiseMax(0.0).squaredNorm();
      if (box >= best * best) continue;
      best = std::min(best, PointTriangleDistance(p, t.a, t.b, t.c));
    }
    d.push_back(best);
  }
  std::sort(d.begin(), d.end());
  return d;
}

double Quantile(const std::vector<double>& sorted, double q) {
  return sorted[static_cast<size_t>(q * (sorted.size() - 1))];
}

struct Case {
  const char* cloud;
  const char* truth;
  ReconstructParams params;
  // Bounds on the distances, in point spacings, from area samples of the
  // reconstruction to the truth (accuracy) and of the truth to the
  // reconstruction (completeness).
  double max_median;
  double max_p95;
};

void CheckAgainstTruth(const Case& c) {
  const auto cloud = ReadPointCloud(DataPath(c.cloud));
  ASSERT_TRUE(cloud.ok()) << cloud.status();
  const auto truth = ReadMesh(DataPath(c.truth));
  ASSERT_TRUE(truth.ok()) << truth.status();
  const auto r = Reconstruct(*cloud, c.params);
  ASSERT_TRUE(r.ok()) << r.status();
  const TriMesh& m = r->mesh.tri;
  const double h = r->stats.point_spacing;
  EXPECT_EQ(test::BoundaryEdgeCount(m), 0);
  EXPECT_EQ(test::NonManifoldVertexCount(m), 0);
  EXPECT_EQ(test::ComponentCount(m), 1);
  constexpr int kSamples = 1000;
  const auto accuracy = PointsToSurface(AreaSamples(m, kSamples), truth->tri);
  const auto completeness = PointsToSurface(AreaSamples(truth->tri, kSamples), m);
  EXPECT_LE(Quantile(accuracy, 0.5), c.max_median * h);
  EXPECT_LE(Quantile(accuracy, 0.95), c.max_p95 * h);
  EXPECT_LE(Quantile(completeness, 0.5), c.max_median * h);
  EXPECT_LE(Quantile(completeness, 0.95), c.max_p95 * h);
  ::testing::Test::RecordProperty("accuracy_median_h", std::to_string(Quantile(accuracy, 0.5) / h));
  ::testing::Test::RecordProperty("accuracy_p95_h", std::to_string(Quantile(accuracy, 0.95) / h));
  ::testing::Test::RecordProperty("completeness_median_h",
                                  std::to_string(Quantile(completeness, 0.5) / h));
  ::testing::Test::RecordProperty("completeness_p95_h",
                                  std::to_string(Quantile(completeness, 0.95) / h));
}

// Clean samples of a CAD part with sharp edges; the p95 is set by the rounding
// of those edges (linear local functions, seed 001 §2.1.1).
TEST(ReconstructSharedData, BrokenBulletWithOutwardNormalsMatchesTruth) {
  CheckAgainstTruth({"broken_bullet_50k.xyz", "broken_bullet_gt.obj", {}, 0.3, 5.0});
}

// A simulated scan with uneven density and noise of about the point spacing
// (median 0.45 h from the truth, p95 1.7 h).
TEST(ReconstructSharedData, AbcScanWithoutNormalsMatchesTruth) {
  CheckAgainstTruth({"abc_00016513_scan.xyz", "abc_00016513_gt.ply", {}, 0.4, 2.5});
}

}  // namespace
}  // namespace meshseg
