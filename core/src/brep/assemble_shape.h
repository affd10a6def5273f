// The faces sewn into shells (BRepBuilderAPI_Sewing); closed shells made
// solids (ShapeFix_Solid, oriented outward by BRepLib::OrientClosedSolid),
// one per body, a shell inside a body its void when its faces face the other
// way; and what BRepCheck and BRepGProp say about the result.
#ifndef MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_
#define MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_

#include <span>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace meshseg::brep_internal {

struct AssembledShape {
  TopoDS_Shape shape;  // a solid, a compound of solids, a shell or a compound of shells
  bool closed = false;
  bool solid = false;  // written as solids
  int solid_count = 0;
  bool valid = false;
  double volume = 0.0;  // of the solids
  double max_tolerance = 0.0;
  int face_count = 0;
};

// Returns `faces` sewn with `sewing_tolerance` (model units).
AssembledShape AssembleShape(std::span<const TopoDS_Face> faces, double sewing_tolerance);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_
