#include "curvature/spatial_order.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

namespace meshseg::curvature_internal {
namespace {

constexpr int kBitsPerAxis = 10;  // 1024 cells per axis: finer than a walk
constexpr double kCells = static_cast<double>((1 << kBitsPerAxis) - 1);

// Cell coordinate of x in [lo, lo + extent] on kBitsPerAxis bits (a
// non-finite coordinate goes to cell 0: only the order, never a result,
// depends on it).
uint64_t Cell(double x, double lo, double extent) {
  const double t = extent > 0.0 ? (x - lo) / extent * kCells : 0.0;
  if (!(t > 0.0)) return 0;
  return t >= kCells ? static_cast<uint64_t>(kCells) : static_cast<uint64_t>(t);
}

// The bits of c spread to every third bit (bit b to bit 3b).
uint64_t Spread(uint64_t c) {
  uint64_t out = 0;
  for (int b = 0; b < kBitsPerAxis; ++b) out |= ((c >> b) & 1) << (3 * b);
  return out;
}

}  // namespace

OrderedGraph MortonOrderedGraph(const TriMesh& mesh) {
  const int n = static_cast<int>(mesh.n_vertices());
  OrderedGraph r;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (int v = 0; v < n; ++v) {
    const Eigen::Vector3d p = ToEigen(mesh.point(TriMesh::VertexHandle(v)));
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d extent = hi - lo;
  // Key = Morton code of the cell above the vertex index: sorting the keys
  // sorts by cell, then by index, and the order is unique.
  std::vector<uint64_t> key(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int v = b.begin(); v < b.end(); ++v) {
      const Eigen::Vector3d p = ToEigen(mesh.point(TriMesh::VertexHandle(v)));
      const uint64_t code = Spread(Cell(p.x(), lo.x(), extent.x())) |
                            Spread(Cell(p.y(), lo.y(), extent.y())) << 1 |
                            Spread(Cell(p.z(), lo.z(), extent.z())) << 2;
      key[v] = code << 32 | static_cast<uint32_t>(v);
    }
  });
  tbb::parallel_sort(key.begin(), key.end());
  r.order.resize(n);
  r.rank.resize(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& b) {
    for (int k = b.begin(); k < b.end(); ++k) {
      r.order[k] = static_cast<int>(key[k] & 0xffffffffu);
      r.rank[r.order[k]] = k;
    }
  });
  r.graph = NumberedVertexGraph(mesh, r.order, r.rank);
  return r;
}

}  // namespace meshseg::curvature_internal
