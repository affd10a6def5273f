// The segment stage's loops that run side by side over a part's vertices
// (TotalEnergy's data terms, FittingVertices' tests, BuildRegionGraph's
// boundary vertices) give, bit for bit, what the one-vertex-at-a-time loops
// they replaced give, written out here as the references: on a generated
// part with its true labels (test_piece, 0.05 h noise: every type of
// surface, boundaries sharp and smooth, over the parallel thresholds).
#include <Eigen/Core>
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "segment/energy.h"
#include "segment/estimate_noise.h"
#include "segment/region_graph.h"
#include "segment/segment_internal.h"
#include "true_labels.h"

namespace meshseg::segment_internal {
namespace {

void BuildTrue(Labeled* t) { BuildTrueLabels("test_piece", 0.05, 1.0, t); }

class ParallelPaths : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    t_ = new Labeled;
    BuildTrue(t_);
  }
  static void TearDownTestSuite() {
    delete t_;
    t_ = nullptr;
  }
  static Labeled* t_;
};
Labeled* ParallelPaths::t_ = nullptr;

TEST_F(ParallelPaths, TotalEnergyIsTheSumInVertexOrder) {
  const SegmentContext& c = t_->c;
  ASSERT_GT(c.vertex_count(), 4096);
  // The labelling with one primitive unlabelled too (the outlier cost).
  std::vector<int> labels = t_->labels;
  for (int& l : labels) {
    if (l == 1) l = -1;
  }
  for (const std::vector<int>* l : {&t_->labels, &labels}) {
    double e = 0.0;
    for (int v = 0; v < c.vertex_count(); ++v) {
      const int r = (*l)[v];
      e += r < 0 ? OutlierCost(c, v) : VertexCost(c, v, t_->regions[r].surface);
      for (const int u : c.graph.Neighbors(v)) {
        if (u > v && (*l)[u] != r) e += EdgeCost(c, u, v);
      }
    }
    for (const RegionState& r : t_->regions) {
      if (r.alive) e += LabelCost(c, r);
    }
    EXPECT_EQ(TotalEnergy(c, *l, t_->regions), e);
  }
}

TEST_F(ParallelPaths, FittingVerticesAreTheOnesEachTestKeeps) {
  const SegmentContext& c = t_->c;
  std::vector<int> all(c.vertex_count());
  for (int v = 0; v < c.vertex_count(); ++v) all[v] = v;
  std::reverse(all.begin(), all.end());  // the order given is kept
  std::size_t kept = 0;
  for (const RegionState& r : t_->regions) {
    std::vector<int> expected;
    for (const int v : all) {
      if (Fits(c, v, ProjectVertex(c, r.surface, v), c.tolerance)) expected.push_back(v);
    }
    EXPECT_EQ(FittingVertices(c, r.surface, all), expected) << SurfaceTypeName(r.type);
    // The small sets stay on the calling thread: the same rule.
    const std::vector<int> few(all.begin(), all.begin() + 100);
    std::vector<int> expected_few;
    for (const int v : few) {
      if (Fits(c, v, ProjectVertex(c, r.surface, v), c.tolerance)) expected_few.push_back(v);
    }
    EXPECT_EQ(FittingVertices(c, r.surface, few), expected_few);
    kept += expected.size();
  }
  // Not vacuous: every vertex fits its own primitive's surface or nearly.
  EXPECT_GT(kept, all.size() / 2);
}

TEST_F(ParallelPaths, RegionGraphIsTheOneAWalkOverEveryVertexGives) {
  const SegmentContext& c = t_->c;
  std::vector<RegionState> regions = t_->regions;
  regions[2].alive = false;  // a dead region's boundaries are no arcs
  std::map<std::pair<int, int>, Eigen::Vector3d> strip;
  std::vector<int> seen;
  for (int v = 0; v < c.vertex_count(); ++v) {
    const int a = t_->labels[v];
    if (a < 0 || !regions[a].alive) continue;
    seen.clear();
    for (const int j : c.graph.Neighbors(v)) {
      const int b = t_->labels[j];
      if (b < 0 || b == a || !regions[b].alive ||
          std::find(seen.begin(), seen.end(), b) != seen.end()) {
        continue;
      }
      seen.push_back(b);
      strip.try_emplace({a, b}, Eigen::Vector3d::Zero()).first->second += c.normal(v);
    }
  }
  const std::vector<RegionArc> arcs = BuildRegionGraph(c, t_->labels, regions);
  std::size_t k = 0;
  for (const auto& [key, sum_ab] : strip) {
    if (key.first > key.second || !strip.contains({key.second, key.first})) continue;
    ASSERT_LT(k, arcs.size());
    EXPECT_EQ(arcs[k].a, key.first);
    EXPECT_EQ(arcs[k].b, key.second);
    const Eigen::Vector3d& sum_ba = strip.at({key.second, key.first});
    const double cosine = sum_ab.dot(sum_ba) / (sum_ab.norm() * sum_ba.norm());
    EXPECT_EQ(arcs[k].angle_deg,
              std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
    ++k;
  }
  EXPECT_EQ(k, arcs.size());
  EXPECT_GE(arcs.size(), 10u);  // the part's faces meet along many edges
}

}  // namespace
}  // namespace meshseg::segment_internal
