// ExpandRegion / ExpandRegions (alpha-expansion in bands around the
// boundaries, alpha_expansion.h) on sheets with known faces: the minimum
// cut is the least data + smoothness cost over every choice in the band
// (brute force), its priced change is the change of TotalEnergy, a boundary
// displaced off a crease goes back onto it, a surface bent over a
// neighbour's rows gives them back, and the band bounds a move.
#include "segment/alpha_expansion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <variant>
#include <vector>

#include "segment/energy.h"
#include "rounded_prism_truth.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::BuildSheet;
using testing::Fold45;
using testing::RegionsFromLabels;
using testing::Sheet;

constexpr double kSigma = 0.01;
constexpr double kStep = 0.25;  // row spacing across the crease

// E without the label costs (data + smoothness).
double DataAndSmoothness(const SegmentContext& c, const std::vector<int>& labels,
                         std::vector<RegionState> regions) {
  RebuildVertexLists(labels, &regions);
  double e = TotalEnergy(c, labels, regions);
  for (const RegionState& r : regions) {
    if (r.alive) e -= LabelCost(c, r.type, r.vertices.size());
  }
  return e;
}

// Applies `move` (alpha's expansion) to labels and vertex lists.
void Apply(const Expansion& move, int alpha, std::vector<int>* labels,
           std::vector<RegionState>* regions) {
  for (const int v : move.taken) (*labels)[v] = alpha;
  RebuildVertexLists(*labels, regions);
}

// The fold of Fold45 at u = 6 over u in [0, 12], rows kStep apart, v in
// [0, 5]; th_dis 5 sigma. Labelled 0 (the flat side) for u < 6 + shift
// rows, 1 beyond, both fitted as planes.
std::vector<RegionState> DisplacedFold(int shift, Sheet* s, std::vector<int>* labels) {
  BuildSheet(Fold45(6.0), 0.0, 12.0, 49, 0.0, 5.0, 21, /*distance=*/5.0 * kSigma,
             /*angle_deg=*/8.0, s);
  s->c.noise_sigma = kSigma;
  labels->resize(s->u.size());
  for (std::size_t v = 0; v < labels->size(); ++v) {
    (*labels)[v] = s->u[v] < 6.0 + kStep * shift - 1e-9 ? 0 : 1;
  }
  return RegionsFromLabels(s->c, *labels, {SurfaceType::kPlane, SurfaceType::kPlane});
}

TEST(ExpandRegionTest, MinimumCutIsTheLeastCostOverTheBand) {
  // 4 x 3 vertices, three labels scattered; alpha = 0 holds one corner and
  // its band (3 rings) is every other vertex: the cut must equal the best
  // of all 2^11 choices.
  Sheet s;
  BuildSheet(
      [](double u, double v) {
        return std::pair{Eigen::Vector3d(u, v, 0.02 * std::sin(3.0 * u + 2.0 * v)),
                         Eigen::Vector3d(0, 0, 1)};
      },
      0.0, 3.0, 4, 0.0, 2.0, 3, /*distance=*/0.03, /*angle_deg=*/8.0, &s);
  const std::vector<int> labels = {0, 1, 2, 1, 2, 2, 1, -1, 1, 2, 1, 2};
  std::vector<RegionState> regions(3);
  regions[0].type = regions[1].type = regions[2].type = SurfaceType::kPlane;
  regions[0].surface = Plane{.point = {0, 0, 0.01}, .normal = {0, 0, 1}};
  regions[1].surface = Plane{.point = {0, 0, -0.02}, .normal = {0, 0, 1}};
  regions[2].surface = Plane{.point = {0, 0, 0.0}, .normal = Eigen::Vector3d(0.01, 0, 1).normalized()};
  RebuildVertexLists(labels, &regions);
  const Expansion move = ExpandRegion(s.c, labels, regions, 0, 3);
  const double before = DataAndSmoothness(s.c, labels, regions);
  double best = before;
  for (int mask = 0; mask < (1 << 11); ++mask) {
    std::vector<int> next = labels;
    for (int k = 0; k < 11; ++k) {
      if (mask & (1 << k)) next[k + 1] = 0;
    }
    best = std::min(best, DataAndSmoothness(s.c, next, regions));
  }
  ASSERT_LT(best, before - 1e-3) << "alpha is of no use anywhere";
  EXPECT_NEAR(move.smooth_data_delta, best - before, 1e-9);
}

