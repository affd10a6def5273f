// Time to generate each catalogue part at its default voxel size, with the
// triangle count as a counter. Run: build/bin/generate_bench
#include <string>

#include <benchmark/benchmark.h>

#include "meshseg/generate.h"

namespace {

void BM_GeneratePart(benchmark::State& state, const std::string& name, double noise) {
  size_t faces = 0;
  for (auto _ : state) {
    auto part = meshseg::GeneratePart(name, {.noise = noise});
    if (!part.ok()) {
      state.SkipWithError(std::string(part.status().message()).c_str());
      return;
    }
    faces = part->mesh.tri.n_faces();
    benchmark::DoNotOptimize(part->face_primitive.data());
  }
  state.counters["triangles"] = static_cast<double>(faces);
  state.counters["triangles_per_s"] =
      benchmark::Counter(static_cast<double>(faces), benchmark::Counter::kIsIterationInvariantRate);
}

const bool registered = [] {
  for (const std::string& name : meshseg::PartNames()) {
    benchmark::RegisterBenchmark(("GeneratePart/" + name).c_str(), BM_GeneratePart, name, 0.0)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1)
        ->UseRealTime();
  }
  benchmark::RegisterBenchmark("GeneratePart/test_piece/noise_0.1", BM_GeneratePart,
                               std::string("test_piece"), 0.1)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1)
      ->UseRealTime();
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
