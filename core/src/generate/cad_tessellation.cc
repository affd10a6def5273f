// Tessellate: BRepMesh_IncrementalMesh on the solid, then one mesh of all the
// faces' triangulations, welded along the B-rep's edges and vertices.
#include "generate/cad_tessellation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <Bnd_Box.hxx>
#include <BRep_Tool.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include "absl/strings/str_cat.h"
#include "meshseg/fit.h"

namespace meshseg::generate_internal {
namespace {

// Global vertex ids of the nodes on B-rep edges and vertices, shared by every
// face that meets them.
struct Welder {
  TopTools_IndexedMapOfShape edges, corners;
  std::vector<std::vector<int>> edge_nodes;  // per edge: id per polygon position
  std::vector<int> corner_node;              // per B-rep vertex
  CadTessellation* out = nullptr;

  int NewVertex(const gp_Pnt& p, int face) {
    out->vertices.emplace_back(p.X(), p.Y(), p.Z());
    out->vertex_face.push_back(face);
    return static_cast<int>(out->vertices.size()) - 1;
  }

  // The id of the B-rep vertex of `edge` nearest to `p` (a polygon's end).
  int& CornerOf(const TopoDS_Edge& edge, const gp_Pnt& p) {
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    const TopoDS_Vertex& v =
        first.IsNull() || (!last.IsNull() &&
                           BRep_Tool::Pnt(last).Distance(p) < BRep_Tool::Pnt(first).Distance(p))
            ? last
            : first;
    return corner_node[corners.FindIndex(v) - 1];
  }
};

// Moves every vertex shared by faces of analytic surfaces onto all of them.
// An edge the boolean computed as an approximated curve (the intersection of
// two cylinders) lies on its faces only to the edge's tolerance (1e-7 of
// the part here); the true edge is the surfaces' intersection, and
// alternating projections onto them converge to its nearest point where
// they cross (linearly, by the cosine of the angle between their normals).
// Tangent faces (a fillet and its neighbours) already share their nodes
// exactly and are left as they are. Returns the worst distance left.
double SnapToSharedSurfaces(CadTessellation& t, double length) {
  std::vector<std::vector<int>> faces_of(t.vertices.size());
  for (size_t i = 0; i < t.triangles.size(); ++i) {
    for (const int v : t.triangles[i]) {
      std::vector<int>& f = faces_of[v];
      if (std::find(f.begin(), f.end(), t.triangle_face[i]) == f.end())
        f.push_back(t.triangle_face[i]);
    }
  }
  constexpr int kMaxRounds = 200;
  const double enough = 1e-15 * length;
  double worst = 0.0;
  for (size_t v = 0; v < t.vertices.size(); ++v) {
    if (faces_of[v].size() < 2) continue;
    Eigen::Vector3d& p = t.vertices[v];
    auto off = [&] {
      double d = 0.0;
      for (const int f : faces_of[v]) {
        if (!t.faces[f].freeform) d = std::max(d, std::abs(SignedDistance(t.faces[f].surface, p)));
      }
      return d;
    };
    double d = off();
    for (int round = 0; round < kMaxRounds && d > enough; ++round) {
      for (const int f : faces_of[v]) {
        if (!t.faces[f].freeform) p = Project(t.faces[f].surface, p).point;
      }
      d = off();
    }
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace

absl::StatusOr<CadTessellation> Tessellate(const TopoDS_Shape& shape, double chordal,
                                           double angular) {
  BRepMesh_IncrementalMesh mesher(shape, chordal, /*isRelative=*/false, angular,
                                  /*isInParallel=*/false);
  if (!mesher.IsDone()) return absl::InternalError("generate: BRepMesh_IncrementalMesh failed");
  CadTessellation out;
  Welder weld;
  weld.out = &out;
  TopExp::MapShapes(shape, TopAbs_EDGE, weld.edges);
  TopExp::MapShapes(shape, TopAbs_VERTEX, weld.corners);
  weld.edge_nodes.resize(weld.edges.Extent());
  weld.corner_node.assign(weld.corners.Extent(), -1);

  for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) {
    const TopoDS_Face& face = TopoDS::Face(fx.Current());
    const int face_id = static_cast<int>(out.faces.size());
    out.faces.push_back(SurfaceOfFace(face));
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) {
      return absl::InternalError(absl::StrCat("generate: B-rep face ", face_id, " (",
                                              out.faces.back().kind, ") got no triangulation"));
    }
    const gp_Trsf trsf = loc.Transformation();
    auto node = [&](int i) { return tri->Node(i).Transformed(trsf); };
    std::vector<int> global(tri->NbNodes() + 1, -1);
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
      const Handle(Poly_PolygonOnTriangulation) poly =
          BRep_Tool::PolygonOnTriangulation(edge, tri, loc);
      if (poly.IsNull()) continue;
      const int n = poly->NbNodes();
      std::vector<int>& ids = weld.edge_nodes[weld.edges.FindIndex(edge) - 1];
      if (ids.empty()) ids.assign(n, -1);
      const bool degenerated = BRep_Tool::Degenerated(edge);
      for (int i = 0; i < n; ++i) {
        const int local = poly->Node(i + 1);
        const gp_Pnt p = node(local);
        // A polygon's ends are the edge's B-rep vertices; a degenerated edge
        // (a cone's apex, a sphere's pole) is its one vertex all along.
        const bool corner = degenerated || i == 0 || i == n - 1;
        int& id = corner ? weld.CornerOf(edge, p)
                         : (n == static_cast<int>(ids.size()) ? ids[i] : global[local]);
        if (id < 0) id = global[local] >= 0 ? global[local] : weld.NewVertex(p, face_id);
        if (global[local] < 0) global[local] = id;
      }
    }
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      if (global[i] < 0) global[i] = weld.NewVertex(node(i), face_id);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int a, b, c;
      tri->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      const std::array<int, 3> g = {global[a], global[b], global[c]};
      if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) continue;  // collapsed at a pole
      out.triangles.push_back(g);
      out.triangle_face.push_back(face_id);
    }
  }
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  out.snap_residual = SnapToSharedSurfaces(out, std::sqrt(box.SquareExtent()));
  return out;
}

}  // namespace meshseg::generate_internal
