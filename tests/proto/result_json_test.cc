#include "meshseg/proto/result_json.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/util/json_util.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace meshseg {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;

v1::SegmentationResult Sample() {
  v1::SegmentationResult r;
  r.mutable_mesh()->set_face_count(2);
  r.add_face_labels(0);
  r.add_face_labels(-1);
  v1::Region* region = r.add_regions();
  region->set_id(0);
  region->set_type(v1::SURFACE_TYPE_PLANE);
  region->mutable_plane()->mutable_normal()->set_z(1.0);
  return r;
}

TEST(ResultJson, UsesSnakeCaseNamesAndEnumNames) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_THAT(*json, HasSubstr("\"face_labels\":[0,-1]"));
  EXPECT_THAT(*json, HasSubstr("\"SURFACE_TYPE_PLANE\""));
  EXPECT_THAT(*json, HasSubstr("\"mean_edge_length\""));
  EXPECT_THAT(*json, ::testing::Not(HasSubstr("faceLabels")));
}

TEST(ResultJson, PrintsZeroValuesSuchAsRegionIdZero) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok());
  EXPECT_THAT(*json, HasSubstr("\"id\":0"));
}

TEST(ResultJson, IsOneLineEndingInANewline) {
  const absl::StatusOr<std::string> json = ResultJson(Sample());
  ASSERT_TRUE(json.ok());
  EXPECT_THAT(*json, EndsWith("}\n"));
  EXPECT_EQ(json->find('\n'), json->size() - 1);
}

TEST(ResultJson, SameMessageGivesSameBytesAfterAWireRoundTrip) {
  const v1::SegmentationResult a = Sample();
  v1::SegmentationResult b;
  ASSERT_TRUE(b.ParseFromString(a.SerializeAsString()));
  EXPECT_EQ(*ResultJson(a), *ResultJson(b));
}

// Protobuf's own print of `m` with ResultJson's options (DESIGN.md).
std::string ProtobufJson(const v1::SegmentationResult& m) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;
  options.always_print_primitive_fields = true;
  options.always_print_enums_as_ints = false;
  options.add_whitespace = false;
  std::string json;
  EXPECT_TRUE(google::protobuf::util::MessageToJsonString(m, &json, options).ok());
  return json + "\n";
}

