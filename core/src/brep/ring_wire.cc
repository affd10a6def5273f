#include "brep/ring_wire.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Vec2d.hxx>

#include "brep/surface_query.h"

namespace meshseg::brep_internal {
namespace {

constexpr int kSamplesPerEdge = 8;

// The surface parameters of `p`, or nullopt where it does not project.
std::optional<gp_Pnt2d> Uv(const Handle(Geom_Surface) & s, const gp_Pnt& p) {
  const std::optional<SurfacePoint> q = ClosestPoint(s, ToEigen(p));
  if (!q) return std::nullopt;
  return gp_Pnt2d(q->u, q->v);
}

// How far the loop turns in u, unwrapped (about +-period once round).
std::optional<double> TurnInU(const Handle(Geom_Surface) & s, double period,
                              const std::vector<TopoDS_Edge>& loop) {
  std::optional<double> last;
  double total = 0.0;
  for (const TopoDS_Edge& e : loop) {
    const BRepAdaptor_Curve c(e);
    const bool reversed = e.Orientation() == TopAbs_REVERSED;
    for (int k = 0; k <= kSamplesPerEdge; ++k) {
      const double f = static_cast<double>(k) / kSamplesPerEdge;
      const double t = c.FirstParameter() + (reversed ? 1.0 - f : f) *
                                                (c.LastParameter() - c.FirstParameter());
      const std::optional<gp_Pnt2d> uv = Uv(s, c.Value(t));
      if (!uv) return std::nullopt;
      if (last) total += std::remainder(uv->X() - *last, period);
      last = uv->X();
    }
  }
  return total;
}

}  // namespace

TopoDS_Wire RingWire(const TopoDS_Face& face, const std::vector<TopoDS_Edge>& a,
                     std::vector<TopoDS_Edge> b, double tolerance, double max_snap,
                     std::string* failure) {
  const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
  if (a.empty() || b.empty() || !s->IsUPeriodic()) {
    *failure = "an axial loop without edges, or a surface that does not close round";
    return {};
  }
  const double period = s->UPeriod();
  const std::optional<double> turn = TurnInU(s, period, a);
  if (!turn || std::abs(*turn) < 0.5 * period) {
    *failure = "an axial loop that does not go round the surface";
    return {};
  }
  const TopoDS_Vertex va = TopExp::FirstVertex(a.front(), true);
  const std::optional<gp_Pnt2d> uv_a = Uv(s, BRep_Tool::Pnt(va));
  // The vertex of loop b nearest loop a's in angle starts b.
  std::optional<gp_Pnt2d> uv_b;
  size_t start = 0;
  for (size_t k = 0; k < b.size(); ++k) {
    const std::optional<gp_Pnt2d> uv = Uv(s, BRep_Tool::Pnt(TopExp::FirstVertex(b[k], true)));
    if (!uv || !uv_a) continue;
    if (!uv_b || std::abs(std::remainder(uv->X() - uv_a->X(), period)) <
                     std::abs(std::remainder(uv_b->X() - uv_a->X(), period))) {
      uv_b = uv;
      start = k;
    }
  }
  if (!uv_a || !uv_b) {
    *failure = "a loop vertex does not project onto the surface";
    return {};
  }
  std::rotate(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(start), b.end());
  const TopoDS_Vertex vb = TopExp::FirstVertex(b.front(), true);
  const gp_Pnt2d from = *uv_a;
  gp_Pnt2d to(from.X() + std::remainder(uv_b->X() - from.X(), period), uv_b->Y());
  // Where the loops' vertices nearly line up the seam is the ruling through
  // loop a's vertex (a parameter line, as meshers expect of seams) and loop
  // b's vertex takes the small distance into its tolerance.
  if (s->Value(from.X(), to.Y()).Distance(BRep_Tool::Pnt(vb)) <= max_snap) {
    to.SetX(from.X());
  }
  GCE2d_MakeSegment segment(from, to);
  if (!segment.IsDone()) {
    *failure = "the loops' vertices coincide on the surface";
    return {};
  }
  // Reversed, the seam leaves loop b where loop a started; forward it
  // leaves loop a one period on, where loop a ended.
  const Handle(Geom2d_Curve) at_start = segment.Value().get();
  const Handle(Geom2d_Curve) at_end = Handle(Geom2d_Curve)::DownCast(
      at_start->Translated(gp_Vec2d((*turn > 0.0 ? 1.0 : -1.0) * period, 0.0)));
  // The vertices sit on the loops' edges, which may miss the surface by their
  // tolerance; the seam's ends lie on it.
  for (const auto& [v, uv] : {std::pair{va, from}, std::pair{vb, to}}) {
    const double d = BRep_Tool::Pnt(v).Distance(s->Value(uv.X(), uv.Y()));
    if (d > BRep_Tool::Tolerance(v)) BRep_Builder().UpdateVertex(v, 1.001 * d + tolerance);
  }
  BRepBuilderAPI_MakeEdge make(at_start, s, va, vb);
  if (!make.IsDone()) {
    *failure = "seam edge construction";
    return {};
  }
  TopoDS_Edge seam = make.Edge();
  BRepLib::BuildCurve3d(seam, tolerance);
  BRep_Builder builder;
  builder.UpdateEdge(seam, at_end, at_start, face, tolerance);
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  for (const TopoDS_Edge& e : a) builder.Add(wire, e);
  builder.Add(wire, seam);
  for (const TopoDS_Edge& e : b) builder.Add(wire, e);
  builder.Add(wire, seam.Reversed());
  wire.Closed(true);
  return wire;
}

}  // namespace meshseg::brep_internal
