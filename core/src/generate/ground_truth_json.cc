// GroundTruthJson: the answer key as JSON, field names as in the result JSON.
#include <string>
#include <type_traits>
#include <variant>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "meshseg/generate.h"

namespace meshseg {
namespace {

std::string Num(double x) { return absl::StrFormat("%.17g", x); }

std::string Vec(const Eigen::Vector3d& v) {
  return absl::StrCat("{\"x\": ", Num(v.x()), ", \"y\": ", Num(v.y()), ", \"z\": ", Num(v.z()), "}");
}

// Escapes the characters JSON strings may not hold raw.
std::string Quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += absl::StrFormat("\\u%04x", c);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string Parameters(const Surface& surface) {
  return std::visit(
      [](const auto& s) -> std::string {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          return absl::StrCat("\"plane\": {\"point\": ", Vec(s.point), ", \"normal\": ", Vec(s.normal), "}");
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return absl::StrCat("\"cylinder\": {\"axis_origin\": ", Vec(s.axis_origin),
                              ", \"axis_direction\": ", Vec(s.axis_direction),
                              ", \"radius\": ", Num(s.radius), "}");
        } else if constexpr (std::is_same_v<T, Cone>) {
          return absl::StrCat("\"cone\": {\"apex\": ", Vec(s.apex), ", \"axis_direction\": ",
                              Vec(s.axis_direction), ", \"half_angle\": ", Num(s.half_angle), "}");
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return absl::StrCat("\"sphere\": {\"center\": ", Vec(s.center), ", \"radius\": ",
                              Num(s.radius), "}");
        } else if constexpr (std::is_same_v<T, Torus>) {
          return absl::StrCat("\"torus\": {\"center\": ", Vec(s.center), ", \"axis_direction\": ",
                              Vec(s.axis_direction), ", \"major_radius\": ", Num(s.major_radius),
                              ", \"minor_radius\": ", Num(s.minor_radius), "}");
        } else {
          return absl::StrCat("\"quadric\": {\"coefficients\": [",
                              absl::StrJoin(s.c, ", ", [](std::string* out, double c) {
                                out->append(Num(c));
                              }),
                              "]}");
        }
      },
      surface);
}

// 0/1 flags as a comma-separated list.
std::string Flags(const std::vector<uint8_t>& flags) {
  return absl::StrJoin(flags, ",",
                       [](std::string* o, uint8_t b) { absl::StrAppend(o, static_cast<int>(b)); });
}

// The answer key's fields, without the closing brace.
std::string GroundTruthFields(const GeneratedPart& part) {
  std::string out = absl::StrCat("{\"name\": ", Quoted(part.name), ", \"voxel_size\": ",
                                 Num(part.voxel_size), ", \"noise\": ", Num(part.noise),
                                 ", \"face_count\": ", part.face_primitive.size(),
                                 ",\n \"primitives\": [");
  for (size_t k = 0; k < part.primitives.size(); ++k) {
    const PrimitiveTruth& p = part.primitives[k];
    absl::StrAppend(&out, k ? ",\n  " : "\n  ", "{\"id\": ", p.id, ", \"name\": ", Quoted(p.name),
                    ", \"type\": \"",
                    p.freeform ? "freeform" : SurfaceTypeName(TypeOf(p.surface)), "\"",
                    p.freeform ? "" : ", " + Parameters(p.surface), "}");
  }
  absl::StrAppend(&out, "],\n \"face_primitive\": [", absl::StrJoin(part.face_primitive, ","),
                  "],\n \"face_near_boundary\": [", Flags(part.face_near_boundary), "]");
  return out;
}

}  // namespace

std::string GroundTruthJson(const GeneratedPart& part) {
  return absl::StrCat(GroundTruthFields(part), "}\n");
}

std::string ScanTruthJson(const ScannedPart& scan) {
  return absl::StrCat(GroundTruthFields(scan.part), ",\n \"point_primitive\": [",
                      absl::StrJoin(scan.point_primitive, ","), "],\n \"point_outlier\": [",
                      Flags(scan.is_outlier), "]}\n");
}

}  // namespace meshseg
