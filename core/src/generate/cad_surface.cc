// SurfaceOfFace: a B-rep face's exact surface as meshseg's Surface, read from
// the face's own geometry (BRepAdaptor_Surface applies the face's location).
#include <BRepAdaptor_Surface.hxx>
#include <TopAbs_Orientation.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>

#include "generate/cad_tessellation.h"

namespace meshseg::generate_internal {
namespace {

Eigen::Vector3d Vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace

CadFace SurfaceOfFace(const TopoDS_Face& face) {
  const BRepAdaptor_Surface s(face, /*theRestriction=*/false);
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  switch (s.GetType()) {
    case GeomAbs_Plane: {
      const gp_Pln p = s.Plane();
      // The plane's normal is the parametrisation's; the face's outward
      // normal is that, reversed with the face.
      const Eigen::Vector3d n = Vec(p.Axis().Direction().XYZ());
      return {Plane{Vec(p.Location().XYZ()), reversed ? -n : n}, false, "plane"};
    }
    case GeomAbs_Cylinder: {
      const gp_Cylinder c = s.Cylinder();
      return {Cylinder{Vec(c.Location().XYZ()), Vec(c.Axis().Direction().XYZ()), c.Radius()}, false,
              "cylinder"};
    }
    case GeomAbs_Cone: {
      const gp_Cone c = s.Cone();
      // gp_Cone's semi-angle is negative when the cone narrows along its
      // axis; meshseg's axis points from the apex to the opening.
      const Eigen::Vector3d axis = Vec(c.Axis().Direction().XYZ());
      const double a = c.SemiAngle();
      return {Cone{Vec(c.Apex().XYZ()), a < 0.0 ? -axis : axis, a < 0.0 ? -a : a}, false, "cone"};
    }
    case GeomAbs_Sphere: {
      const gp_Sphere sp = s.Sphere();
      return {Sphere{Vec(sp.Location().XYZ()), sp.Radius()}, false, "sphere"};
    }
    case GeomAbs_Torus: {
      const gp_Torus t = s.Torus();
      return {Torus{Vec(t.Location().XYZ()), Vec(t.Axis().Direction().XYZ()), t.MajorRadius(),
                    t.MinorRadius()},
              false, "torus"};
    }
    default:
      return {Quadric{}, true, "freeform"};
  }
}

}  // namespace meshseg::generate_internal
