// ExpansionBands (expansion_band.h) on a sheet with patchy labels: every
// band is the set of vertices not labelled alpha at graph distance 1 to
// `rings` from alpha's vertices (a breadth-first search from all of them),
// before and after labels move, with and without regrouping.
#include "segment/expansion_band.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Sheet;

constexpr int kRegions = 4;

// The band by its definition: breadth-first distances from alpha's
// vertices, kept from 1 to `rings` (sorted by vertex id).
std::vector<int> BandByDistance(const SegmentContext& c, const std::vector<int>& labels, int alpha,
                                int rings) {
  std::vector<int> distance(labels.size(), -1);
  std::deque<int> queue;
  for (int v = 0; v < static_cast<int>(labels.size()); ++v) {
    if (labels[v] == alpha) {
      distance[v] = 0;
      queue.push_back(v);
    }
  }
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (const int u : c.graph.Neighbors(v)) {
      if (distance[u] >= 0) continue;
      distance[u] = distance[v] + 1;
      queue.push_back(u);
    }
  }
  std::vector<int> band;
  for (int v = 0; v < static_cast<int>(labels.size()); ++v) {
    if (distance[v] >= 1 && distance[v] <= rings) band.push_back(v);
  }
  return band;
}

// Checks every region's band for 1 to 3 rings, its numbering and its
// release.
void ExpectBandsByDistance(const SegmentContext& c, const std::vector<int>& labels,
                           ExpansionBands* bands, const char* when) {
  for (int alpha = 0; alpha < kRegions; ++alpha) {
    for (int rings = 1; rings <= 3; ++rings) {
      const std::vector<int> band = bands->Band(labels, alpha, rings);
      EXPECT_EQ(band, BandByDistance(c, labels, alpha, rings))
          << when << ": alpha " << alpha << " rings " << rings;
      for (int k = 0; k < static_cast<int>(band.size()); ++k) {
        ASSERT_EQ(bands->Node(band[k]), k) << when;
      }
      bands->Release(band);
      for (int v = 0; v < c.vertex_count(); ++v) ASSERT_EQ(bands->Node(v), -1) << when;
    }
  }
}

TEST(ExpansionBandsTest, BandIsTheVerticesWithinTheRingsOfAlpha) {
  Sheet s;
  BuildSheet([](double u, double v) {
               return std::pair{Eigen::Vector3d(u, v, 0.0), Eigen::Vector3d(0, 0, 1)};
             },
             0.0, 1.0, 24, 0.0, 1.0, 18, /*distance=*/0.01, /*angle_deg=*/8.0, &s);
  const int n = s.c.vertex_count();
  // Patches: four quadrants, then scattered single vertices of every label
  // (-1 included), so that bands meet, wrap and have holes.
  std::vector<int> labels(n);
  for (int v = 0; v < n; ++v) labels[v] = (s.u[v] < 0.5 ? 0 : 1) + (s.v[v] < 0.4 ? 0 : 2);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> vertex(0, n - 1);
  std::uniform_int_distribution<int> label(-1, kRegions - 1);
  for (int k = 0; k < 40; ++k) labels[vertex(random)] = label(random);
  ExpansionBands bands(s.c, labels, kRegions);
  ExpectBandsByDistance(s.c, labels, &bands, "as built");
  // Labels moved in batches, reported, then checked before and after
  // regrouping (the moved vertices may join or leave any first ring).
  for (int round = 0; round < 4; ++round) {
    std::vector<int> moved;
    for (int k = 0; k < 30; ++k) {
      const int v = vertex(random);
      labels[v] = label(random);
      moved.push_back(v);
    }
    // A whole row of one quadrant changes too: a boundary line moves.
    for (int v = 0; v < n; ++v) {
      if (std::abs(s.v[v] - 0.1 * (round + 3)) < 0.02 && s.u[v] < 0.5) {
        labels[v] = round % kRegions;
        moved.push_back(v);
      }
    }
    bands.Moved(moved);
    ExpectBandsByDistance(s.c, labels, &bands, "after moves");
    bands.Regroup(labels);
    ExpectBandsByDistance(s.c, labels, &bands, "regrouped");
  }
}

}  // namespace
}  // namespace meshseg::segment_internal
