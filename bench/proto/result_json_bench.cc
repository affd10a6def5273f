// Times ResultJson (DESIGN.md "Result JSON") against protobuf's printer on
// a result shaped like the 1M-face test part's: 1,035,736 face labels and
// 517,868 vertex labels over 60 regions, with curves along the region
// boundaries. Both print the same bytes (checked once before timing).
// Run: build/bin/result_json_bench
#include <cstdio>
#include <random>
#include <string>

#include <benchmark/benchmark.h>
#include <google/protobuf/util/json_util.h>

#include "meshseg/proto/result_json.h"

namespace meshseg {
namespace {

constexpr int kFaces = 1035736;
constexpr int kVertices = 517868;
constexpr int kRegions = 60;

const v1::SegmentationResult& LargeResult() {
  static const v1::SegmentationResult result = [] {
    v1::SegmentationResult r;
    std::mt19937 rng(1);
    r.mutable_mesh()->set_face_count(kFaces);
    r.mutable_mesh()->set_vertex_count(kVertices);
    // Labels in runs, as regions are: a new region every ~20000 faces.
    for (int f = 0; f < kFaces; ++f) r.add_face_labels(rng() % 100 == 0 ? -1 : f / 17263);
    for (int v = 0; v < kVertices; ++v) r.add_vertex_labels(v / 8632);
    for (int k = 0; k < kRegions; ++k) {
      v1::Region* region = r.add_regions();
      region->set_id(k);
      region->set_type(v1::SURFACE_TYPE_CYLINDER);
      region->set_face_count(kFaces / kRegions);
      region->set_rms_distance(0.01 * k + 1.0 / 3.0);
      region->mutable_cylinder()->set_radius(2.5 + k / 7.0);
      v1::BoundaryCurve* curve = r.add_curves();
      curve->set_id(k);
      for (int i = 0; i < 400; ++i) curve->add_vertices(static_cast<int>(rng() % kVertices));
    }
    return r;
  }();
  return result;
}

std::string ProtobufPrint(const v1::SegmentationResult& r) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;
  options.always_print_primitive_fields = true;
  std::string json;
  (void)google::protobuf::util::MessageToJsonString(r, &json, options);
  return json + "\n";
}

void BM_ResultJson(benchmark::State& state) {
  const v1::SegmentationResult& r = LargeResult();
  if (*ResultJson(r) != ProtobufPrint(r)) {
    state.SkipWithError("ResultJson differs from protobuf's printer");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(ResultJson(r));
}
BENCHMARK(BM_ResultJson)->Unit(benchmark::kMillisecond);

void BM_ProtobufPrinter(benchmark::State& state) {
  const v1::SegmentationResult& r = LargeResult();
  for (auto _ : state) benchmark::DoNotOptimize(ProtobufPrint(r));
}
BENCHMARK(BM_ProtobufPrinter)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace meshseg

BENCHMARK_MAIN();
