// Wall and CPU time and peak memory of the exact-facet path on a mesh file
// (read, exactness estimate, facet segmentation with shared surfaces), the
// #31 speed target: <= 0.5 s per 10K facets, <= 10 s for 1M.
// Usage: exact_path_bench MESH_FILE [RUNS]
//   python3 bench/cad/make_prism_grid.py 8 /tmp/grid10k.obj    (10K facets)
//   python3 bench/cad/make_prism_grid.py 79 /tmp/grid1m.obj    (1M facets)
// Prints one line per stage (the best of RUNS for the estimate and the
// segmentation), then the regions and surfaces found.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <string>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "bench/peak_rss.h"

namespace {

// Wall and process CPU seconds since construction.
struct Clock {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  std::clock_t cpu = std::clock();
  double Wall() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  }
  double Cpu() const { return static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC; }
};

void Print(const char* stage, double wall, double cpu) {
  std::printf("%-10s %8.3f s wall %8.3f s cpu  peak %8.1f MiB\n", stage, wall, cpu, meshseg::bench::PeakRssMiB());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH_FILE [RUNS]\n", argv[0]);
    return 2;
  }
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
  Clock read_clock;
  absl::StatusOr<meshseg::Mesh> mesh = meshseg::ReadMesh(argv[1]);
  if (!mesh.ok()) {
    std::fprintf(stderr, "%s\n", mesh.status().ToString().c_str());
    return 1;
  }
  Print("read", read_clock.Wall(), read_clock.Cpu());
  std::printf("mesh       %zu vertices, %zu facets\n", mesh->tri.n_vertices(), mesh->tri.n_faces());
  double best_wall[2] = {1e300, 1e300}, best_cpu[2] = {1e300, 1e300};
  meshseg::Exactness exactness;
  absl::StatusOr<meshseg::Segmentation> seg;
  for (int run = 0; run < runs; ++run) {
    Clock estimate_clock;
    exactness = meshseg::EstimateExactness(*mesh);
    best_wall[0] = std::min(best_wall[0], estimate_clock.Wall());
    best_cpu[0] = std::min(best_cpu[0], estimate_clock.Cpu());
    Clock segment_clock;
    meshseg::SegmentParams params;
    params.exact_tolerance = exactness.tolerance;
    seg = meshseg::SegmentExactFacets(*mesh, params);
    if (!seg.ok()) {
      std::fprintf(stderr, "%s\n", seg.status().ToString().c_str());
      return 1;
    }
    best_wall[1] = std::min(best_wall[1], segment_clock.Wall());
    best_cpu[1] = std::min(best_cpu[1], segment_clock.Cpu());
  }
  Print("exactness", best_wall[0], best_cpu[0]);
  std::printf("           share %.4f tau %.4g exact %d\n", exactness.share, exactness.tolerance,
              exactness.exact);
  Print("segment", best_wall[1], best_cpu[1]);
  std::map<std::string, int> by_type;
  for (const auto& r : seg->regions) ++by_type[meshseg::SurfaceTypeName(r.type)];
  std::printf("regions    %zu:", seg->regions.size());
  for (const auto& [type, count] : by_type) std::printf(" %s %d", type.c_str(), count);
  std::printf("\nsurfaces   %zu\n", seg->surfaces.size());
  return 0;
}
