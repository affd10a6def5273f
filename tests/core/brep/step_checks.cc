#include "step_checks.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Eigen/Geometry>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Surface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <StepShape_AdvancedFace.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cmath>
#include <map>
#include "absl/strings/str_cat.h"
#include "mesh/point_index.h"

namespace meshseg::testing {
namespace {

using Eigen::Vector3d;

using mesh_internal::PointIndex;

Vector3d ToEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// Distance from p to triangle (a, b, c) (Ericson, Real-Time Collision
// Detection 5.1.5).
double PointTriangleDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

}  // namespace

absl::StatusOr<StepModel> ReadStep(const std::string& path, const std::string& session_unit) {
  STEPControl_Reader reader;  // initialises the STEP session's parameters
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    return absl::InvalidArgumentError(absl::StrCat("cannot read STEP \"", path, "\""));
  }
  const std::string default_unit = Interface_Static::CVal("xstep.cascade.unit");
  if (!session_unit.empty()) Interface_Static::SetCVal("xstep.cascade.unit", session_unit.c_str());
  const int roots = reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", default_unit.c_str());
  if (roots == 0) {
    return absl::InvalidArgumentError(absl::StrCat("no shape in \"", path, "\""));
  }
  StepModel out;
  out.shape = reader.OneShape();
  const Handle(Transfer_TransientProcess) process =
      reader.WS()->TransferReader()->TransientProcess();
  const Handle(Interface_InterfaceModel) model = reader.WS()->Model();
  std::map<const TopoDS_TShape*, std::string> names;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) entity = model->Value(i);
    const Handle(StepShape_AdvancedFace) face = Handle(StepShape_AdvancedFace)::DownCast(entity);
    if (face.IsNull() || face->Name().IsNull()) continue;
    const TopoDS_Shape shape = TransferBRep::ShapeResult(process, entity);
    if (!shape.IsNull()) names[shape.TShape().get()] = face->Name()->ToCString();
  }
  for (TopExp_Explorer it(out.shape, TopAbs_FACE); it.More(); it.Next()) {
    const auto found = names.find(it.Current().TShape().get());
    out.face_names.push_back(found == names.end() ? "" : found->second);
  }
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (!lengths.IsEmpty()) out.length_unit = lengths.First().ToCString();
  return out;
}

ShapeFacts FactsOf(const TopoDS_Shape& shape) {
  ShapeFacts f;
  f.valid = BRepCheck_Analyzer(shape).IsValid();
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_SOLID, map);
  f.solids = map.Extent();
  map.Clear();
  TopExp::MapShapes(shape, TopAbs_SHELL, map);
  f.shells = map.Extent();
  map.Clear();
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  f.faces = map.Extent();
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndUniqueAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(i));
    const TopTools_ListOfShape& around = edge_faces.FindFromIndex(i);
    if (BRep_Tool::Degenerated(e) || around.Extent() != 1) continue;
    if (!BRep_Tool::IsClosed(e, TopoDS::Face(around.First()))) ++f.free_edges;
  }
  if (f.solids > 0) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    f.volume = props.Mass();
  }
  return f;
}

double EnclosedVolume(const TriMesh& mesh) {
  double six_v = 0.0;
  for (OpenMesh::FaceHandle f : mesh.faces()) {
    auto v = mesh.cfv_begin(f);
    const Vector3d a = meshseg::ToEigen(mesh.point(*v++));
    const Vector3d b = meshseg::ToEigen(mesh.point(*v++));
    const Vector3d c = meshseg::ToEigen(mesh.point(*v));
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

FaceSamples SampleFaces(const TopoDS_Shape& shape, double spacing) {
  FaceSamples out;
  BRepMesh_IncrementalMesh(shape, spacing, false, 0.3, false);
  struct Piece {
    Vector3d p[3];
    gp_Pnt2d uv[3];
  };
  int id = -1;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    ++id;
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || !tri->HasUVNodes()) {
      ++out.untessellated_faces;
      continue;
    }
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    std::vector<Piece> stack;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int n[3];
      tri->Triangle(t).Get(n[0], n[1], n[2]);
      Piece piece;
      for (int k = 0; k < 3; ++k) {
        piece.p[k] = ToEigen(tri->Node(n[k]).Transformed(loc.Transformation()));
        piece.uv[k] = tri->UVNode(n[k]);
      }
      stack.push_back(piece);
    }
    while (!stack.empty()) {
      const Piece piece = stack.back();
      stack.pop_back();
      int longest = 0;
      double length = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double l = (piece.p[(k + 1) % 3] - piece.p[k]).norm();
        if (l > length) {
          length = l;
          longest = k;
        }
      }
      if (length > spacing) {
        const int a = longest, b = (longest + 1) % 3;
        const Vector3d mid = 0.5 * (piece.p[a] + piece.p[b]);
        const gp_Pnt2d mid_uv(0.5 * (piece.uv[a].XY() + piece.uv[b].XY()));
        Piece first = piece, second = piece;
        first.p[b] = mid;
        first.uv[b] = mid_uv;
        second.p[a] = mid;
        second.uv[a] = mid_uv;
        stack.push_back(first);
        stack.push_back(second);
        continue;
      }
      const gp_Pnt2d uv((piece.uv[0].XY() + piece.uv[1].XY() + piece.uv[2].XY()) / 3.0);
      out.points.push_back(ToEigen(surface->Value(uv.X(), uv.Y())));
      out.face.push_back(id);
      out.u.push_back(uv.X());
      out.v.push_back(uv.Y());
    }
  }
  return out;
}

