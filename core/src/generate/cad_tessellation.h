// A B-rep tessellated as CAD systems export STL, with the B-rep face of every
// triangle and each face's exact surface.
#ifndef MESHSEG_GENERATE_CAD_TESSELLATION_H_
#define MESHSEG_GENERATE_CAD_TESSELLATION_H_

#include <array>
#include <vector>

#include <Eigen/Core>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "absl/status/statusor.h"
#include "meshseg/surface.h"

namespace meshseg::generate_internal {

struct CadFace {
  Surface surface;
  bool freeform = false;  // no analytic type: surface is an empty Quadric
  const char* kind = "";  // "plane", "cylinder", ..., "freeform"
};

struct CadTessellation {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_face;  // index into faces
  std::vector<int> vertex_face;    // one face each vertex lies on
  std::vector<CadFace> faces;      // in TopExp_Explorer order
  // The largest distance of a vertex on an edge to one of its faces'
  // surfaces after SnapToSharedSurfaces (model units).
  double snap_residual = 0.0;
};

// The exact surface of `face`, its normal pointing out of the solid (the
// face's orientation applied).
CadFace SurfaceOfFace(const TopoDS_Face& face);

// Meshes `shape` with BRepMesh_IncrementalMesh (absolute chordal deflection
// `chordal`, angular deflection `angular` radians) and collects the faces'
// triangulations, triangles oriented outwards. Nodes on a B-rep edge are one
// vertex for every face sharing the edge (Poly_PolygonOnTriangulation), so
// the mesh is welded along the edges exactly as the B-rep is. Vertices on an
// edge are then moved onto every analytic surface they touch (the edge as
// the exact intersection, not the boolean's approximated curve).
// Errors: INTERNAL if a face gets no triangulation.
absl::StatusOr<CadTessellation> Tessellate(const TopoDS_Shape& shape, double chordal,
                                           double angular);

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_CAD_TESSELLATION_H_