// Sets every field of `m` and of its messages (down to `depth` levels),
// repeated ones with three entries, from value lists that reach the
// notation's corners: int32/int64 extremes, -0.0, subnormal and 1e21
// doubles, strings with quotes, backslashes and a key-like text. Of each
// oneof only the member `variant` picks is set.
void FillEverything(google::protobuf::Message* m, int depth, int variant, int* k) {
  using google::protobuf::FieldDescriptor;
  static const int32_t kInt32[] = {0, -1, 7, std::numeric_limits<int32_t>::max(),
                                   std::numeric_limits<int32_t>::min(), 123456};
  static const int64_t kInt64[] = {0, -1, (int64_t{1} << 53) + 1,
                                   std::numeric_limits<int64_t>::min(), 42};
  static const double kDouble[] = {0.0,   -0.0,  0.1,          1.0 / 3.0, 1e-300,  5e-324,
                                   1e21,  1e15,  123456789.125, -2.5e-7,  1e16,    2.0};
  static const char* const kString[] = {"plain", "with \"quotes\" and \\ backslash",
                                        "\"face_labels\":[]", "\xc3\xbc" "n" "\xc3\xaf" "c" "\xc3\xb6" "de",
                                        "tab\tnewline\n"};
  const google::protobuf::Descriptor* d = m->GetDescriptor();
  const google::protobuf::Reflection* r = m->GetReflection();
  for (int f = 0; f < d->field_count(); ++f) {
    const FieldDescriptor* field = d->field(f);
    if (const google::protobuf::OneofDescriptor* o = field->containing_oneof();
        o != nullptr && field->index_in_oneof() != variant % o->field_count()) {
      continue;
    }
    const int count = field->is_repeated() ? 3 : 1;
    for (int i = 0; i < count; ++i, ++*k) {
      const bool rep = field->is_repeated();
      switch (field->cpp_type()) {
        case FieldDescriptor::CPPTYPE_INT32: {
          const int32_t v = kInt32[*k % std::size(kInt32)];
          rep ? r->AddInt32(m, field, v) : r->SetInt32(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_INT64: {
          const int64_t v = kInt64[*k % std::size(kInt64)];
          rep ? r->AddInt64(m, field, v) : r->SetInt64(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_UINT32: {
          const uint32_t v = static_cast<uint32_t>(kInt32[*k % std::size(kInt32)]);
          rep ? r->AddUInt32(m, field, v) : r->SetUInt32(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_UINT64: {
          const uint64_t v = static_cast<uint64_t>(kInt64[*k % std::size(kInt64)]);
          rep ? r->AddUInt64(m, field, v) : r->SetUInt64(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_DOUBLE: {
          const double v = kDouble[*k % std::size(kDouble)];
          rep ? r->AddDouble(m, field, v) : r->SetDouble(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_FLOAT: {
          const float v = static_cast<float>(kDouble[*k % std::size(kDouble)]);
          rep ? r->AddFloat(m, field, v) : r->SetFloat(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_BOOL: {
          const bool v = *k % 2 == 0;
          rep ? r->AddBool(m, field, v) : r->SetBool(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_ENUM: {
          const google::protobuf::EnumDescriptor* e = field->enum_type();
          const int v = e->value(*k % e->value_count())->number();
          rep ? r->AddEnumValue(m, field, v) : r->SetEnumValue(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_STRING: {
          const std::string v = kString[*k % std::size(kString)];
          rep ? r->AddString(m, field, v) : r->SetString(m, field, v);
          break;
        }
        case FieldDescriptor::CPPTYPE_MESSAGE:
          if (depth > 0) {
            FillEverything(rep ? r->AddMessage(m, field) : r->MutableMessage(m, field),
                           depth - 1, variant, k);
          }
          break;
      }
    }
  }
}

// The flat arrays long, with values from the whole range of their type
// (doubles from random bit patterns, finite).
void MakeFlatArraysLong(v1::SegmentationResult* m, std::mt19937_64* rng) {
  for (int i = 0; i < 2000; ++i) {
    m->add_face_labels(static_cast<int32_t>((*rng)()));
    m->add_vertex_labels(static_cast<int32_t>((*rng)() % 200) - 1);
    m->add_point_labels(static_cast<int32_t>((*rng)() % 100000) - 1);
    m->add_face_filled((*rng)() % 2 == 0);
    m->mutable_mesh_geometry()->add_faces(static_cast<int32_t>((*rng)()));
    m->mutable_mesh_geometry()->add_input_faces(i);
    double x = 0.0;
    do {
      x = std::bit_cast<double>((*rng)());
    } while (!std::isfinite(x));
    m->mutable_mesh_geometry()->add_vertices(i % 3 == 0 ? x : (*rng)() % 100000 / 64.0);
  }
}

TEST(ResultJson, SameBytesAsProtobufsPrinterWithEveryFieldSet) {
  std::mt19937_64 rng(7);
  for (int variant = 0; variant < 4; ++variant) {
    v1::SegmentationResult m;
    int k = variant;
    FillEverything(&m, 5, variant, &k);
    MakeFlatArraysLong(&m, &rng);
    const absl::StatusOr<std::string> json = ResultJson(m);
    ASSERT_TRUE(json.ok()) << json.status();
    EXPECT_EQ(*json, ProtobufJson(m)) << "variant " << variant;
  }
}

TEST(ResultJson, SameBytesAsProtobufsPrinterWithEmptyArraysOrNonFiniteVertices) {
  v1::SegmentationResult m = Sample();
  m.clear_face_labels();
  EXPECT_EQ(*ResultJson(m), ProtobufJson(m));  // every flat array empty
  m.mutable_mesh_geometry();
  EXPECT_EQ(*ResultJson(m), ProtobufJson(m));  // an empty mesh geometry
  m.mutable_mesh_geometry()->add_vertices(1.5);
  m.mutable_mesh_geometry()->add_vertices(std::nan(""));
  m.mutable_mesh_geometry()->add_vertices(-INFINITY);
  m.add_face_labels(3);
  const absl::StatusOr<std::string> json = ResultJson(m);
  ASSERT_TRUE(json.ok()) << json.status();
  EXPECT_EQ(*json, ProtobufJson(m));
  EXPECT_THAT(*json, HasSubstr("\"vertices\":[1.5,\"NaN\",\"-Infinity\"]"));
}

}  // namespace
}  // namespace meshseg
