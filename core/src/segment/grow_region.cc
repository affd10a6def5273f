#include "segment/grow_region.h"

#include <algorithm>

namespace meshseg::segment_internal {
namespace {

// Rounds of "grow, then refit" before giving up on convergence.
constexpr int kMaxRounds = 40;

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
  std::vector<int> frontier;
  for (const int v : *region) {
    for (const int j : c.graph.Neighbors(v)) {
      if ((*labels)[j] == -1) frontier.push_back(j);
    }
  }
  std::sort(frontier.begin(), frontier.end());
  frontier.erase(std::unique(frontier.begin(), frontier.end()), frontier.end());
  bool fitted = false;
  std::vector<int> queue;
  std::vector<int> rejected;
  // Marks frontier/rejected vertices of this round: -2 - id is never a label.
  const int kQueued = -2 - id;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!model->Refit(c, *region)) break;
    fitted = true;
    std::size_t added = 0;
    queue = frontier;
    for (const int v : queue) (*labels)[v] = kQueued;
    rejected.clear();
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int v = queue[head];
      if (!Fits(c, v, model->ProjectOne(c, v), tol)) {
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
