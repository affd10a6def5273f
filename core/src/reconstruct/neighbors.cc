#include "reconstruct/neighbors.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// Fills `row` with the k nearest others of point i (see NeighborTable).
void FillRow(const std::vector<Eigen::Vector3d>& points, const mesh_internal::PointIndex& index,
             size_t i, int k, std::vector<uint32_t>* idx, std::vector<double>* d2, uint32_t* row) {
  index.Nearest(points[i], k + 1, idx, d2);
  int out = 0;
  for (size_t j = 0; j < idx->size() && out < k; ++j) {
    if ((*idx)[j] != i) row[out++] = (*idx)[j];
  }
  while (out < k) row[out++] = static_cast<uint32_t>(i);
}

}  // namespace

NeighborTable NearestOthers(const std::vector<Eigen::Vector3d>& points,
                            const mesh_internal::PointIndex& index, int k) {
  NeighborTable table;
  table.k = k;
  table.index.resize(points.size() * static_cast<size_t>(k));
  const std::vector<uint32_t> order = index.SpatialOrder();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, order.size()), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t o = range.begin(); o != range.end(); ++o) {
      const size_t i = order[o];
      FillRow(points, index, i, k, &idx, &d2, table.index.data() + i * k);
    }
  });
  return table;
}

NeighborTable FirstColumns(const NeighborTable& table, int k) {
  NeighborTable out;
  out.k = k;
  out.index.resize(table.size() * static_cast<size_t>(k));
  for (size_t i = 0; i < table.size(); ++i) {
    std::copy_n(table.Row(i), k, out.index.data() + i * k);
  }
  return out;
}

NeighborTable KeptNeighbors(const NeighborTable& all, const std::vector<uint8_t>& removed,
                            const std::vector<Eigen::Vector3d>& kept,
                            const mesh_internal::PointIndex& kept_index) {
  const int k = all.k;
  std::vector<uint32_t> renumber(all.size(), 0);
  std::vector<uint32_t> original;  // kept position → index among all
  original.reserve(kept.size());
  for (size_t i = 0; i < all.size(); ++i) {
    if (removed[i]) continue;
    renumber[i] = static_cast<uint32_t>(original.size());
    original.push_back(static_cast<uint32_t>(i));
  }
  NeighborTable out;
  out.k = k;
  out.index.resize(original.size() * static_cast<size_t>(k));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, original.size()), [&](const auto& range) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    for (size_t c = range.begin(); c != range.end(); ++c) {
      const uint32_t* row = all.Row(original[c]);
      uint32_t* to = out.index.data() + c * k;
      if (std::any_of(row, row + k, [&](uint32_t j) { return removed[j] != 0; })) {
        FillRow(kept, kept_index, c, k, &idx, &d2, to);
        continue;
      }
      for (int j = 0; j < k; ++j) to[j] = renumber[row[j]];
    }
  });
  return out;
}

}  // namespace meshseg::reconstruct_internal
