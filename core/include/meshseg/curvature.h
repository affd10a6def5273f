// File: curvature.h
// -----------------------------------------------------------------------------
// The `curvature` stage: two-pass principal curvature with sharp-vertex
// detection (seed 000 §2), smoothed normals n'_i, and the optional curvature
// filter of seed 002 A4. Neighbourhoods N(i, W) are grown over mesh edges and
// cut by the Euclidean radius W * l_i,avg.
//
// In: a Mesh. Out: CurvatureField with per-vertex curvatures, directions,
// smoothed normals and sharp flags (vectors indexed by vertex index).
#ifndef MESHSEG_CURVATURE_H_
#define MESHSEG_CURVATURE_H_

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "absl/status/statusor.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"

namespace meshseg {

// Vertex adjacency of a mesh in compressed rows: the neighbours of vertex v
// are neighbors[offsets[v] .. offsets[v + 1]), in OpenMesh circulator order.
struct VertexGraph {
  std::vector<int> offsets;    // vertex count + 1 entries
  std::vector<int> neighbors;  // two per edge
  std::vector<Eigen::Vector3d> positions;

  int vertex_count() const { return static_cast<int>(offsets.size()) - 1; }
  std::span<const int> Neighbors(int v) const {
    return {neighbors.data() + offsets[v], neighbors.data() + offsets[v + 1]};
  }
};

// Returns the vertex graph (adjacency and positions) of `mesh`.
VertexGraph BuildVertexGraph(const TriMesh& mesh);

// Reusable visit marks and queue for CollectNeighborhood; one per thread.
struct NeighborhoodScratch {
  std::vector<uint32_t> mark;
  uint32_t stamp = 0;
  std::vector<int> queue;
};

// Fills `out` with N(i, radius) in breadth-first order, v_i first: the
// vertices reached from v_i over edges through vertices with
// |v_j - v_i| < radius. Vertices with excluded[j] != 0 are neither taken nor
// passed through (empty span = none excluded), which gives seed 000's
// N'(i, W2). Stops after `max_count` vertices (0 = no limit).
void CollectNeighborhood(const VertexGraph& graph, int i, double radius,
                         std::span<const uint8_t> excluded, NeighborhoodScratch* scratch,
                         std::vector<int>* out, std::size_t max_count = 0);

struct CurvatureParams {
  // Pass-1 neighbourhood radius W1, in l_i,avg. Seed 000 §2.
  double w1 = 2.0;
  // Pass-2 neighbourhood radius W2, in l_i,avg. Seed 000 §2.
  double w2 = 5.0;
  // Sharp-vertex threshold th_sv: sharp if 1/|kappa_max| < th_sv * l_i,avg.
  // Seed 000 uses 4.0 to 8.0; unset = derived from the data.
  std::optional<double> sharp_threshold;
  // Median + 3 mean filters on non-sharp curvatures. Seed 002 A4.
  bool filter_curvature = true;
};

struct CurvatureField {
  std::vector<double> kappa_max;              // larger |.| principal curvature
  std::vector<double> kappa_min;
  std::vector<Eigen::Vector3d> dir_max;       // unit principal directions
  std::vector<Eigen::Vector3d> dir_min;
  std::vector<Eigen::Vector3d> normal;        // area-weighted vertex normal n_i
  std::vector<Eigen::Vector3d> smooth_normal; // n'_i from the pass-2 fit
  std::vector<double> mean_edge_length;       // l_i,avg
  std::vector<uint8_t> sharp;                 // 1 = sharp vertex
  std::vector<double> fit_residual;           // rms residual of the pass-2 fit
  double sharp_threshold = 0.0;               // th_sv actually used
};

// Returns the curvature field of `mesh`.
// Errors: INVALID_ARGUMENT for bad params or an empty mesh; CANCELLED on stop.
absl::StatusOr<CurvatureField> EstimateCurvature(const Mesh& mesh,
                                                 const CurvatureParams& params = {},
                                                 const RunContext& ctx = {});

}  // namespace meshseg

#endif  // MESHSEG_CURVATURE_H_
