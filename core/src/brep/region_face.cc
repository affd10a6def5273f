#include "brep/region_face.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepCheck_Status.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "brep/ring_wire.h"

namespace meshseg::brep_internal {
namespace {

// The first problem BRepCheck reports on `face` or its sub-shapes, or "".
std::string CheckFace(const TopoDS_Face& face) {
  BRepCheck_Analyzer analyzer(face);
  if (analyzer.IsValid()) return "";
  const Handle(BRepCheck_Result) result = analyzer.Result(face);
  if (!result.IsNull()) {
    for (const BRepCheck_Status s : result->Status()) {
      if (s == BRepCheck_NoError) continue;
      std::ostringstream name;
      BRepCheck::Print(s, name);
      return absl::StrCat("invalid face (BRepCheck: ",
                          absl::StripAsciiWhitespace(name.str()), ")");
    }
  }
  return "invalid face (BRepCheck: a wire or edge of it)";
}

// `face` healed by ShapeFix_Shape, or null unless that gives one face.
TopoDS_Face Heal(const TopoDS_Face& face, double precision, double max_tolerance) {
  ShapeFix_Shape fix(face);
  fix.SetPrecision(precision);
  fix.SetMaxTolerance(max_tolerance);
  fix.Perform();
  TopExp_Explorer it(fix.Shape(), TopAbs_FACE);
  if (!it.More()) return {};
  const TopoDS_Face healed = TopoDS::Face(it.Current());
  it.Next();
  return it.More() ? TopoDS_Face() : healed;
}

// One loop's edges in wire order, each oriented as the wire runs.
struct LoopEdges {
  LoopKind kind = LoopKind::kOuter;
  std::vector<TopoDS_Edge> edges;
};

TopoDS_Wire WireOf(const std::vector<TopoDS_Edge>& edges) {
  BRep_Builder builder;
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  for (const TopoDS_Edge& e : edges) builder.Add(wire, e);
  wire.Closed(true);
  return wire;
}

double WireLength(const TopoDS_Wire& wire) {
  GProp_GProps props;
  BRepGProp::LinearProperties(wire, props);
  return props.Mass();
}

}  // namespace

RegionFace MakeRegionFace(const Topology& topology, int region, int patch,
                          const Handle(Geom_Surface) & surface, int sign,
                          const BoundaryEdges& edges, double precision, double max_tolerance,
                          double seam_snap) {
  RegionFace out;
  try {
    std::vector<LoopEdges> loops;
    int loop_count = 0;
    for (const int l : topology.regions[region].loops) {
      const Loop& loop = topology.loops[l];
      if (loop.patch != patch) continue;
      ++loop_count;
      // Seen from the surface's normal side the region lies left of its
      // loops when that normal points out of the solid; else the loops run
      // the other way.
      std::vector<CurveUse> uses = loop.curves;
      if (sign < 0) {
        std::reverse(uses.begin(), uses.end());
        for (CurveUse& use : uses) use.reversed = !use.reversed;
      }
      LoopEdges oriented{loop.kind, {}};
      for (const CurveUse& use : uses) {
        if (edges.contracted[use.curve]) continue;
        const TopoDS_Edge& e = edges.edges[use.curve];
        if (e.IsNull()) {
          out.failure = absl::StrCat("edge of curve ", use.curve, " missing: ",
                                     edges.failure[use.curve]);
          return out;
        }
        oriented.edges.push_back(use.reversed ? TopoDS::Edge(e.Reversed()) : e);
      }
      if (!oriented.edges.empty()) loops.push_back(std::move(oriented));
    }
    if (loops.empty() && loop_count > 0) {
      // Every curve around the patch is contracted: the patch is a few faces
      // where regions meet, contracted with them into one vertex.
      out.contracted = true;
      return out;
    }
    BRep_Builder builder;
    TopoDS_Face face;
    if (loops.empty()) {
      // A closed surface without loops (a whole sphere or torus).
      if (!surface->IsUClosed() || !surface->IsVClosed()) {
        out.failure = "no boundary loop and an open surface";
        return out;
      }
      BRepBuilderAPI_MakeFace whole(surface, Precision::Confusion());
      if (!whole.IsDone()) {
        out.failure = "natural bounds of the closed surface";
        return out;
      }
      face = whole.Face();
    } else {
      builder.MakeFace(face, surface, Precision::Confusion());
      std::vector<const LoopEdges*> axial;
      for (const LoopEdges& l : loops) {
        if (l.kind == LoopKind::kAxial) axial.push_back(&l);
      }
      if (axial.size() == 2 && surface->IsUPeriodic()) {
        const TopoDS_Wire ring =
            RingWire(face, axial[0]->edges, axial[1]->edges, precision, seam_snap, &out.failure);
        if (ring.IsNull()) return out;
        builder.Add(face, ring);
      }
      for (const LoopEdges& l : loops) {
        if (l.kind == LoopKind::kAxial && axial.size() == 2 && surface->IsUPeriodic()) continue;
        const TopoDS_Wire wire = WireOf(l.edges);
        // A hole whose loop is narrower than the precision everywhere (area
        // over length) encloses nothing: a closed edge that doubles back.
        if (l.kind == LoopKind::kInner &&
            ShapeAnalysis::ContourArea(wire) < precision * WireLength(wire)) {
          continue;
        }
        builder.Add(face, wire);
      }
    }
    ShapeFix_Face fix(face);
    fix.SetPrecision(precision);
    fix.SetMaxTolerance(max_tolerance);
    fix.FixAddNaturalBoundMode() = loops.empty() ? 1 : 0;
    // No periodic-degenerated fix: on a periodic face built from our own
    // wires, OCCT 7.6's ShapeFix_Face::FixPeriodicDegenerated can crash
    // (a segfault, not a Standard_Failure, so it took the whole process
    // down, on a coarse voxel block). CheckFace and Heal below
    // judge the face either way.
    fix.FixPeriodicDegeneratedMode() = 0;
    fix.Perform();
    face = fix.Face();
    if (sign < 0) face.Reverse();
    out.failure = CheckFace(face);
    if (!out.failure.empty()) {
      // One more try: ShapeFix_Shape's whole face healing (on a face, the
      // outer wire runs counter-clockwise in the parameter plane and holes
      // clockwise, whatever the direction their edges came in).
      const TopoDS_Face healed = Heal(face, precision, max_tolerance);
      if (!healed.IsNull() && CheckFace(healed).empty()) {
        face = healed;
        out.failure.clear();
      }
    }
    if (out.failure.empty()) out.face = face;
  } catch (const Standard_Failure& e) {
    out.failure = absl::StrCat("OpenCASCADE: ", e.GetMessageString());
  }
  return out;
}

}  // namespace meshseg::brep_internal
