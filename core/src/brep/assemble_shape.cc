#include "brep/assemble_shape.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
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
#include <TopoDS_Vertex.hxx>

namespace meshseg::brep_internal {
namespace {

double VolumeOf(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

// `shell` as a solid oriented outward: ShapeFix_Solid makes it, and
// BRepLib::OrientClosedSolid reverses it if the point at infinity
// classifies inside.
TopoDS_Solid OutwardSolid(const TopoDS_Shell& shell) {
  ShapeFix_Solid fix;
  TopoDS_Solid solid = fix.SolidFromShell(shell);
  BRepLib::OrientClosedSolid(solid);
  return solid;
}

// True if `inner` lies inside `outer`: a vertex of it classifies inside
// (closed shells that do not cross: one vertex decides).
bool Inside(const TopoDS_Shell& inner, const TopoDS_Solid& outer, double tolerance) {
  TopExp_Explorer it(inner, TopAbs_VERTEX);
  if (!it.More()) return false;
  BRepClass3d_SolidClassifier classify(outer, BRep_Tool::Pnt(TopoDS::Vertex(it.Current())),
                                       tolerance);
  return classify.State() == TopAbs_IN;
}

// True if the faces of the closed `shell`, as they came, face out of it
// (the volume it encloses, taken with their orientation, is positive).
bool FacesOut(const TopoDS_Shell& shell) {
  BRep_Builder builder;
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  return VolumeOf(solid) > 0.0;
}

// Closed shells as solids: each body's outer shell with the shells inside it
// as voids. A shell inside an odd number of larger shells is a void of the
// smallest of them if its faces face the other way than that one's (the
// faces come oriented by the mesh's normals, which face into a cavity);
// facing the same way it is a body inside the other (parts of an assembly
// the mesh holds as separate bodies). A shell inside an even number (an
// island in a void) is a body of its own. Empty if a shell encloses no
// volume (it folds onto itself).
std::vector<TopoDS_Solid> SolidsOf(const std::vector<TopoDS_Shell>& shells, double tolerance) {
  const size_t n = shells.size();
  std::vector<TopoDS_Solid> alone(n);
  std::vector<double> volume(n);
  std::vector<char> faces_out(n);
  for (size_t k = 0; k < n; ++k) {
    faces_out[k] = FacesOut(shells[k]);
    alone[k] = OutwardSolid(shells[k]);
    volume[k] = VolumeOf(alone[k]);
    if (!(volume[k] > 0.0)) return {};
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return volume[a] > volume[b]; });
  // For each shell (largest first), the bodies that enclose it.
  std::vector<int> owner(n, -1);  // body shell of a void; -1 for a body
  std::vector<std::vector<size_t>> voids(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t k = order[i];
    int depth = 0;
    size_t smallest = n;
    for (size_t j = 0; j < i; ++j) {
      if (Inside(shells[k], alone[order[j]], tolerance)) {
        ++depth;
        smallest = order[j];
      }
    }
    if (depth % 2 == 1 && faces_out[k] != faces_out[smallest]) {
      owner[k] = static_cast<int>(smallest);
      voids[smallest].push_back(k);
    }
  }
  BRep_Builder builder;
  std::vector<TopoDS_Solid> solids;
  for (const size_t k : order) {
    if (owner[k] >= 0) continue;
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    for (TopExp_Explorer it(alone[k], TopAbs_SHELL); it.More(); it.Next()) {
      builder.Add(solid, it.Current());
    }
    // A void's shell faces into the void: its outward solid's shell reversed.
    for (const size_t v : voids[k]) {
      for (TopExp_Explorer it(alone[v], TopAbs_SHELL); it.More(); it.Next()) {
        builder.Add(solid, it.Current().Reversed());
      }
    }
    solids.push_back(solid);
  }
  return solids;
}

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
  // ShapeFix_Shell orients each shell's faces consistently.
  for (TopoDS_Shell& s : shells) {
    ShapeFix_Shell fix(s);
    fix.Perform();
    s = fix.Shell();
  }
  out.closed = !shells.empty();
  for (const TopoDS_Shell& s : shells) out.closed = out.closed && BRep_Tool::IsClosed(s);

  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  if (out.closed) {
    const std::vector<TopoDS_Solid> solids = SolidsOf(shells, sewing_tolerance);
    for (const TopoDS_Solid& s : solids) {
      out.volume += VolumeOf(s);
      builder.Add(compound, s);
    }
    out.solid_count = static_cast<int>(solids.size());
    out.solid = !solids.empty();
    if (solids.size() == 1) out.shape = solids[0];
  }
  if (!out.solid) {
    for (const TopoDS_Shell& s : shells) builder.Add(compound, s);
    if (shells.size() == 1) out.shape = shells[0];
    out.volume = 0.0;
  }
  if (out.shape.IsNull()) out.shape = compound;
  out.valid = BRepCheck_Analyzer(out.shape).IsValid();
  out.max_tolerance = ShapeAnalysis_ShapeTolerance().Tolerance(out.shape, 1);
  TopTools_IndexedMapOfShape face_map;
  TopExp::MapShapes(out.shape, TopAbs_FACE, face_map);
  out.face_count = face_map.Extent();
  return out;
}

}  // namespace meshseg::brep_internal
