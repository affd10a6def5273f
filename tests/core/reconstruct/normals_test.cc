#include "reconstruct/normals.h"

#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

// Points on a box surface (sharp edges) and their outward normals.
void BoxSamples(int count, std::vector<Eigen::Vector3d>* points,
                std::vector<Eigen::Vector3d>* outward) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> face(0, 5);
  const Eigen::Vector3d half(1.0, 0.6, 0.4);
  for (int i = 0; i < count; ++i) {
    const int f = face(rng);
    Eigen::Vector3d p(u(rng) * half.x(), u(rng) * half.y(), u(rng) * half.z());
    const double sign = f % 2 ? 1.0 : -1.0;
    p[f / 2] = sign * half[f / 2];
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    n[f / 2] = sign;
    points->push_back(p);
    outward->push_back(n);
  }
}

// Fraction of normals within acos(min_cos) of the true inward normal.
double InwardFraction(const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<Eigen::Vector3d>& outward, double min_cos = 0.9) {
  int inward = 0;
  for (size_t i = 0; i < normals.size(); ++i) inward += normals[i].dot(-outward[i]) > min_cos;
  return static_cast<double>(inward) / normals.size();
}

void SphereSamples(int count, std::vector<Eigen::Vector3d>* points,
                   std::vector<Eigen::Vector3d>* outward) {
  std::mt19937 rng(6);
  std::normal_distribution<double> g;
  for (int i = 0; i < count; ++i) {
    outward->push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
    points->push_back(outward->back());
  }
}

TEST(InwardNormals, EstimatedNormalsAreConsistentAndPointInward) {
  std::vector<Eigen::Vector3d> points, outward;
  BoxSamples(6000, &points, &outward);
  const mesh_internal::PointIndex index(points);
  const auto r = InwardNormals(points, {}, NearestOthers(points, index, 10), {});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_GE(InwardFraction(r->normals, outward, 0.0), 0.995);  // consistently inward
  EXPECT_GE(InwardFraction(r->normals, outward), 0.9);         // PCA tilts them at the edges
}

TEST(InwardNormals, GivenOutwardNormalsAreFlipped) {
  std::vector<Eigen::Vector3d> points, outward;
  BoxSamples(2000, &points, &outward);
  const mesh_internal::PointIndex index(points);
  const auto r = InwardNormals(points, outward, NearestOthers(points, index, 10), {});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE(r->flipped);
  EXPECT_DOUBLE_EQ(InwardFraction(r->normals, outward), 1.0);
}

TEST(InwardNormals, GivenInwardNormalsAreKept) {
  std::vector<Eigen::Vector3d> points, outward;
  BoxSamples(2000, &points, &outward);
  std::vector<Eigen::Vector3d> inward;
  for (const auto& n : outward) inward.push_back(-n);
  const mesh_internal::PointIndex index(points);
  const auto r = InwardNormals(points, inward, NearestOthers(points, index, 10), {});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_FALSE(r->flipped);
  EXPECT_DOUBLE_EQ(InwardFraction(r->normals, outward), 1.0);
}

// On a smooth surface; at a sharp edge, normals given exactly perpendicular
// carry no orientation across it.
TEST(InwardNormals, InconsistentGivenNormalsAreReoriented) {
  std::vector<Eigen::Vector3d> points, outward;
  SphereSamples(4000, &points, &outward);
  std::vector<Eigen::Vector3d> mixed = outward;
  for (size_t i = 0; i < mixed.size(); i += 2) mixed[i] = -mixed[i];
  const mesh_internal::PointIndex index(points);
  const auto r = InwardNormals(points, mixed, NearestOthers(points, index, 10), {});
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_GE(InwardFraction(r->normals, outward), 0.99);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
