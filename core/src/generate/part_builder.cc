#include "generate/part_builder.h"

#include <type_traits>
#include <utility>
#include <variant>

namespace meshseg::generate_internal {

Surface Transformed(const Surface& surface, const Eigen::Isometry3d& motion) {
  const Eigen::Matrix3d rot = motion.linear();
  return std::visit(
      [&](const auto& s) -> Surface {
        using T = std::decay_t<decltype(s)>;
        T t = s;
        if constexpr (std::is_same_v<T, meshseg::Plane>) {
          t.point = motion * s.point;
          t.normal = rot * s.normal;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          t.axis_origin = motion * s.axis_origin;
          t.axis_direction = rot * s.axis_direction;
        } else if constexpr (std::is_same_v<T, Cone>) {
          t.apex = motion * s.apex;
          t.axis_direction = rot * s.axis_direction;
        } else if constexpr (std::is_same_v<T, Sphere>) {
          t.center = motion * s.center;
        } else if constexpr (std::is_same_v<T, Torus>) {
          t.center = motion * s.center;
          t.axis_direction = rot * s.axis_direction;
        }
        return t;
      },
      surface);
}

PartBuilder::PartBuilder(std::string name, double default_voxel_size,
                         const Eigen::Isometry3d& motion)
    : motion_(motion) {
  spec_.name = std::move(name);
  spec_.default_voxel_size = default_voxel_size;
}

int PartBuilder::Face(const std::string& name, const Surface& surface) {
  const int id = static_cast<int>(spec_.primitives.size());
  const Surface world = Transformed(surface, motion_);
  spec_.primitives.push_back({id, name, world});
  return spec_.solid.AddLeaf(MakeLeaf(world, id));
}

int PartBuilder::Aux(const Surface& surface) {
  return spec_.solid.AddLeaf(MakeLeaf(Transformed(surface, motion_), -1));
}

int PartBuilder::Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                     const std::array<std::string, 6>& names) {
  std::vector<int> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = side ? 1.0 : -1.0;
      const Eigen::Vector3d& point = side ? hi : lo;
      const std::string& name = names[2 * axis + side];
      faces.push_back(name.empty() ? AuxPlane(point, n) : Plane(name, point, n));
    }
  }
  return csg().Intersection(std::move(faces));
}

int PartBuilder::RoundCut(const std::string& name, const Eigen::Vector3d& c,
                          const Eigen::Vector3d& axis, const Eigen::Vector3d& n1,
                          const Eigen::Vector3d& n2, double r) {
  // The wedge spanned by n1 and n2 around the axis: bounded by the plane
  // through the axis and n1 (kept on the side of n2) and vice versa.
  const Eigen::Vector3d m1 = (n2 - n2.dot(n1) * n1).normalized();
  const Eigen::Vector3d m2 = (n1 - n1.dot(n2) * n2).normalized();
  const int wedge = csg().Intersection({AuxPlane(c, -m1), AuxPlane(c, -m2)});
  return csg().Difference(wedge, Face(name, Cylinder{c, axis.normalized(), r}));
}

PartSpec PartBuilder::Finish(int root, const Eigen::AlignedBox3d& local_bounds) {
  spec_.solid.SetRoot(root);
  spec_.bounds.setEmpty();
  for (int corner = 0; corner < 8; ++corner) {
    spec_.bounds.extend(motion_ * local_bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  }
  return std::move(spec_);
}

}  // namespace meshseg::generate_internal
