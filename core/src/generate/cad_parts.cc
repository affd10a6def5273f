// The CAD-mode parts, each built the way a CAD system builds it: primitives
// (BRepPrimAPI), booleans (BRepAlgoAPI) and fillets / chamfers
// (BRepFilletAPI) on exact geometry, in millimetres. Each stresses something
// CAD exports hold: thin walls, bends, countersinks and counterbores, tori,
// small holes next to large planes, one surface split into several faces.
#include "generate/cad_parts.h"

#include <cmath>
#include <functional>
#include <numbers>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Lin.hxx>

namespace meshseg::generate_internal {
namespace {

const gp_Dir kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

TopoDS_Shape Cyl(const gp_Pnt& base, const gp_Dir& axis, double r, double h) {
  return BRepPrimAPI_MakeCylinder(gp_Ax2(base, axis), r, h).Shape();
}

// Null if an operand is null or the boolean fails.
TopoDS_Shape Cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  if (a.IsNull() || b.IsNull()) return {};
  BRepAlgoAPI_Cut op(a, b);
  return op.IsDone() && !op.HasErrors() ? op.Shape() : TopoDS_Shape();
}

TopoDS_Shape Fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  if (a.IsNull() || b.IsNull()) return {};
  BRepAlgoAPI_Fuse op(a, b);
  return op.IsDone() && !op.HasErrors() ? op.Shape() : TopoDS_Shape();
}

TopoDS_Shape Common(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  if (a.IsNull() || b.IsNull()) return {};
  BRepAlgoAPI_Common op(a, b);
  return op.IsDone() && !op.HasErrors() ? op.Shape() : TopoDS_Shape();
}

// The closed polygon `points` (a plane figure) swept along `sweep`.
TopoDS_Shape PolygonPrism(const std::vector<gp_Pnt>& points, const gp_Vec& sweep) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& p : points) polygon.Add(p);
  polygon.Close();
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(polygon.Wire());
  return BRepPrimAPI_MakePrism(face, sweep).Shape();
}

using EdgeTest = std::function<bool(const BRepAdaptor_Curve&)>;

// Blends the edges of `shape` that pass `test`: a fillet of `size` (radius),
// or a 45-degree chamfer of `size` (distance) if `chamfer`.
TopoDS_Shape Blend(const TopoDS_Shape& shape, double size, const EdgeTest& test,
                   bool chamfer = false) {
  if (shape.IsNull()) return {};
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  BRepFilletAPI_MakeFillet fillet(shape);
  BRepFilletAPI_MakeChamfer cham(shape);
  int added = 0;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (!test(BRepAdaptor_Curve(e))) continue;
    chamfer ? cham.Add(size, e) : fillet.Add(size, e);
    ++added;
  }
  if (added == 0) return {};
  BRepFilletAPI_LocalOperation& op = chamfer ? static_cast<BRepFilletAPI_LocalOperation&>(cham)
                                             : static_cast<BRepFilletAPI_LocalOperation&>(fillet);
  op.Build();
  return op.IsDone() ? op.Shape() : TopoDS_Shape();
}

// A straight edge along `dir` through the line {x = at.X(), z = at.Z()}
// (coordinates other than along dir compared).
EdgeTest LineThrough(const gp_Pnt& at, const gp_Dir& dir) {
  return [at, dir](const BRepAdaptor_Curve& c) {
    if (c.GetType() != GeomAbs_Line || !c.Line().Direction().IsParallel(dir, 1e-9)) return false;
    return gp_Lin(at, dir).Distance(c.Value(0.5 * (c.FirstParameter() + c.LastParameter()))) < 1e-6;
  };
}

// A circle of radius r about the z axis at height z.
EdgeTest CircleAt(double r, double z) {
  return [r, z](const BRepAdaptor_Curve& c) {
    if (c.GetType() != GeomAbs_Circle) return false;
    const gp_Circ k = c.Circle();
    return std::abs(k.Radius() - r) < 1e-6 && std::abs(k.Location().Z() - z) < 1e-6 &&
           k.Axis().Direction().IsParallel(kZ, 1e-9);
  };
}

// A tube of wall 0.6 (2 % of its length): two coaxial cylinders whose facets
// nearly touch, and two thin annular ends.
TopoDS_Shape ThinTube() {
  return Cut(Cyl(gp_Pnt(0, 0, 0), kZ, 10.0, 30.0), Cyl(gp_Pnt(0, 0, -1), kZ, 9.4, 32.0));
}

// A sheet-metal L bracket, 2 thick: a bend of inner radius 3 (two coaxial
// fillet cylinders, r 3 and 5), holes through both flanges.
TopoDS_Shape SheetBracket() {
  TopoDS_Shape s = PolygonPrism({gp_Pnt(0, 0, 0), gp_Pnt(40, 0, 0), gp_Pnt(40, 0, 2),
                                 gp_Pnt(2, 0, 2), gp_Pnt(2, 0, 30), gp_Pnt(0, 0, 30)},
                                gp_Vec(0, 30, 0));
  s = Blend(s, 3.0, LineThrough(gp_Pnt(2, 0, 2), kY));
  s = Blend(s, 5.0, LineThrough(gp_Pnt(0, 0, 0), kY));
  s = Cut(s, Cyl(gp_Pnt(20, 10, -1), kZ, 1.5, 4.0));
  s = Cut(s, Cyl(gp_Pnt(32, 20, -1), kZ, 1.5, 4.0));
  return Cut(s, Cyl(gp_Pnt(-1, 15, 18), kX, 2.5, 4.0));
}

