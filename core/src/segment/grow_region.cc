#include "segment/grow_region.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

namespace meshseg::segment_internal {
namespace {

// Rounds of "grow, then refit" before giving up on convergence.
constexpr int kMaxRounds = 40;

// Below this many queued (or region) vertices the tests (or reads) run on the calling thread (a
// parallel loop costs more than it saves).
constexpr std::size_t kParallelTests = 256;

// fits[k] = whether queue[k] meets (5) and (6) for `model`, for k in
// [begin, queue.size()). Each test reads only the fixed model and its vertex.
void TestQueued(const SegmentContext& c, const GrowModel& model, const Tolerance& tol,
                const std::vector<int>& queue, std::size_t begin, std::vector<char>* fits) {
  fits->resize(queue.size());
  const auto test = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      (*fits)[k] = Fits(c, queue[k], model.ProjectOne(c, queue[k]), tol);
    }
  };
  if (queue.size() - begin < kParallelTests) {
    test(begin, queue.size());
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, queue.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) { test(r.begin(), r.end()); });
}

// The free vertices (labels -1) next to `region`, sorted, each once. The
// region's rows are read side by side; the sorted set does not depend on
// the order they were gathered in.
std::vector<int> FreeNeighbors(const SegmentContext& c, const std::vector<int>& labels,
                               const std::vector<int>& region) {
  const auto gather = [&](std::size_t from, std::size_t to, std::vector<int>* out) {
    for (std::size_t k = from; k < to; ++k) {
      for (const int j : c.graph.Neighbors(region[k])) {
        if (labels[j] == -1) out->push_back(j);
      }
    }
  };
  std::vector<int> frontier;
  if (region.size() < kParallelTests) {
    gather(0, region.size(), &frontier);
  } else {
    tbb::combinable<std::vector<int>> parts;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, region.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        gather(r.begin(), r.end(), &parts.local());
                      });
    parts.combine_each([&](const std::vector<int>& part) {
      frontier.insert(frontier.end(), part.begin(), part.end());
    });
  }
  std::sort(frontier.begin(), frontier.end());
  frontier.erase(std::unique(frontier.begin(), frontier.end()), frontier.end());
  return frontier;
}

}  // namespace

bool HeightModel::Refit(const SegmentContext& c, std::span<const int> vertices) {
  if (vertices.empty()) return false;
  const std::vector<int> sample = Sample(vertices);
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
  for (const int v : sample) {
    normal += c.vertex_area[v] * c.curvature->smooth_normal[v];
    points.push_back(c.position(v));
    weights.push_back(c.vertex_area[v] + 1e-12);
  }
  if (!(normal.norm() > 0.0)) return false;
  h_ = FitHeightFunction(points, c.position(vertices.front()), normal.normalized(), weights);
  return h_.valid;
}

Projection HeightModel::ProjectOne(const SegmentContext& c, int v) const {
  return Project(h_, c.position(v));
}

bool SurfaceModel::Refit(const SegmentContext& c, std::span<const int> vertices) {
  FitResult fit = FitType(c, type_, vertices);
  if (!fit.ok()) return false;
  fit_ = std::move(fit);
  return true;
}

Projection SurfaceModel::ProjectOne(const SegmentContext& c, int v) const {
  return ProjectVertex(c, fit_.surface, v);
}

bool GrowRegion(const SegmentContext& c, GrowModel* model, const Tolerance& tol, int id,
                std::vector<int>* labels, std::vector<int>* region) {
  // The frontier: free vertices next to the region that failed the last test.
  std::vector<int> frontier = FreeNeighbors(c, *labels, *region);
  bool fitted = false;
  std::vector<int> queue;
  std::vector<int> rejected;
  std::vector<char> fits;  // per queue entry, as tested
  // Marks frontier/rejected vertices of this round: -2 - id is never a label.
  const int kQueued = -2 - id;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!model->Refit(c, *region)) break;
    fitted = true;
    std::size_t added = 0;
    queue = frontier;
    for (const int v : queue) (*labels)[v] = kQueued;
    rejected.clear();
    // The queue is walked in order as one breadth-first search; the model
    // is fixed within the round, so the tests of everything queued so far
    // are made first (side by side), level by level of the search.
    for (std::size_t head = 0, tested = 0; head < queue.size(); ++head) {
      if (head == tested) {
        TestQueued(c, *model, tol, queue, head, &fits);
        tested = queue.size();
      }
      const int v = queue[head];
      if (!fits[head]) {
        rejected.push_back(v);
        continue;
      }
      (*labels)[v] = id;
      region->push_back(v);
      ++added;
      for (const int j : c.graph.Neighbors(v)) {
        if ((*labels)[j] != -1) continue;
        (*labels)[j] = kQueued;
        queue.push_back(j);
      }
    }
    for (const int v : rejected) (*labels)[v] = -1;
    std::sort(rejected.begin(), rejected.end());
    frontier.swap(rejected);
    if (added == 0) break;
  }
  return fitted;
}

}  // namespace meshseg::segment_internal
