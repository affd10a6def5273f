// The one wire of a face that goes all the way round a periodic surface
// (a bore, a shaft step, a fillet round a boss): its two axial loops joined
// by a seam edge. The seam runs straight in the surface's parameter plane
// from a vertex of one loop to the vertex of the other nearest it in angle
// (the ruling through the first where the second lies within `max_snap` of
// it, else a helix piece), and
// carries two parameter curves one period apart, as OpenCASCADE's seams do.
// The loops keep their vertices, so the edges they share with the
// neighbouring faces stay whole.
#ifndef MESHSEG_SRC_BREP_RING_WIRE_H_
#define MESHSEG_SRC_BREP_RING_WIRE_H_

#include <string>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

namespace meshseg::brep_internal {

// Returns the wire [a, seam, b, seam reversed] on the u-periodic surface of
// `face` (a face without wires yet); `a` and `b` are the two loops' edges in
// wire order, each edge oriented as the wire runs. A null wire, with
// `failure` set, when a loop does not go once round the surface.
TopoDS_Wire RingWire(const TopoDS_Face& face, const std::vector<TopoDS_Edge>& a,
                     std::vector<TopoDS_Edge> b, double tolerance, double max_snap,
                     std::string* failure);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_RING_WIRE_H_
