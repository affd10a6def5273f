#include "reconstruct/neighbors.h"

#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

std::vector<Eigen::Vector3d> RandomPoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) points.emplace_back(u(rng), u(rng), 0.2 * u(rng));
  return points;
}

// The k nearest others of point i by brute force, nearest first.
std::vector<uint32_t> BruteForce(const std::vector<Eigen::Vector3d>& points, size_t i, int k) {
  std::vector<uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::erase(order, static_cast<uint32_t>(i));
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return (points[a] - points[i]).squaredNorm() < (points[b] - points[i]).squaredNorm();
  });
  order.resize(std::min<size_t>(k, order.size()));
  return order;
}

TEST(NearestOthers, RowsAreTheKNearestOtherPointsNearestFirst) {
  const auto points = RandomPoints(600, 1);
  const mesh_internal::PointIndex index(points);
  const NeighborTable table = NearestOthers(points, index, 8);
  ASSERT_EQ(table.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(std::vector<uint32_t>(table.Row(i), table.Row(i) + 8), BruteForce(points, i, 8)) << i;
  }
  const NeighborTable first = FirstColumns(table, 3);
  EXPECT_EQ(std::vector<uint32_t>(first.Row(7), first.Row(7) + 3), BruteForce(points, 7, 3));
}

TEST(NearestOthers, RowsOfATinyCloudArePaddedWithThePointItself) {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  const mesh_internal::PointIndex index(points);
  const NeighborTable table = NearestOthers(points, index, 4);
  EXPECT_EQ(std::vector<uint32_t>(table.Row(0), table.Row(0) + 4),
            (std::vector<uint32_t>{1, 2, 0, 0}));
}

// Removing a cluster of points: rows that named none of them are carried
// over renumbered, the others found again; either way the result is the
// table of the kept points.
TEST(KeptNeighbors, EqualsTheTableOfTheKeptPoints) {
  const auto points = RandomPoints(800, 2);
  const mesh_internal::PointIndex index(points);
  const NeighborTable all = NearestOthers(points, index, 10);
  std::vector<uint8_t> removed(points.size(), 0);
  std::vector<Eigen::Vector3d> kept;
  for (size_t i = 0; i < points.size(); ++i) {
    removed[i] = points[i].x() > 0.5 && points[i].y() > 0.5;
    if (!removed[i]) kept.push_back(points[i]);
  }
  ASSERT_GT(points.size() - kept.size(), 20u);
  const mesh_internal::PointIndex kept_index(kept);
  const NeighborTable from_all = KeptNeighbors(all, removed, kept, kept_index);
  const NeighborTable direct = NearestOthers(kept, kept_index, 10);
  EXPECT_EQ(from_all.k, 10);
  EXPECT_EQ(from_all.index, direct.index);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