TEST(ExpandRegionTest, PricedChangeIsTheChangeOfTheTotalEnergy) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = DisplacedFold(3, &s, &labels);
  for (const int alpha : {0, 1}) {
    std::vector<int> l = labels;
    std::vector<RegionState> r = regions;
    const double before = TotalEnergy(s.c, l, r);
    const Expansion move = ExpandRegion(s.c, l, r, alpha);
    EXPECT_LE(move.smooth_data_delta, 1e-12) << "alpha " << alpha;
    if (alpha == 1) {
      EXPECT_EQ(move.taken.size(), 3u * 21u);
    }
    Apply(move, alpha, &l, &r);
    EXPECT_NEAR(TotalEnergy(s.c, l, r) - before, move.delta, 1e-9 * std::abs(before))
        << "alpha " << alpha;
  }
}

TEST(ExpandRegionsTest, PutsADisplacedBoundaryBackOnTheCrease) {
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = DisplacedFold(3, &s, &labels);
  const double before = TotalEnergy(s.c, labels, regions);
  const absl::StatusOr<int> moved = ExpandRegions(s.c, &labels, &regions);
  ASSERT_TRUE(moved.ok());
  EXPECT_EQ(*moved, 3 * 21);
  EXPECT_LT(TotalEnergy(s.c, labels, regions), before);
  // Every vertex more than one row from the crease is on its own face.
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (std::abs(s.u[v] - 6.0) <= kStep + 1e-9) continue;
    EXPECT_EQ(labels[v], s.u[v] < 6.0 ? 0 : 1) << "u " << s.u[v] << " v " << s.v[v];
  }
  // The flat face's plane is refitted to z = 0 once the rows are gone.
  const auto& plane = std::get<Plane>(regions[0].surface);
  EXPECT_NEAR(std::abs(plane.normal.z()), 1.0, 1e-6);
}

TEST(ExpandRegionTest, TheBandBoundsTheMove) {
  // Displaced by 8 rows: one expansion of the 45-degree face with a band of
  // 2 rings takes only rows within 2 of its boundary; the sweeps take the rest.
  Sheet s;
  std::vector<int> labels;
  std::vector<RegionState> regions = DisplacedFold(8, &s, &labels);
  const double boundary = 6.0 + 8 * kStep;
  const Expansion move = ExpandRegion(s.c, labels, regions, 1, 2);
  ASSERT_FALSE(move.taken.empty());
  for (const int v : move.taken) {
    EXPECT_GE(s.u[v], boundary - 2 * kStep - 1e-9) << "u " << s.u[v];
  }
  ASSERT_TRUE(ExpandRegions(s.c, &labels, &regions, 2).ok());
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (std::abs(s.u[v] - 6.0) <= kStep + 1e-9) continue;
    EXPECT_EQ(labels[v], s.u[v] < 6.0 ? 0 : 1) << "u " << s.u[v];
  }
}

// A flat face (u <= 6) running tangent into a round of radius 2 about an
// axis along v (u > 6 is arc length along it), as a convex edge round meets
// a top face.
std::pair<Eigen::Vector3d, Eigen::Vector3d> FlatIntoRound(double u, double v) {
  constexpr double kRadius = 2.0;
  if (u <= 6.0) return {Eigen::Vector3d(u, v, 0.0), Eigen::Vector3d(0, 0, 1)};
  const double t = (u - 6.0) / kRadius;
  return {Eigen::Vector3d(6.0 + kRadius * std::sin(t), v, -kRadius * (1.0 - std::cos(t))),
          Eigen::Vector3d(std::sin(t), 0.0, std::cos(t))};
}

