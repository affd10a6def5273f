// The faces sewn into shells (BRepBuilderAPI_Sewing), one closed shell made
// a solid (ShapeFix_Solid orients it outward), and what BRepCheck and
// BRepGProp say about the result.
#ifndef MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_
#define MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_

#include <span>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace meshseg::brep_internal {

struct AssembledShape {
  TopoDS_Shape shape;  // a solid, a shell, or a compound of shells
  bool closed = false;
  bool solid = false;
  bool valid = false;
  double volume = 0.0;  // of the solid
  double max_tolerance = 0.0;
  int face_count = 0;
};

// Returns `faces` sewn with `sewing_tolerance` (model units).
AssembledShape AssembleShape(std::span<const TopoDS_Face> faces, double sewing_tolerance);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_ASSEMBLE_SHAPE_H_
