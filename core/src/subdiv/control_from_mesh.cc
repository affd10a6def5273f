#include "subdiv/control_from_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <vector>

#include "meshseg/status_macros.h"
#include "voxel/edge_collapse.h"

namespace meshseg::subdiv_internal {
namespace {

// A collapse that turns a face normal by more than 60 degrees is refused:
// keeps the control mesh from folding over where the input curves strongly.
constexpr double kMinCosNormalTurn = 0.5;

// Returns the root of v's set (path halving).
int Find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// The feature edges of `mesh` and the feature-edge count per vertex.
struct Features {
  std::vector<uint8_t> edge;
  std::vector<int> count;
};

// Returns the edges sharper than feature_angle_deg (between the two faces'
// normals) that lie in connected feature lines of at least min_edges edges:
// a machined edge or a crease crosses many triangles; a lone sharp edge is a
// scan or tessellation artefact. Open borders are not counted (the collapse
// keeps them on themselves and the limit surface's boundary is sharp anyway).
Features TagFeatures(const TriMesh& mesh, double feature_angle_deg, int min_edges) {
  const double min_cos = std::cos(feature_angle_deg * std::numbers::pi / 180.0);
  std::vector<OpenMesh::SmartEdgeHandle> sharp;
  std::vector<int> parent(mesh.n_vertices());
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const auto n0 = mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 0)));
    const auto n1 = mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 1)));
    if (OpenMesh::dot(n0, n1) >= min_cos) continue;
    sharp.push_back(e);
    parent[Find(parent, e.v0().idx())] = Find(parent, e.v1().idx());
  }
  std::vector<int> line_edges(mesh.n_vertices(), 0);
  for (auto e : sharp) ++line_edges[Find(parent, e.v0().idx())];
  Features out{std::vector<uint8_t>(mesh.n_edges(), 0), std::vector<int>(mesh.n_vertices(), 0)};
  for (auto e : sharp) {
    if (line_edges[Find(parent, e.v0().idx())] < min_edges) continue;
    out.edge[e.idx()] = 1;
    ++out.count[e.v0().idx()];
    ++out.count[e.v1().idx()];
  }
  return out;
}

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
                                            double feature_angle_deg, int min_crease_edges,
                                            const RunContext& ctx) {
  TriMesh work = mesh;
  work.update_face_normals();
  const Features features = TagFeatures(work, feature_angle_deg, min_crease_edges);
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
      // Feature lines turn by more than feature_angle_deg: their two face
      // planes already price moving them sideways (see CollapseParams).
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
