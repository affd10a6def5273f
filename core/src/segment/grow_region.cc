#include "segment/grow_region.h"

#include <algorithm>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

namespace meshseg::segment_internal {
namespace {

// Rounds of "grow, then refit" before giving up on convergence.
constexpr int kMaxRounds = 40;

// Below this many queued (or region) vertices the tests (or reads) run on
// the calling thread (a parallel loop costs more than it saves).
constexpr std::size_t kParallelTests = 64;

// A queued vertex as tested: whether it meets (5) and (6), and if so its
// neighbours that were free (labels -1) when tested, in row order (at most
// kMaxFree; kReadRow: more, read the row again).
constexpr int kMaxFree = 8;
constexpr uint8_t kReadRow = 255;
struct Tested {
  bool fits = false;
  uint8_t free_count = 0;
  int free[kMaxFree];
};

// Tests queue[k] for k in [begin, queue.size()) against the fixed `model`,
// and lists each fitting one's free neighbours, side by side: each entry
// reads only the model, its vertex, its row and the labels, which nothing
// writes meanwhile.
void TestQueued(const SegmentContext& c, const GrowModel& model, const Tolerance& tol,
                const std::vector<int>& labels, const std::vector<int>& queue, std::size_t begin,
                std::vector<Tested>* tests) {
  tests->resize(queue.size());
  const auto test = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      Tested& t = (*tests)[k];
      t.fits = Fits(c, queue[k], model.ProjectOne(c, queue[k]), tol);
      t.free_count = 0;
      if (!t.fits) continue;
      for (const int j : c.graph.Neighbors(queue[k])) {
        if (labels[j] != -1) continue;
        if (t.free_count == kMaxFree) {
          t.free_count = kReadRow;
          break;
        }
        t.free[t.free_count++] = j;
      }
    }
  };
  if (queue.size() - begin < kParallelTests) {
    test(begin, queue.size());
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, queue.size(), 16),
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
  // Fitted to the measured vertices, as FitType is.
  std::vector<int> measured;
  if (!c.measured.empty()) {
    measured = MeasuredVertices(c, vertices);
    if (!measured.empty()) vertices = measured;
  }
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
  std::vector<Tested> tests;  // per queue entry
  // Marks frontier/rejected vertices of this round: -2 - id is never a label.
  const int kQueued = -2 - id;
  const auto claim = [&](int j, std::vector<int>* queue) {
    if ((*labels)[j] != -1) return;
    (*labels)[j] = kQueued;
    queue->push_back(j);
  };
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!model->Refit(c, *region)) break;
    fitted = true;
    std::size_t added = 0;
    queue = frontier;
    for (const int v : queue) (*labels)[v] = kQueued;
    rejected.clear();
    // The queue is walked in order as one breadth-first search. The model
    // is fixed within the round, so everything queued so far (a level of
    // the search) is tested first, side by side. A neighbour not free then
    // stays taken through the level, so the walk need only look again at
    // those that were free, in the same order.
    for (std::size_t head = 0, tested = 0; head < queue.size(); ++head) {
      if (head == tested) {
        TestQueued(c, *model, tol, *labels, queue, head, &tests);
        tested = queue.size();
      }
      const int v = queue[head];
      const Tested& t = tests[head];
      if (!t.fits) {
        rejected.push_back(v);
        continue;
      }
      (*labels)[v] = id;
      region->push_back(v);
      ++added;
      if (t.free_count == kReadRow) {
        for (const int j : c.graph.Neighbors(v)) claim(j, &queue);
      } else {
        for (int i = 0; i < t.free_count; ++i) claim(t.free[i], &queue);
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
