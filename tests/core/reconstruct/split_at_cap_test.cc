#include "reconstruct/split_at_cap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruct/close_unsupported.h"
#include "washers.h"

namespace meshseg::reconstruct_internal {
namespace {

using test_washers::ExpectOneClosedManifoldOfGenus;
using test_washers::kInner;
using test_washers::kNu;
using test_washers::kOuter;
using test_washers::kStep;
using test_washers::SeenWhere;
using test_washers::Washer;
using test_washers::WasherDistance;
using test_washers::WorstWasherDistance;

// A bore (the washer's inner wall) seen only above z = 6, the face it opens
// onto (the underside) unseen, the outer wall seen all the way down to it.
// Both rims leave straight down, so (d) refuses the arc tube; the outer
// rim's seen wall ends on the cap plane z = 0, 6 below the bore's rim. The
// bore's wall runs on straight down to it and the underside is the strip
// between the outer rim and the bore's circle on it: genus 1 like the
// solid, every patch vertex on the washer to within a tenth of the mesh's
// spacing (the bore's polygon is the washer's own; its chord sag, 0.005,
// is the only error), and no face without area. Discs (genus 0) span the
// bore's mouth 6 above the unseen face.
TEST(SplitAtCap, ABoreSeenToAboveTheFaceItOpensOntoRunsStraightOnToThatFace) {
  constexpr double kTall = 20.0, kBoreSeenAbove = 6.0;
  std::vector<Eigen::Vector2d> section;
  const Mesh washer = Washer(kTall, &section);
  const std::vector<uint8_t> supported = SeenWhere(
      washer, section, [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
        const bool underside = p.y() == 0.0 && q.y() == 0.0;
        const bool low_bore =
            p.x() == kInner && q.x() == kInner && p.y() + q.y() < 2 * kBoreSeenAbove;
        return !underside && !low_bore;
      });
  const auto closed = CloseUnsupported(washer, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(closed.ok()) << closed.status();
  EXPECT_EQ(closed->hole_count, 2);
  ExpectOneClosedManifoldOfGenus(closed->mesh.tri, 1);
  double worst = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (const auto f : closed->mesh.tri.faces()) {
    if (!closed->filled[f.idx()]) continue;
    smallest = std::min(smallest, static_cast<double>(closed->mesh.tri.calc_face_area(f)));
    for (const auto v : closed->mesh.tri.fv_range(f)) {
      worst = std::max(worst, WasherDistance(ToEigen(closed->mesh.tri.point(v)), kTall));
    }
  }
  EXPECT_LT(worst, 0.1 * kStep);
  EXPECT_GT(smallest, 1e-3 * kStep * kStep);
}

// As above, but the outer wall seen down to the underside on three quarters
// of the washer and only down to z = 3 on the rest: the outer rim climbs the
// wall. Straight rungs from its high quarter to the bore's circle on z = 0 cut the
// corner between wall and underside (1.5 inside the washer halfway along a
// rung 5 across and 3 down); bent onto the seen planes (the outer wall's
// tangent planes and the cap plane) the strip lies on the washer to within
// a third of the mesh step: the wall's polygon between tangent planes
// (15 (1 − cos(π / 96)), 0.01) and a corner vertex sent to the nearer of
// wall and face (at most a row spacing, about a mean edge, from the edge).
TEST(SplitAtCap, TheFaceABoreOpensOntoIsBentOntoTheWallsItsRimClimbs) {
  constexpr double kTall = 20.0, kBoreSeenAbove = 6.0, kWallSeenAbove = 3.0;
  std::vector<Eigen::Vector2d> section;
  const Mesh washer = Washer(kTall, &section);
  const size_t nv = section.size();
  std::vector<uint8_t> supported(washer.tri.n_faces());
  for (size_t f = 0; f < supported.size(); ++f) {
    const Eigen::Vector2d& p = section[f / 2 % nv];
    const Eigen::Vector2d& q = section[(f / 2 + 1) % nv];
    const bool high_quarter = f / 2 / nv < static_cast<size_t>(kNu / 4);
    const bool underside = p.y() == 0.0 && q.y() == 0.0;
    const bool low_bore =
        p.x() == kInner && q.x() == kInner && p.y() + q.y() < 2 * kBoreSeenAbove;
    const bool low_wall = high_quarter && p.x() == kOuter && q.x() == kOuter &&
                          p.y() + q.y() < 2 * kWallSeenAbove;
    supported[f] = !underside && !low_bore && !low_wall;
  }
  const auto straight = CloseUnsupported(washer, supported, 0.01, false, {}, false, 0.0);
  ASSERT_TRUE(straight.ok()) << straight.status();
  ExpectOneClosedManifoldOfGenus(straight->mesh.tri, 1);
  EXPECT_GT(WorstWasherDistance(*straight, kTall), 1.0);
  const auto bent = CloseUnsupported(washer, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(bent.ok()) << bent.status();
  EXPECT_EQ(bent->hole_count, 2);
  ExpectOneClosedManifoldOfGenus(bent->mesh.tri, 1);
  EXPECT_LT(WorstWasherDistance(*bent, kTall), kStep / 3);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