TEST(ExpandRegionsTest, ARoundBentOverAFaceGivesItsRowsBack) {
  // The round grown over 8 rows of the face (u in [4, 6]) and fitted to all
  // it holds, so bent toward the face; the face holds u < 4.
  Sheet s;
  const double end = 6.0 + 2.0 * 3.14159265358979323846 / 2.0;
  BuildSheet(FlatIntoRound, 0.0, end, static_cast<int>(end / kStep) + 1, 0.0, 5.0, 21,
             /*distance=*/5.0 * kSigma, /*angle_deg=*/8.0, &s);
  s.c.noise_sigma = kSigma;
  std::vector<int> labels(s.u.size());
  for (std::size_t v = 0; v < labels.size(); ++v) labels[v] = s.u[v] < 4.0 ? 0 : 1;
  std::vector<RegionState> regions =
      RegionsFromLabels(s.c, labels, {SurfaceType::kPlane, SurfaceType::kCylinder});
  const double bent = std::get<Cylinder>(regions[1].surface).radius;
  ASSERT_GT(std::abs(bent - 2.0), 0.1) << "the round is not bent";
  const double before = TotalEnergy(s.c, labels, regions);
  ASSERT_TRUE(ExpandRegions(s.c, &labels, &regions).ok());
  EXPECT_LT(TotalEnergy(s.c, labels, regions), before);
  // The face's rows more than two rows from the tangent line are the face's
  // again (nearer, the round departs from the face by less than sigma).
  int kept = 0;
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (s.u[v] < 6.0 - 2 * kStep - 1e-9) kept += labels[v] != 0;
  }
  EXPECT_EQ(kept, 0);
  EXPECT_NEAR(std::get<Cylinder>(regions[1].surface).radius, 2.0, 0.02) << "bent " << bent;
}

using RoundedPrismTest = testing::RoundedPrismTruth;

// Every plane took three rings of the fillets next to it, as region growing
// does at high noise. The expansions give them back.
TEST_F(RoundedPrismTest, GivesFilletsBackTheRingsThePlanesTook) {
  const SegmentContext c = MakeSegmentContext(part_.mesh.tri, field_, estimates_, 0.9, run_);
  std::vector<int> labels;
  const std::vector<int> taken = PlanesTakeFilletRings(c, 3, &labels);
  ASSERT_GT(taken.size(), 1000u);
  std::vector<RegionState> regions = regions_;
  RebuildVertexLists(labels, &regions);
  const double before = TotalEnergy(c, labels, regions);

  ASSERT_TRUE(ExpandRegions(c, &labels, &regions).ok());

  EXPECT_LT(TotalEnergy(c, labels, regions), before);
  // The rows that lie off the plane by more than half of th_dis (a data
  // cost of 9/8 or more there, about the noise's on the fillet) go back;
  // nearer the tangent line plane and fillet differ by less than the noise
  // in position and E does not decide (the refinement's normal term does).
  int off = 0;
  int returned = 0;
  for (const int v : taken) {
    const int fillet = part_.vertex_primitive[v];
    // The plane that took v: a plane neighbour region of the fillet.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < regions_.size(); ++r) {
      if (!IsPlane(static_cast<int>(r))) continue;
      nearest = std::min(nearest, std::abs(ProjectVertex(c, regions_[r].surface, v).distance));
    }
    if (nearest < 0.5 * c.tolerance.distance) continue;
    ++off;
    returned += labels[v] == fillet;
  }
  // Measured 140 of 182: a fillet re-estimated with plane rows past its
  // tangent line widens and holds some of them (why Segment() lets the
  // refinement's normal term settle tangent joins after the expansions).
  ASSERT_GT(off, 100);
  EXPECT_GT(returned, off / 2) << "of " << off;
}

