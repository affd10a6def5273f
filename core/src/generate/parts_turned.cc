// Parts made of surfaces of revolution: a boss on a plate with torus
// fillets, a stepped shaft, a spherical cap and a free-standing torus.
#include <cmath>
#include <numbers>

#include "generate/parts.h"

namespace meshseg::generate_internal {
namespace {

using V = Eigen::Vector3d;
const V kZ = V::UnitZ();

}  // namespace

// A 60 x 60 x 8 plate with a cylindrical boss (radius 10, height 20) joined
// by a concave torus fillet (radius 4), its top edge rounded by a convex torus
// (radius 2), a bore through boss and plate and a second hole in the plate.
PartSpec PlateBoss() {
  PartBuilder b("plate_boss", 0.5, Tilt(13.0, V(1.0, -2.0, 2.0), V(0.0, 0.0, 0.0)));
  Csg& csg = b.csg();
  const int plate = b.Box(V(-30, -30, -8), V(30, 30, 0),
                          {"plate_left", "plate_right", "plate_front", "plate_back",
                           "plate_bottom", "plate_top"});
  const int boss = csg.Intersection({b.Face("boss", Cylinder{V(0, 0, 0), kZ, 10.0}),
                                     b.Plane("boss_top", V(0, 0, 20), kZ),
                                     b.AuxPlane(V(0, 0, -1), -kZ)});
  // The fillet fills the ring 10 <= r <= 14, 0 <= z <= 4 outside the tube.
  const int fillet = csg.Intersection({
      b.Aux(Cylinder{V(0, 0, 0), kZ, 14.0}), b.AuxPlane(V(0, 0, -1), -kZ),
      b.AuxPlane(V(0, 0, 4), kZ),
      csg.Complement(b.Face("boss_fillet", Torus{V(0, 0, 4), kZ, 14.0, 4.0})),
  });
  // The edge round removes r >= 8, z >= 18 outside the tube.
  const int round = csg.Difference(
      csg.Intersection({b.AuxPlane(V(0, 0, 18), -kZ),
                        csg.Complement(b.Aux(Cylinder{V(0, 0, 0), kZ, 8.0}))}),
      b.Face("boss_edge_round", Torus{V(0, 0, 18), kZ, 8.0, 2.0}));
  const int holes = csg.Union({b.Face("bore", Cylinder{V(0, 0, 0), kZ, 5.0}),
                               b.Face("plate_hole", Cylinder{V(18, -18, 0), kZ, 4.0})});
  return b.Finish(csg.Difference(csg.Union({plate, boss, fillet}), csg.Union({round, holes})),
                  Eigen::AlignedBox3d(V(-30, -30, -8), V(30, 30, 20)));
}

// Coaxial cylinders (radius 12, 8, 5) joined by a 45-degree cone and a flat
// step, with a 45-degree chamfer at the thin end.
PartSpec SteppedShaft() {
  PartBuilder b("stepped_shaft", 0.35, Tilt(31.0, V(1.0, 1.0, 0.0), V(0.0, 0.0, 0.0)));
  Csg& csg = b.csg();
  const double quarter = std::numbers::pi / 4;
  // Radius 12 up to z = 25, then the cone (apex z = 37) down to radius 8.
  const int body1 = csg.Intersection({b.Plane("bottom", V(0, 0, 0), -kZ),
                                      b.Face("cylinder_12", Cylinder{V(0, 0, 0), kZ, 12.0}),
                                      b.Face("cone", Cone{V(0, 0, 37), -kZ, quarter}),
                                      b.AuxPlane(V(0, 0, 29.5), kZ)});
  const int body2 = csg.Intersection({b.Face("cylinder_8", Cylinder{V(0, 0, 0), kZ, 8.0}),
                                      b.AuxPlane(V(0, 0, 28), -kZ),
                                      b.Plane("step", V(0, 0, 55), kZ)});
  // Radius 5 from the step to z = 70, chamfered from z = 68.5 (apex z = 73.5).
  const int body3 = csg.Intersection({b.Face("cylinder_5", Cylinder{V(0, 0, 0), kZ, 5.0}),
                                      b.AuxPlane(V(0, 0, 54), -kZ),
                                      b.Face("chamfer", Cone{V(0, 0, 73.5), -kZ, quarter}),
                                      b.Plane("top", V(0, 0, 70), kZ)});
  return b.Finish(csg.Union({body1, body2, body3}),
                  Eigen::AlignedBox3d(V(-12, -12, 0), V(12, 12, 70)));
}

// A cylinder (radius 15, height 10) capped by a sphere of radius 20 meeting
// its rim, with a spherical dimple (radius 6) in the bottom face.
PartSpec SphereCap() {
  PartBuilder b("sphere_cap", 0.3, Tilt(19.0, V(-2.0, 1.0, 1.0), V(0.0, 0.0, 0.0)));
  Csg& csg = b.csg();
  const double cap_center_z = 10.0 - std::sqrt(20.0 * 20.0 - 15.0 * 15.0);
  const int body = csg.Intersection({b.Plane("bottom", V(0, 0, 0), -kZ),
                                     b.Face("cylinder", Cylinder{V(0, 0, 0), kZ, 15.0}),
                                     b.Face("cap", Sphere{V(0, 0, cap_center_z), 20.0})});
  const int dimple = b.Face("dimple", Sphere{V(0, 0, -2), 6.0});
  return b.Finish(csg.Difference(body, dimple),
                  Eigen::AlignedBox3d(V(-15, -15, 0), V(15, 15, cap_center_z + 20.0)));
}

// A free-standing torus: major radius 15, minor radius 5.
PartSpec TorusRing() {
  PartBuilder b("torus_ring", 0.3, Tilt(37.0, V(1.0, 0.0, 1.0), V(0.0, 0.0, 0.0)));
  const int ring = b.Face("torus", Torus{V(0, 0, 0), kZ, 15.0, 5.0});
  return b.Finish(ring, Eigen::AlignedBox3d(V(-20, -20, -5), V(20, 20, 5)));
}

}  // namespace meshseg::generate_internal
