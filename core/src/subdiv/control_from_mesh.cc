#include "subdiv/control_from_mesh.h"

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

#include "meshseg/status_macros.h"
#include "voxel/edge_collapse.h"

namespace meshseg::subdiv_internal {
namespace {

// A collapse that turns a face normal by more than 60 degrees is refused:
// keeps the control mesh from folding over where the input curves strongly.
constexpr double kMinCosNormalTurn = 0.5;

// The surviving vertices and faces of `work`; `crease` flags its edges
// after the collapse (open borders included, which are not creases).
ControlMesh Compact(const TriMesh& work, const std::vector<int>& feature_count,
                    const std::vector<uint8_t>& crease) {
  ControlMesh out;
  std::vector<int> index(work.n_vertices(), -1);
  for (auto v : work.vertices()) {
    if (work.status(v).deleted() || work.is_isolated(v)) continue;
    index[v.idx()] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(ToEigen(work.point(v)));
    if (feature_count[v.idx()] >= 3) out.corners.push_back(index[v.idx()]);
  }
  for (auto f : work.faces()) {
    if (work.status(f).deleted()) continue;
    std::array<int, 3> t;
    int c = 0;
    for (auto v : work.fv_range(f)) t[c++] = index[v.idx()];
    out.faces.push_back(t);
  }
  for (auto e : work.edges()) {
    if (work.status(e).deleted() || !crease[e.idx()] || work.is_boundary(e)) continue;
    out.creases.push_back({index[e.v0().idx()], index[e.v1().idx()]});
  }
  return out;
}

}  // namespace

absl::StatusOr<ControlMesh> ControlFromMesh(const TriMesh& mesh, int64_t target_faces,
                                            const FeatureLines& features, const RunContext& ctx) {
  TriMesh work = mesh;
  work.update_face_normals();
  // Feature lines and open borders are the collapse's creases: their
  // vertices only slide along them. Vertices where the feature-edge count is
  // not 0 or 2 (junctions, line ends, a line meeting the border) are locked.
  std::vector<uint8_t> crease = features.edge;
  for (auto e : work.edges()) crease[e.idx()] |= work.is_boundary(e) ? 1 : 0;
  std::vector<uint8_t> locked(work.n_vertices(), 0);
  for (size_t v = 0; v < locked.size(); ++v) {
    locked[v] = features.count[v] != 0 && features.count[v] != 2;
  }
  RunContext collapse_ctx;
  collapse_ctx.stop = ctx.stop;
  collapse_ctx.on_progress = [&ctx](std::string_view, double f) {
    ctx.Progress("subdiv", 0.4 * std::min(1.0, f / 0.9));  // the loop reports up to 0.9
  };
  const voxel_internal::CollapseParams params{
      .target_faces = static_cast<size_t>(std::max<int64_t>(target_faces, 1)),
      .min_cos_normal = kMinCosNormalTurn,
      // Feature lines are sharp: their two face planes already price
      // moving them sideways (see CollapseParams).
      .interior_crease_planes = false};
  std::vector<uint8_t> crease_after;
  const absl::Status status =
      voxel_internal::CollapseEdges(work, params, locked, crease, collapse_ctx, &crease_after);
  if (absl::IsCancelled(status)) return absl::CancelledError("subdiv: stop requested");
  MESHSEG_RETURN_IF_ERROR(status);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("subdiv"));
  ctx.Progress("subdiv", 0.4);
  return Compact(work, features.count, crease_after);
}

}  // namespace meshseg::subdiv_internal