// ExpandRegions skips an expansion whose inputs have not changed since it
// was last not made, and finds its bands from the boundaries: the labels
// and surfaces must be those of the sweeps as alpha_expansion.h states
// them, made here naively with ExpandRegion on every region of every sweep.
TEST_F(RoundedPrismTest, SweepsAreTheNaiveSweepsBitForBit) {
  const SegmentContext c = MakeSegmentContext(part_.mesh.tri, field_, estimates_, 0.9, run_);
  std::vector<int> labels;
  PlanesTakeFilletRings(c, 3, &labels);
  std::vector<RegionState> regions = regions_;
  RebuildVertexLists(labels, &regions);
  std::vector<int> naive_labels = labels;
  std::vector<RegionState> naive = regions;
  const int count = static_cast<int>(naive.size());
  int sweeps = 0;
  for (int sweep = 0; sweep < kMaxExpansionSweeps; ++sweep, ++sweeps) {
    std::vector<uint8_t> changed(count, 0);
    for (int alpha = 0; alpha < count; ++alpha) {
      if (!naive[alpha].alive || naive[alpha].vertices.empty()) continue;
      const Expansion move = ExpandRegion(c, naive_labels, naive, alpha);
      if (move.taken.empty() || !(move.delta < 0.0)) continue;
      for (const int v : move.taken) {
        if (naive_labels[v] >= 0) changed[naive_labels[v]] = 1;
        naive_labels[v] = alpha;
      }
      changed[alpha] = 1;
      RebuildVertexLists(naive_labels, &naive);
    }
    if (std::none_of(changed.begin(), changed.end(), [](uint8_t x) { return x != 0; })) break;
    for (int r = 0; r < count; ++r) {
      if (changed[r] && naive[r].alive && !naive[r].vertices.empty()) {
        naive[r] = Reestimated(c, naive[r]);
      }
    }
  }
  ASSERT_GE(sweeps, 2) << "too few sweeps to skip any expansion";
  ASSERT_TRUE(ExpandRegions(c, &labels, &regions).ok());
  EXPECT_EQ(labels, naive_labels);
  for (int r = 0; r < count; ++r) {
    EXPECT_EQ(regions[r].vertices, naive[r].vertices) << "region " << r;
    std::visit(
        [&](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          EXPECT_EQ(std::memcmp(&x, &std::get<T>(naive[r].surface), sizeof(T)), 0)
              << "region " << r;
        },
        regions[r].surface);
  }
}

// With the true labels, E does not rise and the only vertices that move lie
// on the surface they go to (within th_dis of its true surface): rows along
// the tangent lines, which both faces explain within the noise.
TEST_F(RoundedPrismTest, MovesOnlyRowsTheOtherFaceExplains) {
  const SegmentContext c = MakeSegmentContext(part_.mesh.tri, field_, estimates_, 0.9, run_);
  std::vector<int> labels = part_.vertex_primitive;
  std::vector<RegionState> regions = regions_;
  RebuildVertexLists(labels, &regions);
  const double before = TotalEnergy(c, labels, regions);
  ASSERT_TRUE(ExpandRegions(c, &labels, &regions).ok());
  EXPECT_LE(TotalEnergy(c, labels, regions), before);
  int moved = 0;
  int off = 0;
  for (int v = 0; v < c.vertex_count(); ++v) {
    if (labels[v] == part_.vertex_primitive[v]) continue;
    ++moved;
    const double d = ProjectVertex(c, regions_[labels[v]].surface, v).distance;
    off += !(std::abs(d) < c.tolerance.distance);
  }
  EXPECT_LT(moved, 0.05 * c.vertex_count());
  EXPECT_EQ(off, 0) << "of " << moved << " moved";
}

TEST_F(RoundedPrismTest, StopsWhenCancelled) {
  std::stop_source source;
  source.request_stop();
  const RunContext cancelled{.stop = source.get_token(), .on_progress = {}};
  const SegmentContext c = MakeSegmentContext(part_.mesh.tri, field_, estimates_, 0.9, cancelled);
  std::vector<int> labels = part_.vertex_primitive;
  std::vector<RegionState> regions = regions_;
  RebuildVertexLists(labels, &regions);
  EXPECT_EQ(ExpandRegions(c, &labels, &regions).status().code(), absl::StatusCode::kCancelled);
}

}  // namespace
}  // namespace meshseg::segment_internal
