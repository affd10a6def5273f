#include "segment/seeds.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

namespace meshseg::segment_internal {

std::vector<int> SeedOrder(const SegmentContext& c) {
  const int n = c.vertex_count();
  const CurvatureField& k = *c.curvature;
  std::vector<double> d(n, 0.0);
  struct Scratch {
    NeighborhoodScratch nbhd;
    std::vector<int> ids;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 512), [&](const tbb::blocked_range<int>& r) {
    Scratch& s = scratch.local();
    for (int i = r.begin(); i < r.end(); ++i) {
      if (k.sharp[i]) continue;
      CollectNeighborhood(c.graph, i, kW3 * k.mean_edge_length[i], k.sharp, &s.nbhd, &s.ids);
      double mean = 0.0;
      for (const int j : s.ids) mean += k.kappa_max[j];
      mean /= s.ids.size();
      double dev = 0.0;
      for (const int j : s.ids) dev += std::abs(k.kappa_max[j] - mean);
      // Scale-free: deviation in units of 1 / l_i,avg.
      d[i] = dev / s.ids.size() * k.mean_edge_length[i];
    }
  });
  // Ties in d keep the vertex order (the stable order), on both cores. The
  // key (d, vertex) is a strict total order (d is finite), so the sorted
  // order is unique whatever the algorithm; sorting the keys themselves
  // compares contiguous pairs instead of looking d up at random.
  std::vector<std::pair<double, int>> keyed;
  keyed.reserve(n);
  for (int i = 0; i < n; ++i) {
    if (!k.sharp[i] && c.Measured(i)) keyed.emplace_back(d[i], i);
  }
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<int> order(keyed.size());
  for (std::size_t j = 0; j < keyed.size(); ++j) order[j] = keyed[j].second;
  return order;
}

std::vector<int> CollectSeed(const SegmentContext& c, int i, const std::vector<int>& labels,
                             NeighborhoodScratch* scratch) {
  std::vector<int> ids;
  CollectNeighborhood(c.graph, i, kW4 * c.curvature->mean_edge_length[i], c.curvature->sharp,
                      scratch, &ids);
  std::erase_if(ids, [&](int v) { return labels[v] != -1 || !c.Measured(v); });
  if (ids.size() < kMinSeed) ids.clear();
  return ids;
}

}  // namespace meshseg::segment_internal
