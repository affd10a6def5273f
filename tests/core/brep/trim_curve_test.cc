// TrimAlong: a candidate curve laid along a boundary polyline, oriented as
// the polyline runs, trimmed at its vertices or once round when closed, and
// rejected when it cannot follow it.
#include "brep/trim_curve.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <GC_MakeSegment.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

using Eigen::Vector3d;

// Points on the circle of radius r about the z axis from angle a to b.
std::vector<Vector3d> Arc(double r, double a, double b, int n) {
  std::vector<Vector3d> out;
  for (int k = 0; k <= n; ++k) {
    const double t = a + (b - a) * k / n;
    out.emplace_back(r * std::cos(t), r * std::sin(t), 0.0);
  }
  return out;
}

Handle(Geom_Curve) UnitZCircle(double r) {
  return new Geom_Circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), r);
}

TEST(TrimAlong, ClosedClockwiseBoundaryReversesTheCircleOnceRound) {
  const std::vector<Vector3d> polyline = Arc(5.0, 2.0 * std::numbers::pi, 0.0, 60);
  const std::optional<TrimmedCurve> t =
      TrimAlong(UnitZCircle(5.0), polyline, std::nullopt, std::nullopt);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->last - t->first, 2.0 * std::numbers::pi, 1e-9);
  // It starts at the polyline's first point and runs its way.
  EXPECT_NEAR((ToEigen(t->curve->Value(t->first)) - polyline.front()).norm(), 0.0, 1e-6);
  const Vector3d ahead = ToEigen(t->curve->Value(t->first + 0.1));
  EXPECT_LT(ahead.y(), 0.0) << "clockwise about +z";
  EXPECT_LT(t->deviation, 0.01);
}

TEST(TrimAlong, ClosedBsplineIsOrientedByItsSamplesNotByItsClosure) {
  // A closed, non-periodic B-spline circle (as GeomAPI_IntSS returns) and a
  // boundary that starts on its closure point: the first sample's parameter
  // is its first or its last, whichever the projection picks.
  const Handle(Geom_Curve) bspline = GeomConvert::CurveToBSplineCurve(
      new Geom_TrimmedCurve(UnitZCircle(5.0), 0.0, 2.0 * std::numbers::pi));
  ASSERT_FALSE(bspline->IsPeriodic());
  ASSERT_TRUE(bspline->IsClosed());
  for (const bool counterclockwise : {true, false}) {
    const std::vector<Vector3d> polyline =
        counterclockwise ? Arc(5.0, 0.0, 2.0 * std::numbers::pi, 60)
                         : Arc(5.0, 2.0 * std::numbers::pi, 0.0, 60);
    const std::optional<TrimmedCurve> t =
        TrimAlong(bspline, polyline, std::nullopt, std::nullopt);
    ASSERT_TRUE(t.has_value()) << counterclockwise;
    const Vector3d ahead = ToEigen(t->curve->Value(t->first + 0.05 * (t->last - t->first)));
    EXPECT_EQ(ahead.y() > 0.0, counterclockwise) << ahead.transpose();
    EXPECT_LT(t->deviation, 0.01);
  }
}

TEST(TrimAlong, ArcAcrossTheParameterOriginKeepsItsShortWay) {
  // From -30 to +40 degrees: the circle's parameter origin lies inside.
  const double a = -30.0 * std::numbers::pi / 180.0, b = 40.0 * std::numbers::pi / 180.0;
  const std::vector<Vector3d> polyline = Arc(2.0, a, b, 20);
  const std::optional<TrimmedCurve> t =
      TrimAlong(UnitZCircle(2.0), polyline, polyline.front(), polyline.back());
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->last - t->first, b - a, 1e-9);
  EXPECT_LT(t->deviation, 0.01);
}

TEST(TrimAlong, LineIsTrimmedAtItsVerticesAndMeasured) {
  const std::vector<Vector3d> polyline = {{0, 0.1, 0}, {1, -0.1, 0}, {2, 0.1, 0}, {3, 0, 0}};
  const Handle(Geom_Curve) line = new Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(-1, 0, 0));
  const std::optional<TrimmedCurve> t =
      TrimAlong(line, polyline, Vector3d(0, 0, 0), Vector3d(3, 0, 0));
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->last - t->first, 3.0, 1e-9);
  EXPECT_NEAR((ToEigen(t->curve->Value(t->last)) - Vector3d(3, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(t->deviation, 0.1, 1e-9);
  const Handle(Geom_Surface) planes[1] = {new Geom_Plane(gp_Pnt(0, 0, 0.5), gp_Dir(0, 0, 1))};
  TrimmedCurve measured = *t;
  MeasureGap(planes, &measured);
  EXPECT_NEAR(measured.gap, 0.5, 1e-9);
}

TEST(TrimAlong, SegmentIsExtendedAlongItsLineButCannotGoRound) {
  // An intersection may come back as a segment of its line; the edge is
  // trimmed from the whole line, so a segment shorter than the boundary
  // still reaches its end vertex.
  const std::vector<Vector3d> polyline = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  GC_MakeSegment segment(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0));
  const std::optional<TrimmedCurve> t =
      TrimAlong(segment.Value(), polyline, Vector3d(0, 0, 0), Vector3d(2, 0, 0));
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->last - t->first, 2.0, 1e-9);
  EXPECT_NEAR((ToEigen(t->curve->Value(t->last)) - Vector3d(2, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(t->deviation, 0.0, 1e-9);
  const std::optional<TrimmedCurve> closed =
      TrimAlong(segment.Value(), polyline, std::nullopt, std::nullopt);
  EXPECT_FALSE(closed.has_value()) << "an open segment cannot go round";
}

TEST(Resample, SpreadsPointsEvenlyByLength) {
  const std::vector<Vector3d> polyline = {{0, 0, 0}, {1, 0, 0}, {1, 3, 0}};
  const std::vector<Vector3d> r = Resample(polyline, 5);
  ASSERT_EQ(r.size(), 5u);
  EXPECT_NEAR((r[0] - Vector3d(0, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r[1] - Vector3d(1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r[2] - Vector3d(1, 1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r[4] - Vector3d(1, 3, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(DistanceToPolyline(Vector3d(0.5, 1, 0), polyline), 0.5, 1e-12);
}

}  // namespace
}  // namespace meshseg::brep_internal
