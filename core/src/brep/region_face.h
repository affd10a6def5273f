// One B-rep face per region patch: its surface bounded by the wires of the
// patch's loops (outer, inner and axial; junction artifacts contracted),
// oriented so the face's normal points out of the solid. ShapeFix_Face adds
// the parameter-space curves, the seam of a face that goes all the way
// round a periodic surface and natural bounds for a closed surface without
// loops.
#ifndef MESHSEG_SRC_BREP_REGION_FACE_H_
#define MESHSEG_SRC_BREP_REGION_FACE_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/topology.h"

#include <span>
#include <string>

#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "brep/boundary_edges.h"

namespace meshseg::brep_internal {

struct RegionFace {
  TopoDS_Face face;     // null on failure or when contracted
  std::string failure;  // why it failed
  // Every curve around the patch is contracted (BoundaryEdges): no face,
  // and no failure.
  bool contracted = false;
};

// Returns the face of patch `patch` of region `region` on `surface`
// (`sign` +1 when its normal points out of the solid) bounded by `edges`.
// `precision` and `max_tolerance` bound ShapeFix; `seam_snap` is how far a
// vertex of a loop may lie off the seam's parameter line and still take it
// into its tolerance (RingWire's max_snap): a distance the surfaces' noise
// allows, not the curve tolerance.
RegionFace MakeRegionFace(const Topology& topology, int region, int patch,
                          const Handle(Geom_Surface) & surface, int sign,
                          const BoundaryEdges& edges, double precision, double max_tolerance,
                          double seam_snap);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_REGION_FACE_H_
