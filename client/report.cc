#include "client/report.h"

#include <map>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "absl/strings/strip.h"

namespace meshseg::cli {
namespace {

std::string Vec(const v1::Vec3& v) { return absl::StrFormat("(%.4g %.4g %.4g)", v.x(), v.y(), v.z()); }

std::string KeyParameters(const v1::Region& r) {
  switch (r.surface_case()) {
    case v1::Region::kPlane:
      return absl::StrCat("n=", Vec(r.plane().normal()));
    case v1::Region::kCylinder:
      return absl::StrFormat("r=%.4g axis=%s", r.cylinder().radius(),
                             Vec(r.cylinder().axis_direction()));
    case v1::Region::kCone:
      return absl::StrFormat("half_angle=%.3f deg apex=%s",
                             r.cone().half_angle() * 57.29577951308232, Vec(r.cone().apex()));
    case v1::Region::kSphere:
      return absl::StrFormat("r=%.4g c=%s", r.sphere().radius(), Vec(r.sphere().center()));
    case v1::Region::kTorus:
      return absl::StrFormat("R=%.4g r=%.4g c=%s", r.torus().major_radius(),
                             r.torus().minor_radius(), Vec(r.torus().center()));
    case v1::Region::kQuadric:
      return "quadric";
    default:
      return "";
  }
}

// "LOOP_KIND_OUTER" -> "outer".
std::string EnumWord(const std::string& name, absl::string_view prefix) {
  return absl::AsciiStrToLower(absl::StripPrefix(name, prefix));
}

std::string FeatureLine(const v1::Feature& f) {
  std::string line = absl::StrFormat(
      "  %-28s regions %s", EnumWord(v1::FeatureType_Name(f.type()), "FEATURE_TYPE_"),
      absl::StrJoin(f.regions(), ","));
  switch (f.type()) {
    case v1::FEATURE_TYPE_LINEAR_EXTRUSION:
      absl::StrAppend(&line, "  direction=", Vec(f.direction()));
      break;
    case v1::FEATURE_TYPE_REVOLUTION:
      absl::StrAppend(&line, "  axis=", Vec(f.direction()), " through ", Vec(f.point()));
      break;
    default:
      absl::StrAppendFormat(&line, "  r=%.4g %s", f.radius(), f.convex() ? "convex" : "concave");
  }
  return line + "\n";
}

}  // namespace

std::string TopologySummary(const v1::SegmentationResult& result) {
  std::map<std::string, int> geometry, loops;
  int sharp = 0;
  for (const v1::BoundaryCurve& c : result.curves()) {
    ++geometry[EnumWord(v1::CurveGeometryType_Name(c.geometry().type()), "CURVE_GEOMETRY_TYPE_")];
    sharp += c.sharp() ? 1 : 0;
  }
  for (const v1::Loop& l : result.loops()) {
    ++loops[EnumWord(v1::LoopKind_Name(l.kind()), "LOOP_KIND_")];
  }
  const auto counts = [](const std::map<std::string, int>& m) {
    return absl::StrJoin(m, ", ", [](std::string* out, const auto& e) {
      absl::StrAppend(out, e.second, " ", e.first);
    });
  };
  std::string out = absl::StrFormat(
      "boundaries: %d curves (%s; %d sharp, %d smooth), %d loops (%s), %d corners, "
      "%d adjacent region pairs\n",
      result.curves_size(), counts(geometry), sharp, result.curves_size() - sharp,
      result.loops_size(), counts(loops), result.corners_size(), result.adjacency_size());
  absl::StrAppend(&out, "features: ", result.features_size(), "\n");
  for (const v1::Feature& f : result.features()) absl::StrAppend(&out, FeatureLine(f));
  return out;
}

std::string RegionTable(const v1::SegmentationResult& result) {
  int64_t labelled = 0;
  for (int label : result.face_labels()) labelled += label >= 0 ? 1 : 0;
  std::string out = absl::StrFormat(
      "%d faces, %d vertices, mean edge %.4g; %d regions cover %d faces\n",
      result.mesh().face_count(), result.mesh().vertex_count(), result.mesh().mean_edge_length(),
      result.regions_size(), labelled);
  if (result.mesh().filled_face_count() > 0) {
    absl::StrAppendFormat(&out, "%d faces close areas no point supports (area %.4g)\n",
                          result.mesh().filled_face_count(), result.mesh().filled_area());
  }
  if (result.point_labels_size() > 0) {
    int64_t points_labelled = 0;
    for (int label : result.point_labels()) points_labelled += label >= 0 ? 1 : 0;
    const int64_t unlabelled =
        result.point_labels_size() - points_labelled - result.point_outlier_count();
    absl::StrAppendFormat(&out, "%d points: %d labelled with a region, %d discarded as outliers",
                          result.point_labels_size(), points_labelled,
                          result.point_outlier_count());
    if (unlabelled > 0) absl::StrAppendFormat(&out, ", %d nearest a face of no region", unlabelled);
    absl::StrAppend(&out, "\n");
  }
  if (result.regions_size() == 0) return out;
  absl::StrAppendFormat(&out, "%4s  %-9s %8s  %-44s %10s\n", "id", "type", "faces",
                        "parameters", "rms");
  for (const v1::Region& r : result.regions()) {
    const std::string type(
        absl::StripPrefix(v1::SurfaceType_Name(r.type()), "SURFACE_TYPE_"));
    absl::StrAppendFormat(&out, "%4d  %-9s %8d  %-44s %10.3g\n", r.id(), type, r.face_count(),
                          KeyParameters(r), r.rms_distance());
  }
  return out;
}

std::string JobLine(const v1::Job& job) {
  const std::string state(absl::StripPrefix(v1::JobState_Name(job.state()), "JOB_STATE_"));
  std::string line = absl::StrFormat("%s  %-9s %s", job.job_id(), state, job.file_name());
  switch (job.state()) {
    case v1::JOB_STATE_QUEUED:
      absl::StrAppend(&line, "  (", job.queue_position(), " ahead)");
      break;
    case v1::JOB_STATE_RUNNING:
      absl::StrAppendFormat(&line, "  %s %.0f%%", job.stage(), 100.0 * job.fraction());
      break;
    case v1::JOB_STATE_SUCCEEDED:
      absl::StrAppend(&line, "  ", job.region_count(), " regions, ", job.face_count(), " faces");
      break;
    default:
      if (!job.error_message().empty()) absl::StrAppend(&line, "  ", job.error_message());
  }
  return line;
}

std::string BrepSummary(const v1::BrepReport& brep) {
  if (!brep.error().empty()) return absl::StrCat("step: not written: ", brep.error(), "\n");
  std::string out = absl::StrFormat(
      "step: %d/%d faces, %s, %s; volume %.6g %s^3; edges %d exact, %d fitted; "
      "tolerance max %.3g (sewing %.3g) %s\n",
      brep.face_count(), brep.patch_count(),
      !brep.solid()            ? (brep.closed() ? "closed shell" : "open shell")
      : brep.solid_count() > 1 ? absl::StrCat(brep.solid_count(), " closed solids")
                               : std::string("closed solid"),
      brep.valid() ? "valid" : "INVALID", brep.volume(), brep.length_unit(),
      brep.exact_edge_count(), brep.fitted_edge_count(), brep.max_tolerance(),
      brep.sewing_tolerance(), brep.length_unit());
  for (const v1::BrepFaceFailure& f : brep.failures()) {
    absl::StrAppendFormat(&out, "  face of region %d patch %d not built: %s\n", f.region(),
                          f.patch(), f.reason());
  }
  return out;
}

}  // namespace meshseg::cli
