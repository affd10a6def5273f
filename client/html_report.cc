#include "client/html_report.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>

#include <bit>
#include <cassert>

#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "client/embedded.h"
#include "meshseg/label_color.h"
#include "meshseg/proto/result_json.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {
namespace {

// Typed arrays read the platform's byte order: little endian wherever a
// browser runs, and here.
static_assert(std::endian::native == std::endian::little, "report buffers are little endian");

// The result without what the binary buffers carry (labels per face, vertex
// and point; curve vertex lists), printed as the result JSON contract.
absl::StatusOr<std::string> ResultForPage(const v1::SegmentationResult& result) {
  v1::SegmentationResult page = result;
  page.clear_face_labels();
  page.clear_vertex_labels();
  page.clear_point_labels();
  page.clear_face_filled();  // per face; MeshInfo keeps the count and area
  for (v1::BoundaryCurve& curve : *page.mutable_curves()) curve.clear_vertices();
  return ResultJson(page);
}

absl::StatusOr<std::string> StructJson(const google::protobuf::Struct& s) {
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(s, &json);
  if (!status.ok()) return absl::InternalError(absl::StrCat("report: ", status.ToString()));
  return json;
}

// Everything but the result and the buffers: title, geometry facts, timings.
google::protobuf::Struct PageFacts(const ReportInputs& inputs) {
  google::protobuf::Struct facts;
  auto& fields = *facts.mutable_fields();
  fields["title"].set_string_value(inputs.title);
  auto& geometry = *fields["geometry"].mutable_struct_value()->mutable_fields();
  const ReportGeometry& g = inputs.geometry;
  const char* kind = g.kind == ReportGeometry::Kind::kTriangles ? "triangles"
                     : g.kind == ReportGeometry::Kind::kPoints  ? "points"
                                                                : "none";
  geometry["kind"].set_string_value(kind);
  geometry["note"].set_string_value(g.note);
  auto* offset = geometry["offset"].mutable_list_value();
  for (const double c : g.offset) offset->add_values()->set_number_value(c);
  auto* timings = fields["timings"].mutable_list_value();
  for (const StageTime& t : inputs.timings) {
    auto& row = *timings->add_values()->mutable_struct_value()->mutable_fields();
    row["stage"].set_string_value(t.stage);
    row["seconds"].set_number_value(t.seconds);
  }
  return facts;
}

template <typename T>
std::string Buffer(const char* id, const std::vector<T>& values) {
  const absl::string_view bytes(reinterpret_cast<const char*>(values.data()),
                                values.size() * sizeof(T));
  return absl::StrCat("<script type=\"application/octet-stream\" id=\"", id, "\">",
                      absl::Base64Escape(bytes), "</script>\n");
}

// JSON inside <script>: "</" would end the element early; "<\/" is the same
// JSON string.
std::string ScriptSafe(absl::string_view json) {
  return absl::StrReplaceAll(json, {{"</", "<\\/"}});
}

}  // namespace

absl::StatusOr<std::string> HtmlReport(const ReportInputs& inputs) {
  assert(inputs.result != nullptr && "a report needs a result");
  const v1::SegmentationResult& result = *inputs.result;
  MESHSEG_ASSIGN_OR_RETURN(std::string result_json, ResultForPage(result));
  MESHSEG_ASSIGN_OR_RETURN(std::string facts_json, StructJson(PageFacts(inputs)));
  // {"result": ..., <facts>}: the facts object with the result spliced in.
  facts_json.insert(1, absl::StrCat("\"result\":", result_json, facts_json.size() > 2 ? "," : ""));

  std::vector<uint8_t> colors;
  colors.reserve(3 * result.regions_size());
  for (const v1::Region& region : result.regions()) {
    for (const uint8_t c : LabelColor(region.id())) colors.push_back(c);
  }
  const ReportGeometry& g = inputs.geometry;
  std::string data =
      absl::StrCat("<script type=\"application/json\" id=\"meshseg-report\">",
                   ScriptSafe(facts_json), "</script>\n", Buffer("meshseg-colors", colors));
  if (g.kind != ReportGeometry::Kind::kNone) {
    absl::StrAppend(&data, Buffer("meshseg-positions", g.positions),
                    Buffer("meshseg-labels", g.labels));
    if (!g.triangles.empty()) absl::StrAppend(&data, Buffer("meshseg-triangles", g.triangles));
    if (!g.sharp_segments.empty())
      absl::StrAppend(&data, Buffer("meshseg-sharp", g.sharp_segments));
    if (!g.smooth_segments.empty()) {
      absl::StrAppend(&data, Buffer("meshseg-smooth", g.smooth_segments));
    }
  }
  return absl::StrReplaceAll(
      embedded::kReportHtml,
      {{"/*MESHSEG_STYLE*/", embedded::kReportCss},
       {"/*MESHSEG_SCRIPT*/", absl::StrCat(embedded::kReportGlJs, "\n", embedded::kReportViewerJs,
                                           "\n", embedded::kReportPageJs)},
       {"<!--MESHSEG_DATA-->", data}});
}

}  // namespace meshseg::cli
