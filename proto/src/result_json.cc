#include "meshseg/proto/result_json.h"

#include <google/protobuf/stubs/strutil.h>
#include <google/protobuf/util/json_util.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

// The printer's options: DESIGN.md "Result JSON".
google::protobuf::util::JsonPrintOptions PrintOptions() {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;    // DESIGN.md: snake_case names
  options.always_print_primitive_fields = true;  // region id 0, zero counts
  options.always_print_enums_as_ints = false;    // enums as names
  options.add_whitespace = false;
  return options;
}

absl::StatusOr<std::string> PrintWithProtobuf(const v1::SegmentationResult& result) {
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(result, &json, PrintOptions());
  if (!status.ok()) {
    return absl::InternalError(
        absl::StrCat("result json: printer failed: ", status.ToString()));
  }
  return json;
}

// The flat arrays of a result (one entry per face, vertex or point, and the
// mesh geometry's) hold nearly all of a large result's values; protobuf's
// printer takes them through its generic value tree one by one. They are
// printed here instead, in the printer's own notation, and spliced into
// protobuf's print of the rest, where each shows as an empty array
// (always_print_primitive_fields prints `"name":[]`).
struct FlatArray {
  std::string_view parent;  // key of the object holding it; "" = the result
  std::string_view key;
  std::string text;  // "[...]" as protobuf prints it
  int found = 0;
};

// Protobuf's notation, compact: decimal int32, true/false, doubles by
// SimpleDtoa (shortest of %.15g / %.17g that reads back, which is what the
// printer uses for finite doubles).
void Append(int32_t v, std::string* out) {
  char buf[12];
  out->append(buf, std::to_chars(buf, buf + sizeof(buf), v).ptr);
}
void Append(bool v, std::string* out) { out->append(v ? "true" : "false"); }
void Append(double v, std::string* out) { out->append(google::protobuf::SimpleDtoa(v)); }

template <typename T>
std::string Print(const google::protobuf::RepeatedField<T>& values) {
  std::string out = "[";
  out.reserve(values.size() * (std::is_same_v<T, double> ? 20 : 6) + 2);
  for (int i = 0; i < values.size(); ++i) {
    if (i > 0) out.push_back(',');
    Append(values.Get(i), &out);
  }
  out.push_back(']');
  return out;
}

// Moves the non-empty flat arrays of `rest` into `arrays` as text, leaving
// them empty in `rest`. Non-finite doubles (printed as quoted strings) stay
// with protobuf.
template <typename Field>
void TakeArray(std::string_view parent, std::string_view key, Field* field,
               std::vector<FlatArray>* arrays) {
  if (field->empty()) return;
  if constexpr (std::is_same_v<Field, google::protobuf::RepeatedField<double>>) {
    for (const double v : *field) {
      if (!std::isfinite(v)) return;
    }
  }
  arrays->push_back({.parent = parent, .key = key, .text = Print(*field)});
  field->Clear();
}

// Copies protobuf's print `json` with each array's `"key":[]` (in the
// object the array's parent names) replaced by the array's text. Walks the
// JSON's tokens, so keys inside strings or in other objects do not match.
// False unless every array was found exactly once.
bool FillIn(std::string_view json, std::vector<FlatArray>* arrays, std::string* out) {
  std::size_t total = json.size();
  for (const FlatArray& a : *arrays) total += a.text.size();
  out->clear();
  out->reserve(total + 1);
  std::vector<std::string_view> open;  // the key each open object / array is the value of
  std::string_view key;                // a key just read, before its value
  std::size_t copied = 0;
  const std::size_t n = json.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char ch = json[i];
    if (ch == '"') {
      std::size_t j = i + 1;
      while (j < n && json[j] != '"') j += json[j] == '\\' ? 2 : 1;
      if (j >= n) return false;
      const std::string_view s = json.substr(i + 1, j - i - 1);
      i = j;
      if (i + 1 >= n || json[i + 1] != ':') continue;  // a string value
      ++i;                                              // at ':'
      key = s;
      if (json.compare(i + 1, 2, "[]") != 0) continue;
      for (FlatArray& a : *arrays) {
        const bool in_parent = a.parent.empty()
                                   ? open.size() == 1
                                   : open.size() == 2 && open[1] == a.parent;
        if (!in_parent || a.key != key) continue;
        out->append(json.substr(copied, i + 1 - copied));
        out->append(a.text);
        copied = i + 3;
        ++a.found;
        break;
      }
      i += 2;  // past "[]"
      key = {};
      continue;
    }
    if (ch == '{' || ch == '[') {
      open.push_back(key);
    } else if (ch == '}' || ch == ']') {
      if (open.empty()) return false;
      open.pop_back();
    }
    if (ch == '{' || ch == '[' || ch == '}' || ch == ']' || ch == ',') key = {};
  }
  out->append(json.substr(copied));
  for (const FlatArray& a : *arrays) {
    if (a.found != 1) return false;
  }
  return true;
}

}  // namespace

absl::StatusOr<std::string> ResultJson(const v1::SegmentationResult& result) {
  v1::SegmentationResult rest = result;
  std::vector<FlatArray> arrays;
  TakeArray("", "face_labels", rest.mutable_face_labels(), &arrays);
  TakeArray("", "vertex_labels", rest.mutable_vertex_labels(), &arrays);
  TakeArray("", "point_labels", rest.mutable_point_labels(), &arrays);
  TakeArray("", "face_filled", rest.mutable_face_filled(), &arrays);
  if (rest.has_mesh_geometry()) {
    v1::MeshGeometry* g = rest.mutable_mesh_geometry();
    TakeArray("mesh_geometry", "vertices", g->mutable_vertices(), &arrays);
    TakeArray("mesh_geometry", "faces", g->mutable_faces(), &arrays);
    TakeArray("mesh_geometry", "input_faces", g->mutable_input_faces(), &arrays);
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::string printed, PrintWithProtobuf(rest));
  std::string json;
  if (!FillIn(printed, &arrays, &json)) {
    // The printer's layout is not the one expected: its own print of all.
    MESHSEG_ASSIGN_OR_RETURN(json, PrintWithProtobuf(result));
  }
  json.push_back('\n');
  return json;
}

absl::StatusOr<v1::SegmentationResult> ParseResultJson(std::string_view json) {
  v1::SegmentationResult result;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = true;  // results of newer versions
  const auto status = google::protobuf::util::JsonStringToMessage(
      google::protobuf::StringPiece(json.data(), json.size()), &result, options);
  if (!status.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("result json: not a segmentation result: ", status.ToString()));
  }
  return result;
}

}  // namespace meshseg
