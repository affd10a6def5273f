// The geometry of one B-rep edge: where the two regions' surfaces intersect
// transversally, the branch of their exact intersection (GeomAPI_IntSS; the
// topology stage's closed-form line or circle for a tangent contact) that
// follows the mesh boundary within the tolerance; otherwise a curve fitted
// to the boundary and drawn onto both surfaces (fitted_curve.h).
#ifndef MESHSEG_SRC_BREP_EDGE_CURVE_H_
#define MESHSEG_SRC_BREP_EDGE_CURVE_H_

// meshseg (OpenMesh) headers come before OpenCASCADE ones: OCCT's Handle()
// macro breaks OpenMesh's headers.
#include "meshseg/topology.h"

#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>

#include "brep/trim_curve.h"

namespace meshseg::brep_internal {

// The intersection branches of region pairs, computed once per pair.
class IntersectionCache {
 public:
  // Returns the branches of surfaces[a] ∩ surfaces[b] (a < b).
  const std::vector<Handle(Geom_Curve)>& Branches(int a, int b,
                                                  std::span<const Handle(Geom_Surface)> surfaces);

 private:
  std::map<std::pair<int, int>, std::vector<Handle(Geom_Curve)>> branches_;
};

struct EdgeCurve {
  TrimmedCurve trimmed;
  // On the intersection of its surfaces (gap below the exactness limit).
  bool exact = false;
};

struct EdgeRequest {
  std::span<const Eigen::Vector3d> polyline;  // the mesh boundary, in curve order
  int left = -1;                              // region ids; right -1 at the border
  int right = -1;
  std::optional<Eigen::Vector3d> start;  // vertex points; unset for a closed curve
  std::optional<Eigen::Vector3d> end;
  CurveGeometry hint;       // the topology stage's geometry of the curve
  double tolerance = 0.0;   // accepted deviation from the polyline, model units
  double exact_gap = 0.0;   // a curve this close to both surfaces lies on them
  double l_avg = 0.0;
  // The surfaces cross at an angle that places their intersection within
  // `tolerance` of the true edge (boundary_edges.cc). False along tangent
  // contacts (fillets): there two fitted surfaces cross, if at all, where
  // their fit errors put them, not where the faces meet.
  bool transversal = true;
  // How far a fitted surface may lie off the true one (3 noise sigmas): a
  // curve whose gap to both surfaces is below it lies on them as far as the
  // data can tell.
  double surface_offset = 0.0;
};

// Returns the edge geometry of `request`, or nullopt when not even a fitted
// curve follows the boundary (a degenerate polyline).
std::optional<EdgeCurve> ChooseEdgeCurve(const EdgeRequest& request,
                                         std::span<const Handle(Geom_Surface)> surfaces,
                                         IntersectionCache* cache);

}  // namespace meshseg::brep_internal

#endif  // MESHSEG_SRC_BREP_EDGE_CURVE_H_
