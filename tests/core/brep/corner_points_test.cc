// CornerPoint and CornerOnCurves: exact where surfaces or curves cross,
// between them where they only touch, the start where nothing constrains.
#include "brep/corner_points.h"

#include <cmath>

#include <Geom_Circle.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

constexpr double kExact = 1e-9;

Handle(Geom_Surface) PlaneAt(const gp_Pnt& p, const gp_Dir& n) { return new Geom_Plane(p, n); }

TEST(CornerPoint, ThreePlanesGiveTheirCommonPoint) {
  const Handle(Geom_Surface) planes[3] = {PlaneAt(gp_Pnt(1, 0, 0), gp_Dir(1, 0, 0)),
                                          PlaneAt(gp_Pnt(0, 2, 0), gp_Dir(0, 1, 1)),
                                          PlaneAt(gp_Pnt(0, 0, 3), gp_Dir(0, 0.2, 1))};
  const Vector3d p = CornerPoint(Vector3d(0.7, 1.6, 2.4), planes, 5.0);
  for (const Handle(Geom_Surface) & s : planes) {
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(s);
    EXPECT_NEAR(plane->Pln().Distance(gp_Pnt(p.x(), p.y(), p.z())), 0.0, kExact);
  }
}

TEST(CornerPoint, TwoPlanesGiveTheNearestPointOfTheirLine) {
  const Handle(Geom_Surface) planes[2] = {PlaneAt(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)),
                                          PlaneAt(gp_Pnt(0, 0, 0), gp_Dir(0, 1, 0))};
  const Vector3d p = CornerPoint(Vector3d(0.1, -0.2, 7.0), planes, 5.0);
  EXPECT_NEAR((p - Vector3d(0, 0, 7)).norm(), 0.0, 1e-5) << p.transpose();
}

TEST(CornerPoint, TangentSurfacesMeetHalfway) {
  // A cylinder of radius 2 about the z axis that misses the plane x = 2.1.
  const Handle(Geom_Surface)
      both[2] = {new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0),
                 PlaneAt(gp_Pnt(2.1, 0, 0), gp_Dir(1, 0, 0))};
  const Vector3d p = CornerPoint(Vector3d(2.3, 0.0, 1.0), both, 1.0);
  EXPECT_NEAR(p.x(), 2.05, 1e-4);
  EXPECT_NEAR(p.z(), 1.0, 1e-4);
}

TEST(CornerPoint, NearlyTangentSurfacesLeaveTheCornerAlongThemAtTheStart) {
  // A plane x = 1.98 cutting a cylinder of radius 2 about the z axis (a
  // fillet and its tangent wall, fitted 0.02 apart): they cross at
  // y = +-0.28, where the fit error put them, and the floor z = 0.
  const Handle(Geom_Surface) surfaces[3] = {
      new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0),
      PlaneAt(gp_Pnt(1.98, 0, 0), gp_Dir(1, 0, 0)), PlaneAt(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))};
  const Vector3d start(2.0, 0.05, 0.1);
  const double crossing_y = std::sqrt(4.0 - 1.98 * 1.98);
  // Exact solving runs to the crossing.
  const Vector3d exact = CornerPoint(start, surfaces, 1.0);
  EXPECT_NEAR(exact.y(), crossing_y, 1e-6);
  // With surfaces known to 0.05 and the corner to 0.2 (a mesh edge), the
  // crossing is not trusted: the corner keeps the start's y, lies between
  // the two surfaces across them, and on the floor.
  const Vector3d p = CornerPoint(start, surfaces, 1.0, {.surface_offset = 0.05, .spacing = 0.2});
  EXPECT_NEAR(p.y(), start.y(), 0.01) << p.transpose();
  EXPECT_GT(p.x(), 1.98);
  EXPECT_LT(p.x(), 2.0);
  EXPECT_NEAR(p.z(), 0.0, kExact);
}

TEST(CornerPoint, TransversalSurfacesStayExactWithASurfaceOffset) {
  const Handle(Geom_Surface) planes[3] = {PlaneAt(gp_Pnt(1, 0, 0), gp_Dir(1, 0, 0)),
                                          PlaneAt(gp_Pnt(0, 2, 0), gp_Dir(0, 1, 1)),
                                          PlaneAt(gp_Pnt(0, 0, 3), gp_Dir(0, 0.2, 1))};
  const Vector3d p =
      CornerPoint(Vector3d(0.7, 1.6, 2.4), planes, 5.0, {.surface_offset = 0.1, .spacing = 0.5});
  for (const Handle(Geom_Surface) & s : planes) {
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(s);
    EXPECT_NEAR(plane->Pln().Distance(gp_Pnt(p.x(), p.y(), p.z())), 0.0, kExact);
  }
}

TEST(CornerPoint, TooFarStaysAtTheStart) {
  const Handle(Geom_Surface) planes[3] = {PlaneAt(gp_Pnt(10, 0, 0), gp_Dir(1, 0, 0)),
                                          PlaneAt(gp_Pnt(0, 10, 0), gp_Dir(0, 1, 0)),
                                          PlaneAt(gp_Pnt(0, 0, 10), gp_Dir(0, 0, 1))};
  const Vector3d start(0.5, 0.5, 0.5);
  EXPECT_EQ(CornerPoint(start, planes, 1.0), start);
}

TEST(CornerOnCurves, CrossingLinesGiveTheirCrossing) {
  const Handle(Geom_Curve) lines[2] = {new Geom_Line(gp_Pnt(1, 2, 3), gp_Dir(1, 0, 0)),
                                       new Geom_Line(gp_Pnt(1, 2, 3), gp_Dir(0, 1, 1))};
  const Vector3d p = CornerOnCurves(Vector3d(1.3, 2.2, 2.9), lines, 2.0);
  EXPECT_NEAR((p - Vector3d(1, 2, 3)).norm(), 0.0, kExact);
}

TEST(CornerOnCurves, SkewLinesGiveTheMiddleOfTheirClosestPoints) {
  // Closest points (0, 0, 0) and (0, 0, 0.2).
  const Handle(Geom_Curve) lines[2] = {new Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)),
                                       new Geom_Line(gp_Pnt(0, 0, 0.2), gp_Dir(0, 1, 0))};
  const Vector3d p = CornerOnCurves(Vector3d(0.3, -0.1, 0.5), lines, 2.0);
  EXPECT_NEAR((p - Vector3d(0, 0, 0.1)).norm(), 0.0, 1e-6) << p.transpose();
}

TEST(CornerOnCurves, NearlyTangentCurvesLeaveTheCornerAlongThemAtTheStart) {
  // The floor's edges along a fillet (circle of radius 2) and its wall (line
  // x = 1.98) cross at y = +-0.28; lines known to 0.05 and a corner known
  // to 0.2 do not fix that.
  const Handle(Geom_Curve)
      curves[2] = {new Geom_Circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0),
                   new Geom_Line(gp_Pnt(1.98, 0, 0), gp_Dir(0, 1, 0))};
  const Vector3d start(1.99, 0.05, 0.0);
  EXPECT_NEAR(CornerOnCurves(start, curves, 1.0).y(), std::sqrt(4.0 - 1.98 * 1.98), 1e-6);
  const Vector3d p = CornerOnCurves(start, curves, 1.0, {.surface_offset = 0.05, .spacing = 0.2});
  EXPECT_NEAR(p.y(), start.y(), 0.01) << p.transpose();
  EXPECT_NEAR(p.z(), 0.0, kExact);
}

}  // namespace
}  // namespace meshseg::brep_internal
