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

#include <TopoDS_Shape.hxx>

#include "absl/status/statusor.h"

namespace meshseg::testing {

struct StepModel {
  TopoDS_Shape shape;
  std::vector<std::string> face_names;  // per face in TopExp_Explorer order ("" unnamed)
  std::string length_unit;              // as declared in the file, e.g. "MM"
};

// Returns the shape in `path` (all roots), its face names and unit.
absl::StatusOr<StepModel> ReadStep(const std::string& path);

struct ShapeFacts {
  bool valid = false;   // BRepCheck_Analyzer
  int solids = 0;
  int shells = 0;
  int faces = 0;
  int free_edges = 0;   // edges of one face only (not seams or degenerate)
  double volume = 0.0;  // BRepGProp, of the solids
};

ShapeFacts FactsOf(const TopoDS_Shape& shape);

// The volume the closed, outward-oriented `mesh` encloses.
double EnclosedVolume(const TriMesh& mesh);

struct TwoWayDistance {
  // Max over mesh vertices of the distance to the B-rep, and the share of
  // vertices farther than `bound` (FaceSamples below).
  double mesh_to_brep = 0.0;
  double mesh_share_over = 0.0;
  // Max over points sampled on the B-rep faces (spacing `spacing`) of the
  // distance to the mesh surface, and the share farther than `bound`.
  double brep_to_mesh = 0.0;
  double brep_share_over = 0.0;
  int samples = 0;
  int untessellated_faces = 0;  // faces BRepMesh could not sample (not measured)
  std::vector<double> vertex_distance;  // per mesh vertex, to the B-rep
};

// Returns the distances between `mesh` and `shape`: each mesh vertex to the
// B-rep (nearest face samples, then the exact projection onto those faces'
// surfaces), each B-rep sample to the mesh triangles near it.
TwoWayDistance MeasureDistances(const TriMesh& mesh, const TopoDS_Shape& shape, double spacing,
                                double bound);

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_BREP_STEP_CHECKS_H_
