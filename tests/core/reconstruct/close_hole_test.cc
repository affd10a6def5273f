#include "reconstruct/close_hole.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = HoleKernel::Point_3;

// Twice the area of face `f` over its longest edge squared (0 when flat).
double AreaRatio(const HoleMesh& sm, HoleMesh::Face_index f) {
  std::vector<Point> p;
  for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) p.push_back(sm.point(v));
  const double longest2 = std::max({CGAL::squared_distance(p[0], p[1]),
                                    CGAL::squared_distance(p[1], p[2]),
                                    CGAL::squared_distance(p[2], p[0])});
  return 2.0 * std::sqrt(CGAL::squared_area(p[0], p[1], p[2])) / longest2;
}

// The area of the faces of `sm` not flagged in "f:filled".
double KeptArea(const HoleMesh& sm) {
  const auto filled = sm.property_map<HoleMesh::Face_index, uint8_t>("f:filled").first;
  double kept = 0.0;
  for (const auto f : sm.faces()) {
    if (!filled[f]) kept += PMP::face_area(f, sm);
  }
  return kept;
}

// The mesh of `points` with faces `kept` and `patch` (corner indices), the
// patch faces flagged in "f:filled".
HoleMesh MeshOf(const std::vector<Point>& points, const std::vector<std::array<int, 3>>& kept,
                const std::vector<std::array<int, 3>>& patch) {
  HoleMesh sm;
  std::vector<HoleMesh::Vertex_index> v;
  for (const Point& p : points) v.push_back(sm.add_vertex(p));
  auto filled = sm.add_property_map<HoleMesh::Face_index, uint8_t>("f:filled", 0).first;
  for (const uint8_t in_patch : {0, 1}) {
    for (const auto& [i, j, k] : in_patch ? patch : kept) {
      const auto f = sm.add_face(v[i], v[j], v[k]);
      EXPECT_TRUE(f.is_valid());
      if (f.is_valid()) filled[f] = in_patch;
    }
  }
  return sm;
}

// `sm` after the flips: closed and valid, with `vertices` and `faces`, no
// flat face, and enclosing `volume` as before.
void ExpectClosedAndNoFlatFace(const HoleMesh& sm, size_t vertices, size_t faces, double volume) {
  EXPECT_TRUE(CGAL::is_closed(sm));
  EXPECT_TRUE(sm.is_valid(false));
  EXPECT_EQ(sm.number_of_vertices(), vertices);
  EXPECT_EQ(sm.number_of_faces(), faces);
  for (const auto f : sm.faces()) EXPECT_GT(AreaRatio(sm, f), 0.1);
  EXPECT_NEAR(PMP::volume(sm), volume, 1e-12);
}

// A tetrahedron a c d e whose face a e c was closed by a patch through the
// midpoint b of its edge a c: the patch faces a b e and b c e and the flat
// a c b (three collinear corners, the apex b on the longest edge a c). The
// edge a c is a loop edge: across it lies the kept face c a d. Flipping a c
// splits the kept face at b, so the closed surface, its area and its
// enclosed volume stay the same and no flat face is left.
TEST(FlipFlatPatchFaces, AFlatPatchFaceOnALoopEdgeSplitsTheKeptFaceAcross) {
  enum { a, c, d, e, b };
  HoleMesh sm = MeshOf({Point(0, 0, 0), Point(2, 0, 0), Point(1, 1.5, 0), Point(1, 0.5, 1),
                        Point(1, 0, 0)},
                       {{c, a, d}, {d, a, e}, {c, d, e}}, {{a, b, e}, {b, c, e}, {a, c, b}});
  ASSERT_TRUE(CGAL::is_closed(sm));
  const double area = PMP::area(sm), volume = PMP::volume(sm), kept = KeptArea(sm);
  size_t flat = 0;
  for (const auto f : sm.faces()) flat += AreaRatio(sm, f) < 1e-9;
  ASSERT_EQ(flat, 1u);  // the patch has the flat face

  FlipFlatPatchFaces(&sm);

  EXPECT_TRUE(CGAL::is_closed(sm));
  EXPECT_TRUE(sm.is_valid(false));
  EXPECT_EQ(sm.number_of_faces(), 6u);
  for (const auto f : sm.faces()) EXPECT_GT(AreaRatio(sm, f), 0.1);
  EXPECT_NEAR(PMP::area(sm), area, 1e-12);
  EXPECT_NEAR(PMP::volume(sm), volume, 1e-12);
  // The kept area is still flagged kept: the two faces that now cover the
  // kept face c a d.
  EXPECT_NEAR(KeptArea(sm), kept, 1e-12);
}

