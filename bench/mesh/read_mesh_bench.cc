// Times ReadMesh + MeshStatistics on a ~2M-triangle binary STL (a finely
// tessellated sphere written by this benchmark to /tmp), the `meshseg info`
// path that must stay under 2 s on the 2-core reference machine.
// Run: build/bin/mesh_read_bench; page faults dominate on the reference VM,
// so also try GLIBC_TUNABLES=glibc.malloc.hugetlb=1 build/bin/mesh_read_bench.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "meshseg/mesh.h"

namespace meshseg {
namespace {

constexpr int kLatitudes = 1000;
constexpr int kLongitudes = 1000;  // 2 * 1000 * 999 = 1,998,000 triangles

struct Vec3f {
  float x, y, z;
};

Vec3f SpherePoint(int lat, int lon) {
  // Exact poles, so that their corners weld into one vertex each.
  if (lat == 0) return {0.0f, 0.0f, 1.0f};
  if (lat == kLatitudes) return {0.0f, 0.0f, -1.0f};
  const double theta = M_PI * lat / kLatitudes;
  const double phi = 2.0 * M_PI * (lon % kLongitudes) / kLongitudes;
  return {static_cast<float>(std::sin(theta) * std::cos(phi)),
          static_cast<float>(std::sin(theta) * std::sin(phi)),
          static_cast<float>(std::cos(theta))};
}

void Append(std::vector<char>& out, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  const Vec3f normal{0, 0, 0};
  for (const Vec3f* v : {&normal, &a, &b, &c}) {
    const char* p = reinterpret_cast<const char*>(v);
    out.insert(out.end(), p, p + sizeof(Vec3f));
  }
  out.push_back(0);
  out.push_back(0);
}

// Writes the sphere once; returns its path and triangle count.
const std::string& SphereStl(int64_t* triangles) {
  static const std::string path = "/tmp/meshseg_bench_sphere_2m.stl";
  static int64_t count = 0;
  if (count == 0) {
    std::vector<char> out(84, 0);
    for (int i = 0; i < kLatitudes; ++i) {
      for (int j = 0; j < kLongitudes; ++j) {
        const Vec3f p00 = SpherePoint(i, j), p01 = SpherePoint(i, j + 1);
        const Vec3f p10 = SpherePoint(i + 1, j), p11 = SpherePoint(i + 1, j + 1);
        if (i > 0) Append(out, p00, p10, p01), ++count;  // poles: one triangle per quad
        if (i + 1 < kLatitudes) Append(out, p01, p10, p11), ++count;
      }
    }
    const uint32_t n = static_cast<uint32_t>(count);
    std::memcpy(out.data() + 80, &n, sizeof(n));
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(out.data(), 1, out.size(), f);
    std::fclose(f);
  }
  *triangles = count;
  return path;
}

void BM_ReadBinaryStlAndStatistics(benchmark::State& state) {
  int64_t triangles = 0;
  const std::string& path = SphereStl(&triangles);
  for (auto _ : state) {
    absl::StatusOr<Mesh> mesh = ReadMesh(path);
    if (!mesh.ok()) {
      state.SkipWithError(std::string(mesh.status().message()).c_str());
      break;
    }
    const MeshStats stats = MeshStatistics(*mesh);
    benchmark::DoNotOptimize(stats);
    state.counters["faces"] = static_cast<double>(stats.face_count);
    state.counters["vertices"] = static_cast<double>(stats.vertex_count);
  }
  state.counters["input_triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_ReadBinaryStlAndStatistics)->Unit(benchmark::kMillisecond)->Iterations(3);

// What `MESHSEG_ASSIGN_OR_RETURN(Mesh m, ReadMesh(path))` adds: OpenMesh 9
// meshes have no move constructor, so taking the Mesh out of the StatusOr
// copies it.
void BM_CopyMesh(benchmark::State& state) {
  int64_t triangles = 0;
  const absl::StatusOr<Mesh> mesh = ReadMesh(SphereStl(&triangles));
  if (!mesh.ok()) {
    state.SkipWithError(std::string(mesh.status().message()).c_str());
    return;
  }
  for (auto _ : state) {
    Mesh copy = *mesh;
    benchmark::DoNotOptimize(copy.tri.n_faces());
  }
}
BENCHMARK(BM_CopyMesh)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace meshseg

BENCHMARK_MAIN();
