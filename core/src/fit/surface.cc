#include "meshseg/surface.h"

#include <type_traits>

namespace meshseg {

const char* SurfaceTypeName(SurfaceType type) {
  switch (type) {
    case SurfaceType::kPlane: return "plane";
    case SurfaceType::kCylinder: return "cylinder";
    case SurfaceType::kCone: return "cone";
    case SurfaceType::kSphere: return "sphere";
    case SurfaceType::kTorus: return "torus";
    case SurfaceType::kQuadric: return "quadric";
    case SurfaceType::kFreeform: return "freeform";
  }
  return "unknown";
}

SurfaceType TypeOf(const Surface& surface) {
  return std::visit(
      [](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) return SurfaceType::kPlane;
        if constexpr (std::is_same_v<T, Cylinder>) return SurfaceType::kCylinder;
        if constexpr (std::is_same_v<T, Cone>) return SurfaceType::kCone;
        if constexpr (std::is_same_v<T, Sphere>) return SurfaceType::kSphere;
        if constexpr (std::is_same_v<T, Torus>) return SurfaceType::kTorus;
        if constexpr (std::is_same_v<T, Quadric>) return SurfaceType::kQuadric;
      },
      surface);
}

std::optional<AxisLine> AxisOf(const Surface& surface) {
  if (const auto* c = std::get_if<Cylinder>(&surface)) {
    return AxisLine{c->axis_origin, c->axis_direction.normalized()};
  }
  if (const auto* c = std::get_if<Cone>(&surface)) {
    return AxisLine{c->apex, c->axis_direction.normalized()};
  }
  if (const auto* t = std::get_if<Torus>(&surface)) {
    return AxisLine{t->center, t->axis_direction.normalized()};
  }
  return std::nullopt;
}

}  // namespace meshseg
