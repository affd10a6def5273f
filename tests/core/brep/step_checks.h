// What the brep tests check on a written STEP file, read back with
// OpenCASCADE's STEPControl_Reader: validity, closedness, solids and faces,
// face names, volume, and the two-sided distance between the B-rep and the
// mesh it was built from.
#ifndef MESHSEG_TESTS_CORE_BREP_STEP_CHECKS_H_
#define MESHSEG_TESTS_CORE_BREP_STEP_CHECKS_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/mesh.h"

#include <string>
#include <vector>

#include <Eigen/Core>
#include <TopoDS_Shape.hxx>

#include "absl/status/statusor.h"

namespace meshseg::testing {

struct StepModel {
  TopoDS_Shape shape;
  std::vector<std::string> face_names;  // per face in TopExp_Explorer order ("" unnamed)
  std::string length_unit;              // as the reader names it, e.g. "MM", "INCH"
};

// Returns the shape in `path` (all roots), its face names and unit.
// `session_unit` (e.g. "M"), when given, is the unit the shape is read in
// ("xstep.cascade.unit"); by default OpenCASCADE's, millimetres.
absl::StatusOr<StepModel> ReadStep(const std::string& path, const std::string& session_unit = "");

struct ShapeFacts {
  bool valid = false;  // BRepCheck_Analyzer
  int solids = 0;
  int shells = 0;
  int faces = 0;
  int free_edges = 0;   // edges of one face only (not seams or degenerate)
  double volume = 0.0;  // BRepGProp, of the solids
};

ShapeFacts FactsOf(const TopoDS_Shape& shape);

// The volume the closed, outward-oriented `mesh` encloses.
double EnclosedVolume(const TriMesh& mesh);

// Points on the faces of a shape about `spacing` apart: its tessellation's
// triangles halved at the longest edge down to `spacing`, each piece's
// centroid in the parameter plane taken on the face's surface.
struct FaceSamples {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> face;        // per point: index of its face (TopExp_Explorer order)
  std::vector<double> u, v;     // per point: its surface parameters
  int untessellated_faces = 0;  // faces BRepMesh could not tessellate (not sampled)
};
FaceSamples SampleFaces(const TopoDS_Shape& shape, double spacing);

// Distances from points to a shape's faces.
class ShapeDistance {
 public:
  ShapeDistance(const TopoDS_Shape& shape, double spacing);
  ~ShapeDistance();
  // The distance from `p` to the shape: the foot of `p` on the surfaces of
  // the faces of its nearest samples, where that foot lies in the face, else
  // the distance to the nearest sample.
  double Distance(const Eigen::Vector3d& p) const;
  // The exact distance from `p` to the shape (BRepExtrema_DistShapeShape):
  // slow, for the points Distance() puts beyond a bound (its fallback to the
  // nearest sample overestimates next to an edge).
  double ExactDistance(const Eigen::Vector3d& p) const;
  const FaceSamples& samples() const;

 private:
  struct Impl;
  Impl* impl_;
};

// Distances from points to a triangle mesh's surface.
class MeshDistance {
 public:
  explicit MeshDistance(const TriMesh& mesh);
  ~MeshDistance();
  double Distance(const Eigen::Vector3d& p) const;

 private:
  struct Impl;
  Impl* impl_;
};

// The max over `points` farther than `edge_margin` from every edge of
// `shape` of the distance to `mesh`, and over the points nearer the edges.
struct EdgeSplitMax {
  double away = 0.0;
  double near = 0.0;
};
EdgeSplitMax MaxDistanceToMesh(const MeshDistance& mesh, const TopoDS_Shape& shape,
                               const std::vector<Eigen::Vector3d>& points, double edge_margin);

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_BREP_STEP_CHECKS_H_
