// PartSpec: a named solid with its ground-truth primitives, and PartBuilder,
// which states a part in its own (local) coordinates and places it in the
// scanner's frame by a rigid motion, so that no face lines up with the grid.
#ifndef MESHSEG_GENERATE_PART_BUILDER_H_
#define MESHSEG_GENERATE_PART_BUILDER_H_

#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "generate/csg.h"
#include "meshseg/generate.h"
#include "meshseg/surface.h"

namespace meshseg::generate_internal {

struct PartSpec {
  std::string name;
  double default_voxel_size = 1.0;  // mm
  Csg solid;                        // world coordinates
  std::vector<PrimitiveTruth> primitives;
  Eigen::AlignedBox3d bounds;       // of the solid, world coordinates
};

// Returns `surface` moved by `motion`.
Surface Transformed(const Surface& surface, const Eigen::Isometry3d& motion);

class PartBuilder {
 public:
  // `motion` maps local to world coordinates.
  PartBuilder(std::string name, double default_voxel_size, const Eigen::Isometry3d& motion);

  // A leaf on a new ground-truth primitive called `name` (local coordinates).
  int Face(const std::string& name, const Surface& surface);
  // A leaf that never shows on the boundary (bounds a piece inside the solid).
  int Aux(const Surface& surface);
  int Plane(const std::string& name, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
    return Face(name, meshseg::Plane{point, normal.normalized()});
  }
  int AuxPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
    return Aux(meshseg::Plane{point, normal.normalized()});
  }
  // Box [lo, hi] from six face leaves named -x, +x, -y, +y, -z, +z; an empty
  // name makes that face auxiliary.
  int Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
          const std::array<std::string, 6>& names);
  // The material to remove to round the convex edge where faces with unit
  // outward normals n1 and n2 (both perpendicular to `axis`) meet: the wedge
  // {c + a n1 + b n2 + t axis : a, b >= 0} outside the cylinder of radius r
  // around the line (c, axis); c lies at distance r inside both faces.
  int RoundCut(const std::string& name, const Eigen::Vector3d& c, const Eigen::Vector3d& axis,
               const Eigen::Vector3d& n1, const Eigen::Vector3d& n2, double r);

  Csg& csg() { return spec_.solid; }

  // Returns the part with solid `root`, which lies inside the local box
  // `local_bounds`.
  PartSpec Finish(int root, const Eigen::AlignedBox3d& local_bounds);

 private:
  Eigen::Isometry3d motion_;
  PartSpec spec_;
};

}  // namespace meshseg::generate_internal

#endif  // MESHSEG_GENERATE_PART_BUILDER_H_
