// EstimateCurvature: the two-pass principal curvature of seed 000 §2 with
// sharp-vertex detection, smoothed normals and the seed 002 A4 filter.
#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "curvature/filter_curvature.h"
#include "curvature/local_fit.h"
#include "curvature/sharp_threshold.h"
#include "curvature/spatial_order.h"
#include "curvature/vertex_frames.h"
#include "meshseg/curvature.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

using curvature_internal::LocalFit;

constexpr int kBlock = 16384;            // vertices per progress/stop check
constexpr std::size_t kMinFitPoints = 7;  // 6 coefficients + 1
constexpr int kMaxRadiusDoublings = 3;    // for sparse CAD fans
constexpr std::size_t kMaxNeighborhood = 600;

absl::Status ValidateParams(const CurvatureParams& p) {
  if (!(p.w1 > 0.0) || !std::isfinite(p.w1)) {
    return absl::InvalidArgumentError(absl::StrCat("curvature: w1 must be > 0, got ", p.w1));
  }
  if (!(p.w2 >= p.w1) || !std::isfinite(p.w2)) {
    return absl::InvalidArgumentError(
        absl::StrCat("curvature: w2 must be >= w1 (", p.w1, "), got ", p.w2));
  }
  if (p.sharp_threshold && (!(*p.sharp_threshold > 0.0) || !std::isfinite(*p.sharp_threshold))) {
    return absl::InvalidArgumentError(
        absl::StrCat("curvature: sharp_threshold must be > 0, got ", *p.sharp_threshold));
  }
  return absl::OkStatus();
}

struct Scratch {
  NeighborhoodScratch nbhd;
  std::vector<int> ids;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights;
};

// Runs `body(k, scratch)` for every vertex number k in blocks, reporting
// progress between blocks as [from, to] of the stage and checking for a stop.
absl::Status ForEachVertex(int n, const RunContext& ctx, double from, double to,
                           tbb::enumerable_thread_specific<Scratch>& scratch,
                           const std::function<void(int, Scratch&)>& body) {
  for (int begin = 0; begin < n; begin += kBlock) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("curvature"));
    const int end = std::min(n, begin + kBlock);
    tbb::parallel_for(tbb::blocked_range<int>(begin, end, 256),
                      [&](const tbb::blocked_range<int>& r) {
                        Scratch& s = scratch.local();
                        for (int k = r.begin(); k < r.end(); ++k) body(k, s);
                      });
    ctx.Progress("curvature", from + (to - from) * end / n);
  }
  return absl::OkStatus();
}

// Local fit on N(i, w * l_i) (excluding `excluded`), widening the radius
// where the neighbourhood is too small to fit six coefficients. `walk` is
// the Morton-ordered graph, `k` the vertex's number in it, `area` and
// `excluded` in its numbering; `v` is the vertex's own index.
LocalFit FitNeighborhood(const curvature_internal::OrderedGraph& walk,
                         const curvature_internal::VertexFrames& f, std::span<const double> area,
                         int k, double w, std::span<const uint8_t> excluded, Scratch& s) {
  const int v = walk.order[k];
  double radius = w * f.mean_edge_length[v];
  for (int d = 0; d <= kMaxRadiusDoublings; ++d, radius *= 2.0) {
    CollectNeighborhood(walk.graph, k, radius, excluded, &s.nbhd, &s.ids, kMaxNeighborhood);
    if (s.ids.size() >= kMinFitPoints) break;
  }
  return curvature_internal::FitAtVertex(walk.graph.positions, area, s.ids, f.normal[v], &s.points,
                                         &s.weights);
}

}  // namespace

