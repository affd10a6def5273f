#include "reconstruct/close_tube.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "clouds.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/surface_mesh.h"
#include "tube_meshes.h"

namespace meshseg::reconstruct_internal {
namespace {

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

// `tri` is one closed manifold of genus `genus`.
void ExpectOneClosedManifoldOfGenus(const TriMesh& tri, int genus) {
  EXPECT_EQ(test::BoundaryEdgeCount(tri), 0);
  EXPECT_EQ(test::NonManifoldVertexCount(tri), 0);
  EXPECT_EQ(test::ComponentCount(tri), 1);
  EXPECT_EQ(Genus(tri), genus);
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

// A washer: the ring of rectangular section ρ in [kInner, kOuter], z in
// [0, height] round the z axis, kNu cells round it and cells kStep square
// on the section, which runs anticlockwise in (ρ, z) from the outer wall's
// foot (so the faces face outwards). Face 2 (i cells + j) + k lies in cell
// (i, j); `section` gets the section's vertices. The walls are tall enough
// that the rings the rims' normals come from (close_tube.cc, up to 9 edges
// in) stay on them.
constexpr double kInner = 10.0, kOuter = 15.0, kHeight = 10.0, kStep = 0.5;

Mesh Washer(double height, std::vector<Eigen::Vector2d>* section) {
  const int across = static_cast<int>(std::lround((kOuter - kInner) / kStep));
  const int up = static_cast<int>(std::lround(height / kStep));
  for (int k = 0; k < up; ++k) section->emplace_back(kOuter, k * kStep);
  for (int k = 0; k < across; ++k) section->emplace_back(kOuter - k * kStep, height);
  for (int k = 0; k < up; ++k) section->emplace_back(kInner, height - k * kStep);
  for (int k = 0; k < across; ++k) section->emplace_back(kInner + k * kStep, 0.0);
  const int nv = static_cast<int>(section->size());
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < kNu; ++i) {
    const double u = 2 * M_PI * i / kNu;
    for (const Eigen::Vector2d& q : *section) {
      vertices.emplace_back(q.x() * std::cos(u), q.x() * std::sin(u), q.y());
    }
  }
  const auto id = [&](int i, int j) { return (i % kNu) * nv + j % nv; };
  for (int i = 0; i < kNu; ++i) {
    for (int j = 0; j < nv; ++j) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return *SurfaceMesh(vertices, triangles, "washer");
}

// The washer's faces whose section edge (p, q) is `seen`.
std::vector<uint8_t> SeenWhere(const Mesh& washer, const std::vector<Eigen::Vector2d>& section,
                               bool (*seen)(const Eigen::Vector2d& p, const Eigen::Vector2d& q)) {
  const int nv = static_cast<int>(section.size());
  std::vector<uint8_t> supported(washer.tri.n_faces());
  for (size_t f = 0; f < supported.size(); ++f) {
    const int j = static_cast<int>(f) / 2 % nv;
    supported[f] = seen(section[j], section[(j + 1) % nv]);
  }
  return supported;
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

// Distance of `p` from the exact washer of `height`: from its section, the
// rectangle [kInner, kOuter] × [0, height] in (ρ, z).
double WasherDistance(const Eigen::Vector3d& p, double height) {
  const double rho = std::hypot(p.x(), p.y());
  const double inside = std::min({rho - kInner, kOuter - rho, p.z(), height - p.z()});
  if (inside >= 0) return inside;
  const double dr = std::max({kInner - rho, rho - kOuter, 0.0});
  const double dz = std::max({-p.z(), p.z() - height, 0.0});
  return std::hypot(dr, dz);
}

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
TEST(CloseTube, ABoreSeenToAboveTheFaceItOpensOntoRunsStraightOnToThatFace) {
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

// The largest distance of a patch vertex from the exact washer of `height`.
double WorstWasherDistance(const ClosedSurface& closed, double height) {
  double worst = 0.0;
  for (const auto f : closed.mesh.tri.faces()) {
    if (!closed.filled[f.idx()]) continue;
    for (const auto v : closed.mesh.tri.fv_range(f)) {
      worst = std::max(worst, WasherDistance(ToEigen(closed.mesh.tri.point(v)), height));
    }
  }
  return worst;
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
TEST(CloseTube, TheFaceABoreOpensOntoIsBentOntoTheWallsItsRimClimbs) {
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
