#include "reconstruct/close_tube.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "clouds.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/surface_mesh.h"
#include "tube_meshes.h"
#include "washers.h"

namespace meshseg::reconstruct_internal {
namespace {

using test_washers::ExpectOneClosedManifoldOfGenus;
using test_washers::kHeight;
using test_washers::SeenWhere;
using test_washers::Washer;

constexpr double kR = 15.0, kr = 5.0;  // torus radii (a ring lying on its side)
constexpr int kNu = 96, kNv = 32;      // grid round the axis and round the tube
// A tube vertex lies this near the torus: the cubic's error against a
// semicircle (1.8 % of r), the mesh's chord sag (r (1 − cos(π / kNv)), 0.5 %)
// and the rims' normals, extrapolated from rings of facets (2-3 %).
constexpr double kTolerance = 0.05 * kr;

Mesh Torus() {
  const TubeMesh m = TorusTubeMesh(kR, kr, kNu, kNv);
  return *SurfaceMesh(m.vertices, m.triangles, "torus");
}

// Distance of `p` from the exact torus.
double TorusDistance(const Eigen::Vector3d& p) {
  return std::abs(std::hypot(std::hypot(p.x(), p.y()) - kR, p.z()) - kr);
}

// The largest distance of a patch vertex from the exact torus.
double WorstPatchDistance(const ClosedSurface& closed) {
  double worst = 0.0;
  for (const auto f : closed.mesh.tri.faces()) {
    if (!closed.filled[f.idx()]) continue;
    for (const auto v : closed.mesh.tri.fv_range(f)) {
      const Eigen::Vector3d p = ToEigen(closed.mesh.tri.point(v));
  
      worst = std::max(worst, TorusDistance(p));
    }
  }
  return worst;
}

// Face 2 (i kNv + j) + k of the torus lies in grid cell (i, j); j counts
// round the tube from the outer equator (v = 2π j / kNv).
std::vector<uint8_t> SupportedWhere(const Mesh& torus, bool (*seen)(int i, int j)) {
  std::vector<uint8_t> supported(torus.tri.n_faces());
  for (size_t f = 0; f < supported.size(); ++f) {
    const int cell = static_cast<int>(f) / 2;
    supported[f] = seen(cell / kNv, cell % kNv);
  }
  return supported;
}

// A ring seen from above only: the whole underside (v in [π, 2π)) is
// unsupported, an annulus between the inner and the outer equator. Its two
// rims leave their plane straight down, so the tube between them is the
// semicircle of the ring's own section: genus 1, every patch vertex on the
// torus to within the cubic's error (under 1 % of r) and the mesh's own
// chord sag (r (1 − cos(π / kNv)) ≈ 0.5 % of r). Two discs instead span the
// equators' planes, up to r (the full depth of the underside) away.
TEST(CloseTube, TheUnseenUndersideOfARingIsClosedByATubeOnTheRingsSection) {
  const Mesh torus = Torus();
  const auto supported = SupportedWhere(torus, [](int, int j) { return j < kNv / 2; });
  const auto tubes = CloseUnsupported(torus, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(tubes.ok()) << tubes.status();
  EXPECT_EQ(tubes->hole_count, 2);
  ExpectOneClosedManifoldOfGenus(tubes->mesh.tri, 1);
  EXPECT_LT(WorstPatchDistance(*tubes), kTolerance);
  const double half_area = 2 * M_PI * M_PI * kR * kr;
  EXPECT_NEAR(tubes->filled_area, half_area, 0.02 * half_area);

  // Without tubes (a negative rim bound): two discs, far from the ring.
  const auto discs = CloseUnsupported(torus, supported, 0.01, false, {}, true, -1.0);
  ASSERT_TRUE(discs.ok()) << discs.status();
  ExpectOneClosedManifoldOfGenus(discs->mesh.tri, 0);
  EXPECT_GT(WorstPatchDistance(*discs), 0.5 * kr);
}

// The unseen band is v in [9π/8, 15π/8]: the rims lie 22.5° below the
// equators, their directions turn by 135°, and the tube is the arc of the
// section between them.
TEST(CloseTube, ATubeFollowsTheArcBetweenRimsThatTurnByLessThanHalfATurn) {
  const Mesh torus = Torus();
  const auto supported = SupportedWhere(
      torus, [](int, int j) { return j < 9 * kNv / 16 || j >= 15 * kNv / 16; });
  const auto tubes = CloseUnsupported(torus, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(tubes.ok()) << tubes.status();
  ExpectOneClosedManifoldOfGenus(tubes->mesh.tri, 1);
  EXPECT_LT(WorstPatchDistance(*tubes), kTolerance);
}

// As above, with a handle inside the unseen underside: a straight tube
// through the ring's hole joins the cell just below the inner equator at
// u = 0 to the one facing it at u = π. The removed component is still
// bounded by the two equators alone (its genus is 1: the handle has no
// point on it either and goes with it), so the rims are joined by the
// ring's tube as before: genus 1, every patch vertex on the torus. Counted
// as an annulus only, the component was left to two discs (genus 0).
TEST(CloseTube, AHandleInsideTheUnseenPartGoesWithIt) {
  const TubeMesh m = TorusTubeMesh(kR, kr, kNu, kNv);
  const int j = kNv / 2 + 1, half = kNu / 2;
  const auto id = [&](int i, int jj) { return (i % kNu) * kNv + jj % kNv; };
  std::vector<Eigen::Vector3d> vertices = m.vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<uint8_t> supported;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const int cell = static_cast<int>(t) / 2;
    if (cell == id(0, j) || cell == id(half, j)) continue;  // the handle's mouths
    triangles.push_back(m.triangles[t]);
    supported.push_back(cell % kNv < kNv / 2);
  }
  // The mouth at u = 0 along its cell's border; the one at u = π against
  // its own, from the corner facing the first one's first.
  std::vector<int> ring = {id(0, j), id(1, j), id(1, j + 1), id(0, j + 1)};
  const std::vector<int> end = {id(half, j), id(half, j + 1), id(half + 1, j + 1),
                                id(half + 1, j)};
  constexpr int kSegments = 8;
  for (int s = 1; s <= kSegments; ++s) {
    std::vector<int> next = end;
    if (s < kSegments) {
      for (int k = 0; k < 4; ++k) {
        const double t = static_cast<double>(s) / kSegments;
        next[k] = static_cast<int>(vertices.size());
        vertices.push_back((1 - t) * m.vertices[ring[k]] + t * m.vertices[end[k]]);
      }
    }
    for (int k = 0; k < 4; ++k) {
      triangles.push_back({ring[k], ring[(k + 1) % 4], next[(k + 1) % 4]});
      triangles.push_back({ring[k], next[(k + 1) % 4], next[k]});
      supported.push_back(0);
      supported.push_back(0);
    }
    ring = next;
  }
  const Mesh torus = *SurfaceMesh(vertices, triangles, "torus with a handle");
  ASSERT_EQ(Genus(torus.tri), 2);
  const auto tubes = CloseUnsupported(torus, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(tubes.ok()) << tubes.status();
  EXPECT_EQ(tubes->hole_count, 2);
  ExpectOneClosedManifoldOfGenus(tubes->mesh.tri, 1);
  EXPECT_LT(WorstPatchDistance(*tubes), kTolerance);
}

// A ring seen from above, as in the first test, with a shaft straight down
// through its tube: from a 2 × 2-cell mouth on top (seen, v just past π/2) to
// the mirror mouth underneath (unseen). The shaft has no point on it, so the
// removed component is the underside and the shaft, bounded by three loops:
// the two equators, which the seen surface leaves straight down (the rims
// of the tube), and the top mouth, which the seen top closes as a sheet (a
// hole in it). The equators are joined by the ring's tube and the mouth is
// closed by its own disc: genus 1, every patch vertex near the torus. Counted
// by all three loops, the component was left to three discs, the equators'
// spanning the ring's hole and bore (genus 0, up to r off the torus). The
// ring is larger than the others (R 40, r 20, cells about 1.3 across), so
// that the top is a sheet over the reach of the rim's rings (9 edges turn
// its normal by about 34°; on the smaller ring's tube, r 5, by about 100°,
// and a mouth there is a wall's rim).
TEST(CloseTube, AHoleInTheSeenSurfaceOpeningOntoTheUnseenPartIsNoRim) {
  constexpr double kBigR = 40.0, kBigr = 20.0;
  constexpr int kBigNu = 192, kBigNv = 96;
  const TubeMesh m = TorusTubeMesh(kBigR, kBigr, kBigNu, kBigNv);
  constexpr int kMouth = 2, kTop = kBigNv / 4;  // cells; the top of the tube
  const auto id = [&](int i, int j) { return (i % kBigNu) * kBigNv + j % kBigNv; };
  // Cell rows v in [kTop, kTop + kMouth) on top; their mirror images
  // (v -> 2π - v), straight below them, underneath.
  const auto in_mouth = [&](int cell) {
    const int i = cell / kBigNv, j = cell % kBigNv;
    return i < kMouth && ((j >= kTop && j < kTop + kMouth) ||
                          (j >= kBigNv - kTop - kMouth && j < kBigNv - kTop));
  };
  std::vector<Eigen::Vector3d> vertices = m.vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<uint8_t> supported;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const int cell = static_cast<int>(t) / 2;
    if (in_mouth(cell)) continue;
    triangles.push_back(m.triangles[t]);
    supported.push_back(cell % kBigNv < kBigNv / 2);
  }
  // The top mouth's border in its cells' order, and below each of its
  // vertices the mirror vertex: the bottom mouth's border the other way
  // round, so the shaft's faces turn as the torus's do.
  std::vector<int> ring, end;
  const auto add = [&](int i, int j) {
    ring.push_back(id(i, j));
    end.push_back(id(i, kBigNv - j));
  };
  for (int i = 0; i < kMouth; ++i) add(i, kTop);
  for (int j = kTop; j < kTop + kMouth; ++j) add(kMouth, j);
  for (int i = kMouth; i > 0; --i) add(i, kTop + kMouth);
  for (int j = kTop + kMouth; j > kTop; --j) add(0, j);
  const int n = static_cast<int>(ring.size());
  constexpr int kSegments = 16;
  for (int s = 1; s <= kSegments; ++s) {
    std::vector<int> next = end;
    if (s < kSegments) {
      for (int k = 0; k < n; ++k) {
        const double t = static_cast<double>(s) / kSegments;
        next[k] = static_cast<int>(vertices.size());
        vertices.push_back((1 - t) * m.vertices[ring[k]] + t * m.vertices[end[k]]);
      }
    }
    for (int k = 0; k < n; ++k) {
      triangles.push_back({ring[k], ring[(k + 1) % n], next[(k + 1) % n]});
      triangles.push_back({ring[k], next[(k + 1) % n], next[k]});
      supported.push_back(0);
      supported.push_back(0);
    }
    ring = next;
  }
  // The mouths' middle vertices are on no face any more.
  std::vector<int> index(vertices.size(), -1);
  std::vector<Eigen::Vector3d> used;
  for (auto& t : triangles) {
    for (int& v : t) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(used.size());
        used.push_back(vertices[v]);
      }
      v = index[v];
    }
  }
  const Mesh torus = *SurfaceMesh(used, triangles, "torus with a shaft");
  ASSERT_EQ(Genus(torus.tri), 2);
  const auto tubes = CloseUnsupported(torus, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(tubes.ok()) << tubes.status();
  EXPECT_EQ(tubes->hole_count, 3);
  ExpectOneClosedManifoldOfGenus(tubes->mesh.tri, 1);
  double worst = 0.0;
  for (const auto f : tubes->mesh.tri.faces()) {
    if (!tubes->filled[f.idx()]) continue;
    for (const auto v : tubes->mesh.tri.fv_range(f)) {
      const Eigen::Vector3d p = ToEigen(tubes->mesh.tri.point(v));
      worst = std::max(worst, std::abs(std::hypot(std::hypot(p.x(), p.y()) - kBigR, p.z()) - kBigr));
    }
  }
  EXPECT_LT(worst, 0.05 * kBigr);  // as kTolerance
}

// A band across the tube (cells i in [0, 4)) leaves two meridians whose
// seen surface leaves them along their axis: the rims of one tube when the
// points resolve loops that long, but a handle to cut (two discs) when the
// rims are shorter than min_rim (handles.h).
TEST(CloseTube, RimsShorterThanTheResolvedHoleAreClosedByDiscs) {
  const Mesh torus = Torus();
  const auto supported = SupportedWhere(torus, [](int i, int) { return i >= 4; });
  const double meridian = 2 * M_PI * kr;
  const auto tube = CloseUnsupported(torus, supported, 0.01, false, {}, true, 0.9 * meridian);
  ASSERT_TRUE(tube.ok()) << tube.status();
  ExpectOneClosedManifoldOfGenus(tube->mesh.tri, 1);
  EXPECT_LT(WorstPatchDistance(*tube), kTolerance);
  const auto discs = CloseUnsupported(torus, supported, 0.01, false, {}, true, 1.1 * meridian);
  ASSERT_TRUE(discs.ok()) << discs.status();
  ExpectOneClosedManifoldOfGenus(discs->mesh.tri, 0);
}

// The washer's underside and both its walls below z = 2 unseen: an annulus
// whose rims leave their plane straight down, like the mouth of a bore and
// the walls round the face it opens onto. The seen walls do not curve, so
// the unseen surface meets them at edges: arcs from rim to rim, 5 apart,
// would reach 2.5 down, 0.5 below the unseen face. Criterion (d) refuses
// the tube (without it the tube is made, genus 1), and no seen surface ends
// beyond the bore's rim to mark a cap plane for the bore's wall to run on
// to: the two discs are kept (genus 0).
TEST(CloseTube, StraightWallsRoundAnUnseenFaceKeepTheirDiscs) {
  std::vector<Eigen::Vector2d> section;
  const Mesh washer = Washer(kHeight, &section);
  const std::vector<uint8_t> supported = SeenWhere(
      washer, section, [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
        return p.y() + q.y() > 2 * 2.0;
      });
  const auto closed = CloseUnsupported(washer, supported, 0.01, false, {}, true, 0.0);
  ASSERT_TRUE(closed.ok()) << closed.status();
  EXPECT_EQ(closed->hole_count, 2);
  ExpectOneClosedManifoldOfGenus(closed->mesh.tri, 0);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