// A 60 x 40 x 4 plate with rounded corners: three holes of r 0.8 near a
// corner, a countersunk hole (r 2 under a 90-degree cone) and a counterbored
// one (r 1.7 under r 3, 2 deep).
TopoDS_Shape PlateHoles() {
  TopoDS_Shape s = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60.0, 40.0, 4.0).Shape();
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {60.0, 0.0}, {60.0, 40.0}, {0.0, 40.0}}) {
    s = Blend(s, 3.0, LineThrough(gp_Pnt(x, y, 0), kZ));
  }
  for (const auto& [x, y] : {std::pair{5.0, 5.0}, {8.0, 5.0}, {5.0, 8.0}}) {
    s = Cut(s, Cyl(gp_Pnt(x, y, -1), kZ, 0.8, 6.0));
  }
  s = Cut(s, Cyl(gp_Pnt(20, 20, -1), kZ, 2.0, 6.0));
  s = Cut(s, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(20, 20, 2), kZ), 2.0, 4.5, 2.5).Shape());
  s = Cut(s, Cyl(gp_Pnt(40, 20, -1), kZ, 1.7, 6.0));
  return Cut(s, Cyl(gp_Pnt(40, 20, 2), kZ, 3.0, 3.0));
}

// A hex nut, 20 across flats, 8 high, bore r 5: both ends chamfered by
// cones of half angle 60 that the six flats cut into six patches each.
TopoDS_Shape HexNut() {
  const double r = 10.0 / std::cos(std::numbers::pi / 6.0);
  std::vector<gp_Pnt> hex;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    hex.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  const double t = std::tan(std::numbers::pi / 3.0);
  // Radius 10.5 at the end faces, between the flats (10) and the corners.
  auto chamfer = [t](double base, const gp_Dir& up) {
    return BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(0, 0, base), up), 10.5 + 9.0 * t, 10.5 - t, 10.0)
        .Shape();
  };
  TopoDS_Shape s = PolygonPrism(hex, gp_Vec(0, 0, 8));
  s = Common(s, chamfer(-1.0, kZ));
  s = Common(s, chamfer(9.0, -kZ));
  return Cut(s, Cyl(gp_Pnt(0, 0, -1), kZ, 5.0, 10.0));
}

// A block with a bore r 4 split into two faces by an inner groove (r 6), and
// a cross hole r 2 through the bore, itself split into two faces by it.
TopoDS_Shape CrossBore() {
  TopoDS_Shape s = BRepPrimAPI_MakeBox(gp_Pnt(-15, -12, 0), 30.0, 24.0, 20.0).Shape();
  s = Cut(s, Cyl(gp_Pnt(0, 0, -1), kZ, 4.0, 22.0));
  s = Cut(s, Cyl(gp_Pnt(0, 0, 8.5), kZ, 6.0, 3.0));
  return Cut(s, Cyl(gp_Pnt(-16, 0, 4), kX, 2.0, 32.0));
}

// A turned shaft r 6 on a flange r 15: fillets r 2 (shaft root) and r 1
// (flange rim) are tori, a 1 mm chamfer on the shaft's end a cone, a
// spherical centre dimple r 3, four holes r 1.5 through the flange.
TopoDS_Shape FlangeShaft() {
  TopoDS_Shape s = Fuse(Cyl(gp_Pnt(0, 0, 0), kZ, 15.0, 4.0), Cyl(gp_Pnt(0, 0, 4), kZ, 6.0, 26.0));
  s = Blend(s, 2.0, CircleAt(6.0, 4.0));
  s = Blend(s, 1.0, CircleAt(15.0, 4.0));
  s = Blend(s, 1.0, CircleAt(6.0, 30.0), /*chamfer=*/true);
  s = Cut(s, BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 31.5), 3.0).Shape());
  for (int k = 0; k < 4; ++k) {
    const double a = (0.25 + 0.5 * k) * std::numbers::pi;
    s = Cut(s, Cyl(gp_Pnt(11 * std::cos(a), 11 * std::sin(a), -1), kZ, 1.5, 6.0));
  }
  return s;
}

struct Entry {
  const char* name;
  TopoDS_Shape (*make)();
};

constexpr Entry kCatalogue[] = {
    {"cad_tube", ThinTube},          {"cad_nut", HexNut},
    {"cad_cross_bore", CrossBore},   {"cad_bracket", SheetBracket},
    {"cad_plate_holes", PlateHoles}, {"cad_flange_shaft", FlangeShaft},
};

}  // namespace

std::optional<TopoDS_Shape> FindCadPart(std::string_view name) {
  for (const Entry& e : kCatalogue) {
    if (name != e.name) continue;
    try {
      return e.make();
    } catch (const Standard_Failure&) {
      return TopoDS_Shape();
    }
  }
  return std::nullopt;
}

std::vector<std::string> CadCatalogueNames() {
  std::vector<std::string> names;
  for (const Entry& e : kCatalogue) names.emplace_back(e.name);
  return names;
}

}  // namespace meshseg::generate_internal
