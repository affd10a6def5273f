// HtmlReport: one self-contained page carrying the result (without the label
// arrays the buffers hold), the geometry as base64 binary buffers, the
// timings, and nothing that reaches the network.
#include "client/html_report.h"

#include <gmock/gmock.h>
#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <cstring>

#include "absl/strings/escaping.h"

namespace meshseg::cli {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Returns the text of <script ... id="ID"> ... </script> in `html`.
std::string ScriptText(const std::string& html, const std::string& id) {
  const std::size_t open = html.find("id=\"" + id + "\">");
  if (open == std::string::npos) return "";
  const std::size_t start = html.find('>', open) + 1;
  return html.substr(start, html.find("</script>", start) - start);
}

v1::SegmentationResult SmallResult() {
  v1::SegmentationResult result;
  v1::Region* plane = result.add_regions();
  plane->set_id(0);
  plane->set_type(v1::SURFACE_TYPE_PLANE);
  plane->set_rms_distance(0.25);
  for (const int label : {0, 0, -1}) result.add_face_labels(label);
  result.add_vertex_labels(0);
  result.add_curves()->add_vertices(1);
  result.mutable_estimates()->set_noise_sigma(0.125);
  return result;
}

TEST(HtmlReport, CarriesTheResultBuffersAndTimings) {
  const v1::SegmentationResult result = SmallResult();
  ReportInputs inputs;
  inputs.title = "part</script><b>.stl";
  inputs.result = &result;
  inputs.geometry.kind = ReportGeometry::Kind::kTriangles;
  inputs.geometry.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 0.5f, 1};
  inputs.geometry.triangles = {0, 1, 2, 0, 1, 3, 1, 2, 3};
  inputs.geometry.labels = {0, 0, -1};
  inputs.geometry.sharp_segments = {0, 1};
  inputs.timings = {{"segment", 1.5}, {"total", 2.0}};
  const absl::StatusOr<std::string> html = HtmlReport(inputs);
  ASSERT_TRUE(html.ok()) << html.status();

  const std::string json = ScriptText(*html, "meshseg-report");
  EXPECT_THAT(json, Not(HasSubstr("</"))) << "the title cannot end the script early";
  google::protobuf::Struct page;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(json, &page).ok()) << json;
  const auto& fields = page.fields();
  EXPECT_EQ(fields.at("title").string_value(), "part</script><b>.stl");
  const auto& page_result = fields.at("result").struct_value().fields();
  EXPECT_EQ(page_result.at("regions").list_value().values_size(), 1);
  EXPECT_FALSE(page_result.count("face_labels") > 0 &&
               page_result.at("face_labels").list_value().values_size() > 0)
      << "labels travel as a buffer";
  EXPECT_DOUBLE_EQ(
      page_result.at("estimates").struct_value().fields().at("noise_sigma").number_value(), 0.125);
  EXPECT_EQ(fields.at("timings").list_value().values_size(), 2);
  EXPECT_EQ(fields.at("geometry").struct_value().fields().at("kind").string_value(), "triangles");

  std::string positions;
  ASSERT_TRUE(absl::Base64Unescape(ScriptText(*html, "meshseg-positions"), &positions));
  ASSERT_EQ(positions.size(), 4 * inputs.geometry.positions.size());
  float x = 0;
  std::memcpy(&x, positions.data() + 4 * 9, sizeof x);
  EXPECT_EQ(x, 0.5f);
  std::string labels;
  ASSERT_TRUE(absl::Base64Unescape(ScriptText(*html, "meshseg-labels"), &labels));
  EXPECT_EQ(labels.size(), 4u * 3);
  std::string colors;
  ASSERT_TRUE(absl::Base64Unescape(ScriptText(*html, "meshseg-colors"), &colors));
  EXPECT_EQ(colors.size(), 3u) << "one rgb per region";
  EXPECT_NE(ScriptText(*html, "meshseg-sharp"), "");
  EXPECT_EQ(ScriptText(*html, "meshseg-smooth"), "") << "no smooth curves, no buffer";

  EXPECT_THAT(*html, Not(HasSubstr("MESHSEG_"))) << "every template marker replaced";
  EXPECT_THAT(*html, Not(HasSubstr("http://")));
  EXPECT_THAT(*html, Not(HasSubstr("https://")));
  EXPECT_THAT(*html, HasSubstr("class Viewer")) << "the viewer is inline";
}

TEST(HtmlReport, TablesOnlyWithoutGeometry) {
  const v1::SegmentationResult result = SmallResult();
  ReportInputs inputs;
  inputs.title = "result.json";
  inputs.result = &result;
  inputs.geometry.note = "no mesh given";
  const absl::StatusOr<std::string> html = HtmlReport(inputs);
  ASSERT_TRUE(html.ok()) << html.status();
  EXPECT_EQ(ScriptText(*html, "meshseg-positions"), "");
  EXPECT_THAT(ScriptText(*html, "meshseg-report"), HasSubstr("no mesh given"));
}

}  // namespace
}  // namespace meshseg::cli
