// Time and peak memory of Reconstruct() on clouds of 100K and 1M points
// sampled from a torus (R = 1, r = 0.4) without normals, with Gaussian noise
// of 0.2 spacings and 1 % uniform outliers in the bounding box.
//   build-rec/bin/reconstruct_bench --benchmark_counters_tabular=true
// Peak RSS is the process's high-water mark (getrusage), so the sizes run
// smallest first.

#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "meshseg/reconstruct.h"
#include "bench/peak_rss.h"

namespace meshseg {
namespace {

PointCloud TorusCloud(int count) {
  constexpr double kR = 1.0, kr = 0.4;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2 * M_PI), accept(0.0, 1.0), box(-1.0, 1.0);
  std::normal_distribution<double> g;
  const double h = std::sqrt(4 * M_PI * M_PI * kR * kr / count);
  PointCloud cloud;
  cloud.name = "torus.xyz";
  for (int i = 0; i < count; ++i) {
    double v;
    do {
      v = u(rng);
    } while (accept(rng) > (kR + kr * std::cos(v)) / (kR + kr));
    const double t = u(rng);
    const Eigen::Vector3d n(std::cos(v) * std::cos(t), std::cos(v) * std::sin(t), std::sin(v));
    const Eigen::Vector3d p = Eigen::Vector3d(kR * std::cos(t), kR * std::sin(t), 0.0) + kr * n;
    cloud.points.push_back(p + 0.2 * h * Eigen::Vector3d(g(rng), g(rng), g(rng)));
  }
  for (int i = 0; i < count / 100; ++i) {
    cloud.points.emplace_back(1.4 * box(rng), 1.4 * box(rng), 0.4 * box(rng));
  }
  return cloud;
}

void BM_Reconstruct(benchmark::State& state) {
  const PointCloud cloud = TorusCloud(static_cast<int>(state.range(0)));
  Reconstruction result;
  for (auto _ : state) {
    auto r = Reconstruct(cloud);
    if (!r.ok()) {
      state.SkipWithError(std::string(r.status().message()).c_str());
      return;
    }
    result = *std::move(r);
  }
  state.counters["points"] = static_cast<double>(cloud.points.size());
  state.counters["supports"] = static_cast<double>(result.stats.support_count);
  state.counters["tets"] = static_cast<double>(result.stats.tet_count);
  state.counters["faces"] = static_cast<double>(result.mesh.tri.n_faces());
  state.counters["peak_rss_MB"] = meshseg::bench::PeakRssMiB();
}
BENCHMARK(BM_Reconstruct)->Arg(100'000)->Arg(1'000'000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace meshseg

BENCHMARK_MAIN();