struct ShapeDistance::Impl {
  Impl(const TopoDS_Shape& shape, double spacing_in)
      : spacing(spacing_in),
        samples(SampleFaces(shape, spacing_in)),
        tree(samples.points) {
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
      faces.push_back(TopoDS::Face(it.Current()));
      surfaces.push_back(new ShapeAnalysis_Surface(BRep_Tool::Surface(faces.back())));
    }
  }
  double spacing;
  FaceSamples samples;
  PointIndex tree;  // over samples.points
  std::vector<TopoDS_Face> faces;
  std::vector<Handle(ShapeAnalysis_Surface)> surfaces;
  TopoDS_Shape shape_;
};

ShapeDistance::ShapeDistance(const TopoDS_Shape& shape, double spacing)
    : impl_(new Impl(shape, spacing)) {
  impl_->shape_ = shape;
}
ShapeDistance::~ShapeDistance() { delete impl_; }
const FaceSamples& ShapeDistance::samples() const { return impl_->samples; }

double ShapeDistance::Distance(const Vector3d& p) const {
  const Impl& m = *impl_;
  if (m.samples.points.empty()) return INFINITY;
  constexpr int kNeighbors = 8;
  std::vector<uint32_t> idx;
  std::vector<double> d2;
  m.tree.Nearest(p, kNeighbors, &idx, &d2);
  const size_t found = idx.size();
  double best = std::sqrt(d2[0]);
  std::vector<int> tried;
  for (size_t k = 0; k < found; ++k) {
    const int face = m.samples.face[idx[k]];
    if (std::find(tried.begin(), tried.end(), face) != tried.end()) continue;
    tried.push_back(face);
    const gp_Pnt q(p.x(), p.y(), p.z());
    const gp_Pnt2d uv = m.surfaces[face]->NextValueOfUV(
        gp_Pnt2d(m.samples.u[idx[k]], m.samples.v[idx[k]]), q, 1e-9, m.spacing);
    const gp_Pnt foot = m.surfaces[face]->Value(uv);
    // A foot next to the sample lies in the face; farther off, ask.
    bool inside = (ToEigen(foot) - m.samples.points[idx[k]]).norm() <= 2.0 * m.spacing;
    if (!inside) {
      const BRepClass_FaceClassifier classifier(m.faces[face], uv, 1e-7);
      inside = classifier.State() == TopAbs_IN || classifier.State() == TopAbs_ON;
    }
    if (inside) best = std::min(best, q.Distance(foot));
  }
  return best;
}

double ShapeDistance::ExactDistance(const Vector3d& p) const {
  const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(p.x(), p.y(), p.z()));
  BRepExtrema_DistShapeShape extrema(vertex, impl_->shape_);
  return extrema.IsDone() ? extrema.Value() : INFINITY;
}

struct MeshDistance::Impl {
  explicit Impl(const TriMesh& mesh_in)
      : mesh(mesh_in),
        vertices(Vertices(mesh_in)),
        tree(vertices) {}
  static std::vector<Vector3d> Vertices(const TriMesh& mesh) {
    std::vector<Vector3d> out;
    for (OpenMesh::VertexHandle v : mesh.vertices()) out.push_back(meshseg::ToEigen(mesh.point(v)));
    return out;
  }
  const TriMesh& mesh;
  std::vector<Vector3d> vertices;
  PointIndex tree;  // over vertices
};

MeshDistance::MeshDistance(const TriMesh& mesh) : impl_(new Impl(mesh)) {}
MeshDistance::~MeshDistance() { delete impl_; }

double MeshDistance::Distance(const Vector3d& p) const {
  const Impl& m = *impl_;
  constexpr int kNeighbors = 4;
  std::vector<uint32_t> idx;
  std::vector<double> d2;
  m.tree.Nearest(p, kNeighbors, &idx, &d2);
  const size_t found = idx.size();
  if (found == 0) return INFINITY;
  double best = std::sqrt(d2[0]);
  for (size_t k = 0; k < found; ++k) {
    for (OpenMesh::FaceHandle f : m.mesh.vf_range(OpenMesh::VertexHandle(idx[k]))) {
      auto it = m.mesh.cfv_begin(f);
      const Vector3d a = meshseg::ToEigen(m.mesh.point(*it++));
      const Vector3d b = meshseg::ToEigen(m.mesh.point(*it++));
      const Vector3d c = meshseg::ToEigen(m.mesh.point(*it));
      best = std::min(best, PointTriangleDistance(p, a, b, c));
    }
  }
  return best;
}

EdgeSplitMax MaxDistanceToMesh(const MeshDistance& mesh, const TopoDS_Shape& shape,
                               const std::vector<Vector3d>& points, double edge_margin) {
  std::vector<Vector3d> edge_points;
  for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next()) {
    const BRepAdaptor_Curve c(TopoDS::Edge(it.Current()));
    const double length = GCPnts_AbscissaPoint::Length(c);
    const int n = std::max(2, static_cast<int>(std::ceil(length / (0.25 * edge_margin))));
    for (int k = 0; k <= n; ++k) {
      edge_points.push_back(
          ToEigen(c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / n)));
    }
  }
  EdgeSplitMax out;
  const PointIndex edge_index(edge_points);
  for (const Vector3d& p : points) {
    const double to_edge =
        edge_points.empty() ? INFINITY : (edge_points[edge_index.Closest(p)] - p).norm();
    double& max = to_edge < edge_margin ? out.near : out.away;
    max = std::max(max, mesh.Distance(p));
  }
  return out;
}

}  // namespace meshseg::testing
