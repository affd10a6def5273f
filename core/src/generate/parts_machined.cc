// Prismatic parts: blocks with bores, grooves, rounded edges and fillets.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "generate/parts.h"

namespace meshseg::generate_internal {
namespace {

using V = Eigen::Vector3d;
const V kX = V::UnitX();
const V kY = V::UnitY();
const V kZ = V::UnitZ();

}  // namespace

// 20 x 14 x 8 block, a through bore and one quarter-round edge: the fast part.
PartSpec SmallBlock() {
  PartBuilder b("small_block", 0.4, Tilt(17.0, V(1.0, 2.0, 3.0), V(1.0, 2.0, 3.0)));
  const int block = b.Box(V(0, 0, 0), V(20, 14, 8),
                          {"left", "right", "front", "back", "bottom", "top"});
  const int round = b.RoundCut("round", V(17, 0, 5), kY, kX, kZ, 3.0);
  const int bore = b.Face("bore", Cylinder{V(7, 7, 0), kZ, 3.5});
  return b.Finish(b.csg().Difference(block, b.csg().Union({round, bore})),
                  Eigen::AlignedBox3d(V(0, 0, 0), V(20, 14, 8)));
}

// The machined test piece: a 90 x 50 x 30 block with a full bore and its
// conical countersink, a half-cylinder groove across the top, three
// quarter-round edges and a conical boss with a flat top.
PartSpec TestPiece(const std::string& name, double default_voxel_size) {
  PartBuilder b(name, default_voxel_size, Tilt(11.0, V(2.0, -1.0, 3.0), V(-40.0, -20.0, 5.0)));
  Csg& csg = b.csg();
  const int block = b.Box(V(0, 0, 0), V(90, 50, 30),
                          {"left", "right", "front", "back", "bottom", "top"});
  const int rounds = csg.Union({
      b.RoundCut("round_front_right", V(84, 6, 0), kZ, kX, -kY, 6.0),
      b.RoundCut("round_back_right", V(84, 44, 0), kZ, kX, kY, 6.0),
      b.RoundCut("round_top_left", V(5, 0, 25), kY, -kX, kZ, 5.0),
  });
  // Frustum from radius 8 at z = 30 to radius 5 at z = 38.
  const double slope = 3.0 / 8.0;
  const int boss = csg.Intersection({
      b.Face("boss_cone", Cone{V(74, 25, 30 + 8.0 / slope), -kZ, std::atan(slope)}),
      b.Plane("boss_top", V(74, 25, 38), kZ),
      b.AuxPlane(V(74, 25, 29), -kZ),
  });
  const int holes = csg.Union({
      b.Face("bore", Cylinder{V(22, 25, 0), kZ, 8.0}),
      // 45 degrees, radius 8 at z = 26 to 12 at the top.
      b.Face("countersink", Cone{V(22, 25, 18), kZ, std::numbers::pi / 4}),
      b.Face("groove", Cylinder{V(52, 0, 30), kY, 7.0}),
  });
  const int solid = csg.Difference(csg.Union({csg.Difference(block, rounds), boss}), holes);
  return b.Finish(solid, Eigen::AlignedBox3d(V(0, 0, 0), V(90, 50, 38)));
}

// An L-block: base and upright joined by a concave cylindrical fillet, with
// convex quarter-rounds on the end of the base and the top of the upright.
PartSpec BlendBlock() {
  PartBuilder b("blend_block", 0.4, Tilt(23.0, V(-1.0, 3.0, 1.0), V(0.0, 0.0, 0.0)));
  Csg& csg = b.csg();
  const int left = b.Plane("left", V(0, 0, 0), -kX);
  const int front = b.Plane("front", V(0, 0, 0), -kY);
  const int back = b.Plane("back", V(0, 30, 0), kY);
  const int bottom = b.Plane("bottom", V(0, 0, 0), -kZ);
  const int base = csg.Intersection({left, front, back, bottom, b.Plane("end", V(50, 0, 0), kX),
                                     b.Plane("base_top", V(0, 0, 10), kZ)});
  const int upright = csg.Intersection({left, front, back, bottom,
                                        b.Plane("upright_face", V(10, 0, 0), kX),
                                        b.Plane("upright_top", V(0, 0, 40), kZ)});
  // Fillet radius 5 in the inner corner (x = 10, z = 10).
  const int fillet = csg.Intersection({
      b.AuxPlane(V(15, 0, 0), kX), b.AuxPlane(V(0, 0, 15), kZ), b.AuxPlane(V(9, 0, 0), -kX),
      b.AuxPlane(V(0, 0, 9), -kZ), front, back,
      csg.Complement(b.Face("inner_fillet", Cylinder{V(15, 0, 15), kY, 5.0})),
  });
  const int rounds = csg.Union({
      b.RoundCut("end_round", V(46, 0, 6), kY, kX, kZ, 4.0),
      b.RoundCut("top_round", V(7, 0, 37), kY, kX, kZ, 3.0),
  });
  return b.Finish(csg.Difference(csg.Union({base, upright, fillet}), rounds),
                  Eigen::AlignedBox3d(V(0, 0, 0), V(50, 30, 40)));
}

// A hexagonal prism (circumradius 20, height 15) with its six vertical edges
// rounded (radius 4) and a central through bore: a linear extrusion.
PartSpec RoundedPrism() {
  PartBuilder b("rounded_prism", 0.35, Tilt(14.0, V(3.0, 1.0, -2.0), V(0.0, 0.0, 0.0)));
  Csg& csg = b.csg();
  const double circumradius = 20.0;
  const double r = 4.0;
  const double apothem = circumradius * std::cos(std::numbers::pi / 6);
  const auto direction = [](double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return V(std::cos(a), std::sin(a), 0.0);
  };
  std::vector<int> faces = {b.Plane("bottom", V(0, 0, 0), -kZ), b.Plane("top", V(0, 0, 15), kZ)};
  std::vector<int> cuts = {b.Face("bore", Cylinder{V(0, 0, 0), kZ, 6.0})};
  for (int k = 0; k < 6; ++k) {
    const V n = direction(60.0 * k);
    faces.push_back(b.Plane("side_" + std::to_string(k), apothem * n, n));
  }
  for (int k = 0; k < 6; ++k) {
    const V c = (apothem - r) / std::cos(std::numbers::pi / 6) * direction(60.0 * k + 30.0);
    cuts.push_back(b.RoundCut("round_" + std::to_string(k), c, kZ, direction(60.0 * k),
                              direction(60.0 * (k + 1)), r));
  }
  return b.Finish(csg.Difference(csg.Intersection(faces), csg.Union(cuts)),
                  Eigen::AlignedBox3d(V(-20, -20, 0), V(20, 20, 15)));
}

}  // namespace meshseg::generate_internal