absl::StatusOr<CurvatureField> EstimateCurvature(const Mesh& mesh, const CurvatureParams& params,
                                                 const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  if (mesh.tri.n_faces() == 0) {
    return absl::InvalidArgumentError(absl::StrCat("curvature: \"", mesh.name, "\" has no faces"));
  }
  const int n = static_cast<int>(mesh.tri.n_vertices());
  // Both passes and the filter walk and fit in the Morton order
  // (spatial_order.h): the same neighbourhoods and sums, with fewer waits on
  // memory; results are stored under each vertex's own index. The frames
  // and the ordered graph only read the mesh, so they are built side by side.
  curvature_internal::VertexFrames frames;
  curvature_internal::OrderedGraph walk;
  tbb::parallel_invoke([&] { frames = curvature_internal::ComputeVertexFrames(mesh.tri); },
                       [&] { walk = curvature_internal::MortonOrderedGraph(mesh.tri); });
  // The field's arrays are first written (and their pages faulted in) on
  // both cores.
  std::vector<double> area;
  CurvatureField field;
  std::vector<double> residual1;
  tbb::parallel_invoke(
      [&] { area = walk.Permuted<double>(frames.area); },
      [&] {
        field.kappa_max.assign(n, 0.0);
        field.kappa_min.assign(n, 0.0);
        field.fit_residual.assign(n, 0.0);
        residual1.assign(n, 0.0);
        field.sharp.assign(n, 0);
      },
      [&] { field.dir_max.assign(n, Eigen::Vector3d::UnitX()); },
      [&] { field.dir_min.assign(n, Eigen::Vector3d::UnitY()); },
      [&] { field.normal = frames.normal; }, [&] { field.smooth_normal = frames.normal; },
      [&] { field.mean_edge_length = frames.mean_edge_length; });
  tbb::enumerable_thread_specific<Scratch> scratch;

  // Pass 1 (W1): kappa_max for the sharp test; seed 000 §2 step 3.
  MESHSEG_RETURN_IF_ERROR(ForEachVertex(n, ctx, 0.0, 0.3, scratch, [&](int k, Scratch& s) {
    const int v = walk.order[k];
    if (frames.normal[v].squaredNorm() == 0.0) return;
    const LocalFit fit = FitNeighborhood(walk, frames, area, k, params.w1, {}, s);
    if (!fit.valid) return;
    field.kappa_max[v] = fit.curvatures.kappa_max;
    field.kappa_min[v] = fit.curvatures.kappa_min;
    field.dir_max[v] = fit.curvatures.dir_max;
    field.dir_min[v] = fit.curvatures.dir_min;
    residual1[v] = fit.residual;
  }));
  field.sharp_threshold = params.sharp_threshold.value_or(
      curvature_internal::DeriveSharpThreshold(residual1, frames.mean_edge_length));
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 8192), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      // 1/|kappa_max| < th_sv * l_i,avg; isolated vertices count as sharp.
      field.sharp[v] = frames.normal[v].squaredNorm() == 0.0 ||
                       std::abs(field.kappa_max[v]) * field.sharp_threshold *
                               frames.mean_edge_length[v] > 1.0;
      field.fit_residual[v] = residual1[v];
    }
  });

  // Pass 2 (W2) on N'(i, W2) for non-sharp vertices; seed 000 §2 steps 4-5.
  const std::vector<uint8_t> sharp = walk.Permuted<uint8_t>(field.sharp);
  MESHSEG_RETURN_IF_ERROR(ForEachVertex(n, ctx, 0.3, 0.9, scratch, [&](int k, Scratch& s) {
    const int v = walk.order[k];
    if (field.sharp[v]) return;
    const LocalFit fit = FitNeighborhood(walk, frames, area, k, params.w2, sharp, s);
    if (!fit.valid) return;
    field.kappa_max[v] = fit.curvatures.kappa_max;
    field.kappa_min[v] = fit.curvatures.kappa_min;
    field.dir_max[v] = fit.curvatures.dir_max;
    field.dir_min[v] = fit.curvatures.dir_min;
    field.smooth_normal[v] = fit.curvatures.normal;
    field.fit_residual[v] = fit.residual;
  }));
  if (params.filter_curvature) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("curvature"));
    curvature_internal::FilterCurvature(walk, &field);
  }
  ctx.Progress("curvature", 1.0);
  return field;
}

}  // namespace meshseg
