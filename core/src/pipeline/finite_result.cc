#include "pipeline/finite_result.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"

namespace meshseg::pipeline_internal {
namespace {

// Collects the first non-finite value it is shown, with where it was.
class FiniteCheck {
 public:
  void Value(const std::string& where, double value) {
    if (!found_ && !std::isfinite(value)) {
      found_ = true;
      what_ = absl::StrCat(where, " is ", value);
    }
  }
  void Vector(const std::string& where, const Eigen::Vector3d& v) {
    static constexpr const char* kAxis[] = {".x", ".y", ".z"};
    for (int i = 0; i < 3; ++i) Value(where + kAxis[i], v[i]);
  }
  bool found() const { return found_; }
  const std::string& what() const { return what_; }

 private:
  bool found_ = false;
  std::string what_;
};

void CheckSurface(const std::string& at, const Surface& surface, FiniteCheck& check) {
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          check.Vector(at + " point", s.point);
          check.Vector(at + " normal", s.normal);
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          check.Vector(at + " axis_origin", s.axis_origin);
          check.Vector(at + " axis_direction", s.axis_direction);
          check.Value(at + " radius", s.radius);
        } else if constexpr (std::is_same_v<T, Cone>) {
          check.Vector(at + " apex", s.apex);
          check.Vector(at + " axis_direction", s.axis_direction);
          check.Value(at + " half_angle", s.half_angle);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          check.Vector(at + " center", s.center);
          check.Value(at + " radius", s.radius);
        } else if constexpr (std::is_same_v<T, Torus>) {
          check.Vector(at + " center", s.center);
          check.Vector(at + " axis_direction", s.axis_direction);
          check.Value(at + " major_radius", s.major_radius);
          check.Value(at + " minor_radius", s.minor_radius);
        } else {
          static_assert(std::is_same_v<T, Quadric>);
          for (std::size_t i = 0; i < s.c.size(); ++i) {
            check.Value(absl::StrCat(at, " coefficient ", i), s.c[i]);
          }
        }
      },
      surface);
}

void CheckTopology(const Topology& topology, FiniteCheck& check) {
  for (const BoundaryCurve& c : topology.curves) {
    const std::string at = absl::StrCat("curve ", c.id);
    check.Value(at + " normal_angle_deg", c.normal_angle_deg);
    check.Value(at + " length", c.length);
    check.Vector(at + " point", c.geometry.point);
    check.Vector(at + " direction", c.geometry.direction);
    check.Value(at + " radius", c.geometry.radius);
    check.Value(at + " max_deviation", c.geometry.max_deviation);
  }
  for (const Corner& c : topology.corners) {
    check.Vector(absl::StrCat("corner ", c.id, " position"), c.position);
  }
  check.Value("topology mean_edge_length", topology.mean_edge_length);
}

// Returns OK if `magnitude` (the largest |coordinate| of point `index`) is
// at most kMaxCoordinate; NaN fails too.
absl::Status CheckCoordinate(std::string_view name, std::size_t index, double magnitude) {
  if (magnitude <= kMaxCoordinate) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat(
      "pipeline: \"", std::string(name), "\": point ", index, " has coordinate ", magnitude,
      ", beyond the +-", kMaxCoordinate,
      " whose fourth powers the surface fits can sum without overflow; rescale the part"));
}

}  // namespace

absl::Status CheckCoordinateRange(std::string_view name, std::span<const Eigen::Vector3d> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    MESHSEG_RETURN_IF_ERROR(CheckCoordinate(name, i, points[i].cwiseAbs().maxCoeff()));
  }
  return absl::OkStatus();
}

absl::Status CheckResultFinite(std::string_view name, const PipelineResult& result) {
  FiniteCheck check;
  const MeshStats& mesh = result.mesh;
  check.Value("mesh mean_edge_length", mesh.mean_edge_length);
  check.Vector("mesh bbox_min", mesh.bbox_min);
  check.Vector("mesh bbox_max", mesh.bbox_max);
  for (const Region& r : result.regions) {
    const std::string at = absl::StrCat("region ", r.id, " (", SurfaceTypeName(r.type), ")");
    check.Value(at + " area", r.area);
    check.Value(at + " rms_distance", r.rms_distance);
    check.Value(at + " max_distance", r.max_distance);
    CheckSurface(at, r.surface, check);
  }
  const SegmentEstimates& e = result.estimates;
  check.Value("estimates mean_edge_length", e.mean_edge_length);
  check.Value("estimates noise_sigma", e.noise_sigma);
  check.Value("estimates distance_tolerance", e.distance_tolerance);
  check.Value("estimates angle_tolerance_deg", e.angle_tolerance_deg);
  check.Value("estimates sharp_threshold", e.sharp_threshold);
  check.Value("estimates remesh_edge_length", result.remesh_edge_length);
  check.Value("estimates remesh_fine_edge_length", result.remesh_fine_edge_length);
  CheckTopology(result.topology, check);
  for (const Feature& f : result.features) {
    const std::string at = absl::StrCat("feature ", f.id, " (", FeatureTypeName(f.type), ")");
    check.Value(at + " radius", f.radius);
    check.Value(at + " opening_angle_deg", f.opening_angle_deg);
    check.Vector(at + " direction", f.direction);
    check.Vector(at + " point", f.point);
  }
  if (!check.found()) return absl::OkStatus();
  return absl::InternalError(absl::StrCat(
      "pipeline: \"", std::string(name), "\": non-finite result, ", check.what(),
      " (mesh bounding box ", mesh.bbox_min.x(), ",", mesh.bbox_min.y(), ",", mesh.bbox_min.z(),
      " to ", mesh.bbox_max.x(), ",", mesh.bbox_max.y(), ",", mesh.bbox_max.z(), ")"));
}

}  // namespace meshseg::pipeline_internal