// A tetrahedron u a w t whose face u a w was closed by a patch round a vertex
// x of valence 3: the flat face u a x (u the midpoint of a x, the longest
// edge), the face across a w x and the third face w u x, which lies in the
// plane of a w x and folds back over it. The flip's new edge u w is there
// already, so x is removed: the one triangle u a w is left, the same
// enclosed volume, and no flat face.
TEST(FlipFlatPatchFaces, AFlatFaceRoundAVertexOfValenceThreeLeavesTheTriangleItsFanAmountsTo) {
  enum { a, x, u, w, t };
  HoleMesh sm = MeshOf({Point(0, 0, 0), Point(2, 0, 0), Point(1, 0, 0), Point(1, 1.5, 0),
                        Point(1, 0.5, 1)},
                       {{a, u, t}, {w, a, t}, {u, w, t}, {a, w, x}}, {{u, a, x}, {w, u, x}});
  ASSERT_TRUE(CGAL::is_closed(sm));
  const double volume = PMP::volume(sm);

  FlipFlatPatchFaces(&sm);

  ExpectClosedAndNoFlatFace(sm, 4, 4, volume);
}

// A pyramid on the square p0 p1 p2 p3 (z = 0) with apex t, whose base was
// closed by a patch with two free vertices b and b2 that the bend put on the
// same point, the base's centre: the patch faces p2 b b2 and b p0 b2 have a
// zero-length edge b b2 and their apex at an end of their longest edge, and
// neither end has valence 3, so no flip or removal mends them. Merging b2
// into b leaves the fan of four faces round the centre: the same surface,
// the same volume, no flat face.
TEST(FlipFlatPatchFaces, CoincidentPatchVerticesAreMergedIntoOne) {
  enum { p0, p1, p2, p3, t, b, b2 };
  HoleMesh sm = MeshOf({Point(-1, -1, 0), Point(1, -1, 0), Point(1, 1, 0), Point(-1, 1, 0),
                        Point(0, 0, 1), Point(0, 0, 0), Point(0, 0, 0)},
                       {{p0, p1, t}, {p1, p2, t}, {p2, p3, t}, {p3, p0, t}},
                       {{p1, p0, b}, {p2, p1, b}, {p2, b, b2}, {p3, p2, b2}, {p0, p3, b2},
                        {b, p0, b2}});
  ASSERT_TRUE(CGAL::is_closed(sm));
  const double volume = PMP::volume(sm), kept = KeptArea(sm);

  FlipFlatPatchFaces(&sm);

  ExpectClosedAndNoFlatFace(sm, 6, 8, volume);
  EXPECT_NEAR(KeptArea(sm), kept, 1e-12);
}

// A patch of a flat square hole (loop of 8 vertices round [-1, 1]² in
// z = 0, mean edge 1) whose one free vertex a bad solve left 50 above the
// loop. The membrane lies in the loop's convex hull (maximum principle), so
// the vertex is faired again with the umbrella weights: onto the mean of its
// neighbours, the loop's centre. A vertex within a mean edge of the loop's
// box is left where it is.
TEST(KeepMembraneInsideItsLoop, AFreeVertexFarOutsideTheLoopsBoxIsFairedBackIntoIt) {
  for (const double height : {50.0, 0.3}) {
    HoleMesh sm;
    std::vector<Eigen::Vector3d> loop = {{-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0},
                                         {1, 1, 0},   {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0}};
    std::vector<HoleMesh::Vertex_index> ring;
    for (const auto& p : loop) ring.push_back(sm.add_vertex(Point(p.x(), p.y(), p.z())));
    const auto centre = sm.add_vertex(Point(0.2, -0.1, height));
    for (size_t k = 0; k < ring.size(); ++k) {
      ASSERT_TRUE(sm.add_face(ring[k], ring[(k + 1) % ring.size()], centre).is_valid());
    }
    KeepMembraneInsideItsLoop(loop, {centre}, &sm);
    const Point& x = sm.point(centre);
    if (height > 1.0) {
      EXPECT_NEAR(x.x(), 0.0, 1e-9);
      EXPECT_NEAR(x.y(), 0.0, 1e-9);
      EXPECT_NEAR(x.z(), 0.0, 1e-9);
    } else {
      EXPECT_EQ(x, Point(0.2, -0.1, height));
    }
  }
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
