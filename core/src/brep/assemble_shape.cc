#include "brep/assemble_shape.h"

#include <vector>

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <ShapeAnalysis_ShapeTolerance.hxx>
#include <ShapeFix_Shell.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

namespace meshseg::brep_internal {
namespace {

// True if every edge of `shell` bounds two of its faces (or is a seam or
// degenerate).
bool IsClosedShell(const TopoDS_Shell& shell) { return BRep_Tool::IsClosed(shell); }

}  // namespace

AssembledShape AssembleShape(std::span<const TopoDS_Face> faces, double sewing_tolerance) {
  AssembledShape out;
  BRepBuilderAPI_Sewing sewing(sewing_tolerance);
  for (const TopoDS_Face& f : faces) sewing.Add(f);
  sewing.Perform();
  const TopoDS_Shape sewed = sewing.SewedShape();

  // Shells of the sewn shape; a face left alone is a shell of its own.
  std::vector<TopoDS_Shell> shells;
  for (TopExp_Explorer it(sewed, TopAbs_SHELL); it.More(); it.Next()) {
    shells.push_back(TopoDS::Shell(it.Current()));
  }
  BRep_Builder builder;
  for (TopExp_Explorer it(sewed, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next()) {
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    builder.Add(shell, it.Current());
    shells.push_back(shell);
  }
  out.closed = !shells.empty();
  for (const TopoDS_Shell& s : shells) out.closed = out.closed && IsClosedShell(s);

  if (shells.size() == 1 && out.closed) {
    ShapeFix_Solid fix;
    TopoDS_Solid solid = fix.SolidFromShell(shells[0]);
    BRepLib::OrientClosedSolid(solid);
    GProp_GProps props;
    BRepGProp::VolumeProperties(solid, props);
    out.volume = props.Mass();
    out.shape = solid;
    out.solid = out.volume > 0.0;
  }
  if (!out.solid) {
    // ShapeFix_Shell orients each shell's faces consistently.
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (TopoDS_Shell& s : shells) {
      ShapeFix_Shell fix(s);
      fix.Perform();
      s = fix.Shell();
      builder.Add(compound, s);
    }
    out.shape = shells.size() == 1 ? TopoDS_Shape(shells[0]) : TopoDS_Shape(compound);
    out.volume = 0.0;
  }
  out.valid = BRepCheck_Analyzer(out.shape).IsValid();
  out.max_tolerance = ShapeAnalysis_ShapeTolerance().Tolerance(out.shape, 1);
  TopTools_IndexedMapOfShape face_map;
  TopExp::MapShapes(out.shape, TopAbs_FACE, face_map);
  out.face_count = face_map.Extent();
  return out;
}

}  // namespace meshseg::brep_internal
