// Single-thread time of the curvature stage's neighbourhood walks
// (CollectNeighborhood, seed 000 §2) on a mesh file, in the mesh's own
// vertex numbering and in the Morton numbering the stage walks in
// (curvature/spatial_order.h): N(i, W1) for every vertex, then N'(i, W2)
// with the stage's sharp vertices excluded, as its two passes do. Checks
// that both numberings give the same neighbourhood, vertex for vertex (the
// same vertices in the same order), and exits non-zero on a difference.
// Usage: neighborhood_bench MESH_FILE [REPEATS]

#include <time.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include "curvature/spatial_order.h"
#include "meshseg/curvature.h"
#include "meshseg/mesh.h"

namespace {

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

constexpr std::size_t kMaxCount = 600;  // the stage's cap

// Best-of-`repeats` thread CPU seconds of one walk per vertex, in the
// order vertex(0), vertex(1), ... of `g`'s numbering.
template <typename VertexOf>
double TimeWalks(const meshseg::VertexGraph& g, std::span<const double> radius,
                 std::span<const uint8_t> excluded, int repeats, VertexOf vertex) {
  meshseg::NeighborhoodScratch scratch;
  std::vector<int> out;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const double t = ThreadSeconds();
    for (int k = 0; k < g.vertex_count(); ++k) {
      meshseg::CollectNeighborhood(g, k, radius[vertex(k)], excluded, &scratch, &out, kMaxCount);
    }
    best = std::min(best, ThreadSeconds() - t);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH_FILE [REPEATS]\n", argv[0]);
    return 2;
  }
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const absl::StatusOr<meshseg::Mesh> mesh = meshseg::ReadMesh(argv[1]);
  if (!mesh.ok()) {
    std::fprintf(stderr, "%s\n", mesh.status().ToString().c_str());
    return 1;
  }
  const meshseg::CurvatureParams params;  // the stage's W1, W2
  const absl::StatusOr<meshseg::CurvatureField> field = meshseg::EstimateCurvature(*mesh, params);
  if (!field.ok()) {
    std::fprintf(stderr, "%s\n", field.status().ToString().c_str());
    return 1;
  }
  const meshseg::VertexGraph g = meshseg::BuildVertexGraph(mesh->tri);
  const meshseg::curvature_internal::OrderedGraph walk =
      meshseg::curvature_internal::MortonOrderedGraph(mesh->tri);
  const std::vector<uint8_t> sharp = walk.Permuted<uint8_t>(field->sharp);
  const int n = g.vertex_count();
  const std::vector<uint8_t> none;
  for (const bool second : {false, true}) {
    const double w = second ? params.w2 : params.w1;
    std::vector<double> radius(n);
    for (int v = 0; v < n; ++v) radius[v] = w * field->mean_edge_length[v];
    const std::span<const uint8_t> own_excluded = second ? field->sharp : none;
    const std::span<const uint8_t> morton_excluded = second ? sharp : none;
    meshseg::NeighborhoodScratch scratch;
    std::vector<int> own;
    std::vector<int> morton;
    std::size_t total = 0;
    for (int v = 0; v < n; ++v) {
      meshseg::CollectNeighborhood(g, v, radius[v], own_excluded, &scratch, &own, kMaxCount);
      meshseg::CollectNeighborhood(walk.graph, walk.rank[v], radius[v], morton_excluded, &scratch,
                                   &morton, kMaxCount);
      for (int& j : morton) j = walk.order[j];
      if (own != morton) {
        std::fprintf(stderr, "vertex %d: the neighbourhoods differ\n", v);
        return 1;
      }
      total += own.size();
    }
    const double own_s = TimeWalks(g, radius, own_excluded, repeats, [](int v) { return v; });
    const double morton_s = TimeWalks(walk.graph, radius, morton_excluded, repeats,
                                      [&](int k) { return walk.order[k]; });
    std::printf("%s  %6.1f vertices per neighbourhood, same in both numberings; thread CPU "
                "(best of %d): own numbering %.3f s, Morton %.3f s\n",
                second ? "W2, sharp excluded" : "W1                ",
                static_cast<double>(total) / n, repeats, own_s, morton_s);
  }
  return 0;
}
