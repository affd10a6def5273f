#include "reconstruct/handles.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/status_macros.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/handle_strips.h"
#include "reconstruct/support.h"

namespace meshseg::reconstruct_internal {

std::vector<double> MaxHandleLoops(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index, double handle_spacings,
                                   double min_spacing) {
  std::vector<double> max_loop(tri.n_vertices(), 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tri.n_vertices()), [&](const auto& range) {
    std::vector<uint32_t> near;
    std::vector<double> dist2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const Eigen::Vector3d& p =
          points[index.Closest(ToEigen(tri.point(TriMesh::VertexHandle(static_cast<int>(i)))))];
      max_loop[i] =
          M_PI * handle_spacings * std::max(min_spacing, SpacingAtPoint(p, index, &near, &dist2));
    }
  });
  return max_loop;
}

absl::Status CutUnsupportedHandles(const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index,
                                   const ReconstructParams& params, Mesh* mesh,
                                   std::vector<uint8_t>* filled, ReconstructStats* stats) {
  // After the first round, only loops near the patches of the last one.
  std::vector<uint8_t> near;
  // The spacing the refined mesh follows (refine.h); 0 without refinement.
  const double mesh_spacing = params.refine_edge_length > 0
                                  ? stats->refine_edge_length / params.refine_edge_length
                                  : 0.0;
  for (int round = 0; round < kHandleRounds; ++round) {
    const int genus = Genus(mesh->tri);
    if (genus <= 0) break;
    // Round holes up to handle_spacings × s across have loops up to π times
    // that; loops up to twice as long are looked at for slits as narrow.
    std::vector<double> max_loop =
        MaxHandleLoops(mesh->tri, points, index, params.handle_spacings, mesh_spacing);
    std::vector<double> max_width(max_loop.size());
    for (size_t v = 0; v < max_loop.size(); ++v) {
      max_width[v] = max_loop[v] / M_PI;
      max_loop[v] *= 2.0;
    }
    const HandleStrips strips = ShortHandleStrips(mesh->tri, max_loop, genus, near, max_width);
    if (strips.cut_count == 0) break;
    std::vector<uint8_t> supported(strips.cut.size());
    for (size_t f = 0; f < supported.size(); ++f) supported[f] = !strips.cut[f];
    // Faces filled before this round are marked 2, so this round's are the 1s.
    std::vector<uint8_t> before = *filled;
    for (uint8_t& b : before) b = b ? 2 : 0;
    MESHSEG_ASSIGN_OR_RETURN(ClosedSurface closed,
                             CloseUnsupported(*mesh, supported, params.min_component_fraction,
                                              params.leave_unsupported_open, before));
    stats->handle_cut_count += strips.cut_count;
    stats->hole_count += closed.hole_count - BorderLoopCount(mesh->tri);
    stats->filled_area = closed.filled_area;
    *mesh = std::move(closed.mesh);
    *filled = std::move(closed.filled);
    near.assign(mesh->tri.n_vertices(), 0);
    for (const auto f : mesh->tri.faces()) {
      uint8_t& flag = (*filled)[f.idx()];
      if (flag == 1) {
        for (const auto v : mesh->tri.fv_range(f)) near[v.idx()] = 1;
      }
      flag = flag != 0;
    }
    // Left open (leave_unsupported_open), a cut is a border instead.
    for (const auto v : mesh->tri.vertices()) near[v.idx()] |= mesh->tri.is_boundary(v);
    stats->filled_face_count = std::count(filled->begin(), filled->end(), 1);
  }
  return absl::OkStatus();
}

}  // namespace meshseg::reconstruct_internal
