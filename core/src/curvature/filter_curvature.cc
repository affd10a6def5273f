#include "curvature/filter_curvature.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace meshseg::curvature_internal {
namespace {

constexpr int kMeanPasses = 3;  // seed 002 A4

// One filter pass over `values`: each non-sharp vertex gets the median
// (use_median) or the mean of itself and its non-sharp 1-ring.
std::vector<double> FilterPass(const VertexGraph& graph, const std::vector<uint8_t>& sharp,
                               const std::vector<double>& values, bool use_median) {
  std::vector<double> out = values;
  const int n = graph.vertex_count();
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& r) {
    std::vector<double> ring;
    for (int v = r.begin(); v < r.end(); ++v) {
      if (sharp[v]) continue;
      ring.clear();
      ring.push_back(values[v]);
      for (const int j : graph.Neighbors(v)) {
        if (!sharp[j]) ring.push_back(values[j]);
      }
      if (use_median) {
        const auto mid = ring.begin() + ring.size() / 2;
        std::nth_element(ring.begin(), mid, ring.end());
        out[v] = *mid;
      } else {
        double sum = 0.0;
        for (const double x : ring) sum += x;
        out[v] = sum / ring.size();
      }
    }
  });
  return out;
}

}  // namespace

void FilterCurvature(const OrderedGraph& walk, CurvatureField* field) {
  // In the walk's numbering (each ring the same values in the same order,
  // so the same medians and means), then back under each vertex's index.
  // kappa_max and kappa_min are filtered side by side (independent values).
  const std::vector<uint8_t> sharp = walk.Permuted<uint8_t>(field->sharp);
  const int n = static_cast<int>(field->kappa_max.size());
  const auto filter = [&](std::vector<double>* values) {
    std::vector<double> walked = walk.Permuted<double>(*values);
    walked = FilterPass(walk.graph, sharp, walked, /*use_median=*/true);
    for (int k = 0; k < kMeanPasses; ++k) {
      walked = FilterPass(walk.graph, sharp, walked, /*use_median=*/false);
    }
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
      for (int k = r.begin(); k < r.end(); ++k) (*values)[walk.order[k]] = walked[k];
    });
  };
  tbb::parallel_invoke([&] { filter(&field->kappa_max); }, [&] { filter(&field->kappa_min); });
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if (std::abs(field->kappa_min[v]) > std::abs(field->kappa_max[v])) {
        std::swap(field->kappa_min[v], field->kappa_max[v]);
        std::swap(field->dir_min[v], field->dir_max[v]);
      }
    }
  });
}

}  // namespace meshseg::curvature_internal
