#include "step_checks.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <BRepClass_FaceClassifier.hxx>
#include <Eigen/Geometry>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_InterfaceModel.hxx>
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
#include <nanoflann.hpp>

#include "absl/strings/str_cat.h"

namespace meshseg::testing {
namespace {

using Eigen::Vector3d;

struct Cloud {
  const std::vector<Vector3d>& points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>,
                                                   Cloud, 3, uint32_t>;

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

struct FaceSample {
  int face = 0;
  gp_Pnt2d uv;
};

}  // namespace

absl::StatusOr<StepModel> ReadStep(const std::string& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    return absl::InvalidArgumentError(absl::StrCat("cannot read STEP \"", path, "\""));
  }
  if (reader.TransferRoots() == 0) {
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

TwoWayDistance MeasureDistances(const TriMesh& mesh, const TopoDS_Shape& shape, double spacing,
                                double bound) {
  TwoWayDistance out;
  // The tessellation only gives each face's parameter domain; the samples
  // are surface points at its subdivided parameter triangles.
  BRepMesh_IncrementalMesh(shape, spacing, false, 0.3, false);
  std::vector<TopoDS_Face> faces;
  std::vector<Handle(ShapeAnalysis_Surface)> surfaces;
  std::vector<Vector3d> points;
  std::vector<FaceSample> samples;
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face& face = TopoDS::Face(it.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || !tri->HasUVNodes()) {
      ++out.untessellated_faces;
      continue;
    }
    const int id = static_cast<int>(faces.size());
    faces.push_back(face);
    surfaces.push_back(new ShapeAnalysis_Surface(BRep_Tool::Surface(face)));
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int n[3];
      tri->Triangle(t).Get(n[0], n[1], n[2]);
      Vector3d p[3];
      gp_Pnt2d uv[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = ToEigen(tri->Node(n[k]).Transformed(loc.Transformation()));
        uv[k] = tri->UVNode(n[k]);
      }
      const double longest =
          std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
      const int steps = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
      for (int i = 0; i <= steps; ++i) {
        for (int j = 0; i + j <= steps; ++j) {
          const double a = static_cast<double>(i) / steps, b = static_cast<double>(j) / steps;
          const gp_Pnt2d q((1 - a - b) * uv[0].X() + a * uv[1].X() + b * uv[2].X(),
                           (1 - a - b) * uv[0].Y() + a * uv[1].Y() + b * uv[2].Y());
          points.push_back(ToEigen(surfaces[id]->Value(q)));
          samples.push_back({id, q});
        }
      }
    }
  }
  out.samples = static_cast<int>(points.size());
  if (points.empty()) return out;

  // Mesh vertices to the B-rep: the nearest samples' faces, each by the foot
  // of the vertex on its surface when that foot lies in the face.
  const Cloud brep_cloud{points};
  KdTree brep_tree(3, brep_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  brep_tree.buildIndex();
  int over = 0;
  for (OpenMesh::VertexHandle v : mesh.vertices()) {
    const Vector3d p = meshseg::ToEigen(mesh.point(v));
    constexpr int kNeighbors = 8;
    uint32_t idx[kNeighbors];
    double d2[kNeighbors];
    const size_t found = brep_tree.knnSearch(p.data(), kNeighbors, idx, d2);
    double best = std::sqrt(d2[0]);
    std::vector<int> tried;
    for (size_t k = 0; k < found; ++k) {
      const FaceSample& s = samples[idx[k]];
      if (std::find(tried.begin(), tried.end(), s.face) != tried.end()) continue;
      tried.push_back(s.face);
      const gp_Pnt q(p.x(), p.y(), p.z());
      const gp_Pnt2d uv = surfaces[s.face]->NextValueOfUV(s.uv, q, 1e-9, spacing);
      const gp_Pnt foot = surfaces[s.face]->Value(uv);
      // A foot next to the sample lies in the face; farther off, ask.
      bool inside = ToEigen(foot).isApprox(points[idx[k]], 0.0) ||
                    (ToEigen(foot) - points[idx[k]]).norm() <= 2.0 * spacing;
      if (!inside) {
        const BRepClass_FaceClassifier classifier(faces[s.face], uv, 1e-7);
        inside = classifier.State() == TopAbs_IN || classifier.State() == TopAbs_ON;
      }
      if (inside) best = std::min(best, q.Distance(foot));
    }
    out.mesh_to_brep = std::max(out.mesh_to_brep, best);
    out.vertex_distance.push_back(best);
    over += best > bound;
  }
  out.mesh_share_over = static_cast<double>(over) / std::max<size_t>(1, mesh.n_vertices());

  // B-rep samples to the mesh: triangles around the nearest mesh vertices.
  std::vector<Vector3d> vertices;
  for (OpenMesh::VertexHandle v : mesh.vertices()) {
    vertices.push_back(meshseg::ToEigen(mesh.point(v)));
  }
  const Cloud mesh_cloud{vertices};
  KdTree mesh_tree(3, mesh_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  mesh_tree.buildIndex();
  over = 0;
  for (const Vector3d& p : points) {
    constexpr int kNeighbors = 4;
    uint32_t idx[kNeighbors];
    double d2[kNeighbors];
    const size_t found = mesh_tree.knnSearch(p.data(), kNeighbors, idx, d2);
    double best = std::sqrt(d2[0]);
    for (size_t k = 0; k < found; ++k) {
      for (OpenMesh::FaceHandle f : mesh.vf_range(OpenMesh::VertexHandle(idx[k]))) {
        auto it = mesh.cfv_begin(f);
        const Vector3d a = meshseg::ToEigen(mesh.point(*it++));
        const Vector3d b = meshseg::ToEigen(mesh.point(*it++));
        const Vector3d c = meshseg::ToEigen(mesh.point(*it));
        best = std::min(best, PointTriangleDistance(p, a, b, c));
      }
    }
    out.brep_to_mesh = std::max(out.brep_to_mesh, best);
    over += best > bound;
  }
  out.brep_share_over = static_cast<double>(over) / static_cast<double>(points.size());
  return out;
}

}  // namespace meshseg::testing
