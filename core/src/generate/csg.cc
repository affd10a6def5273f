#include "generate/csg.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>
#include <utility>
#include <variant>

namespace meshseg::generate_internal {

Leaf MakeLeaf(const Surface& surface, int primitive) {
  Leaf leaf;
  leaf.surface = surface;
  leaf.primitive = primitive;
  leaf.type = TypeOf(surface);
  std::visit(
      [&leaf](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          leaf.origin = s.point;
          leaf.axis = s.normal.normalized();
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          leaf.origin = s.axis_origin;
          leaf.axis = s.axis_direction.normalized();
          leaf.r1 = s.radius;
        } else if constexpr (std::is_same_v<T, Cone>) {
          leaf.origin = s.apex;
          leaf.axis = s.axis_direction.normalized();
          leaf.sin_a = std::sin(s.half_angle);
          leaf.cos_a = std::cos(s.half_angle);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          leaf.origin = s.center;
          leaf.r1 = s.radius;
        } else if constexpr (std::is_same_v<T, Torus>) {
          leaf.origin = s.center;
          leaf.axis = s.axis_direction.normalized();
          leaf.r1 = s.major_radius;
          leaf.r2 = s.minor_radius;
        } else {
          assert(false && "a quadric cannot bound a generated solid");
        }
      },
      surface);
  return leaf;
}

double LeafValue(const Leaf& leaf, const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = p - leaf.origin;
  switch (leaf.type) {
    case SurfaceType::kPlane:
      return v.dot(leaf.axis);
    case SurfaceType::kSphere:
      return v.norm() - leaf.r1;
    case SurfaceType::kCylinder: {
      const double h = v.dot(leaf.axis);
      return std::sqrt(std::max(0.0, v.squaredNorm() - h * h)) - leaf.r1;
    }
    case SurfaceType::kCone: {
      // In the half-plane through the axis: generator (sin a, cos a) from the
      // apex; behind the apex the apex itself is the closest point.
      const double h = v.dot(leaf.axis);
      const double rho = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
      if (rho * leaf.sin_a + h * leaf.cos_a >= 0.0) return rho * leaf.cos_a - h * leaf.sin_a;
      return v.norm();
    }
    case SurfaceType::kTorus: {
      const double h = v.dot(leaf.axis);
      const double rho = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
      return std::hypot(rho - leaf.r1, h) - leaf.r2;
    }
    default:
      assert(false && "unsupported leaf type");
      return 0.0;
  }
}

int Csg::AddLeaf(const Leaf& leaf) {
  leaves_.push_back(leaf);
  nodes_.push_back({Op::kLeaf, static_cast<int>(leaves_.size()) - 1, {}});
  return static_cast<int>(nodes_.size()) - 1;
}

int Csg::Union(std::vector<int> children) {
  assert(!children.empty() && "union of nothing");
  nodes_.push_back({Op::kUnion, -1, std::move(children)});
  return static_cast<int>(nodes_.size()) - 1;
}

int Csg::Intersection(std::vector<int> children) {
  assert(!children.empty() && "intersection of nothing");
  nodes_.push_back({Op::kIntersection, -1, std::move(children)});
  return static_cast<int>(nodes_.size()) - 1;
}

int Csg::Complement(int child) {
  nodes_.push_back({Op::kComplement, -1, {child}});
  return static_cast<int>(nodes_.size()) - 1;
}

Csg::Value Csg::EvalNode(int node, const Eigen::Vector3d& p) const {
  const Node& n = nodes_[node];
  switch (n.op) {
    case Op::kLeaf:
      return {LeafValue(leaves_[n.leaf], p), n.leaf};
    case Op::kComplement: {
      Value v = EvalNode(n.children[0], p);
      v.f = -v.f;
      return v;
    }
    case Op::kUnion: {
      Value best = EvalNode(n.children[0], p);
      for (size_t i = 1; i < n.children.size(); ++i) {
        const Value v = EvalNode(n.children[i], p);
        if (v.f < best.f) best = v;
      }
      return best;
    }
    case Op::kIntersection: {
      Value best = EvalNode(n.children[0], p);
      for (size_t i = 1; i < n.children.size(); ++i) {
        const Value v = EvalNode(n.children[i], p);
        if (v.f > best.f) best = v;
      }
      return best;
    }
  }
  return {};
}

}  // namespace meshseg::generate_internal
