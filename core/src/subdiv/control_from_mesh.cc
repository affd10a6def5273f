#include "subdiv/control_from_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"

namespace meshseg::subdiv_internal {
namespace {

using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
using Quadric = OpenMesh::Decimater::ModQuadricT<TriMesh>;
using NormalFlipping = OpenMesh::Decimater::ModNormalFlippingT<TriMesh>;

// A collapse that turns a face normal by more than this is refused: keeps the
// control mesh from folding over where the input curves strongly.
constexpr double kMaxNormalTurnDeg = 60.0;

class Progress : public OpenMesh::Decimater::Observer {
 public:
  Progress(const RunContext& ctx, size_t total) : Observer(4096), ctx_(ctx), total_(total) {}
  void notify(size_t step) override {
    ctx_.Progress("subdiv", 0.4 * std::min(1.0, static_cast<double>(step) / total_));
  }
  bool abort() const override { return ctx_.stop_requested(); }

 private:
  const RunContext& ctx_;
  size_t total_;
};

// Returns the root of v's set (path halving).
int Find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Tags feature edges and their vertices in `work`: edges sharper than
// feature_angle_deg, in connected feature lines of at least min_edges edges
// (a machined edge or a crease crosses many triangles; a lone sharp edge is a
// scan or tessellation artefact). Locks vertices whose feature-edge count is
// not 0 or 2. Returns the feature-edge count per vertex.
std::vector<int> TagFeatures(TriMesh& work, double feature_angle_deg, int min_edges) {
  const double min_cos = std::cos(feature_angle_deg * std::numbers::pi / 180.0);
  std::vector<OpenMesh::SmartEdgeHandle> sharp;
  std::vector<int> parent(work.n_vertices());
  for (size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
  for (auto e : work.edges()) {
    if (work.is_boundary(e)) continue;  // the decimater keeps boundaries on themselves
    const auto n0 = work.normal(work.face_handle(work.halfedge_handle(e, 0)));
    const auto n1 = work.normal(work.face_handle(work.halfedge_handle(e, 1)));
    if (OpenMesh::dot(n0, n1) >= min_cos) continue;
    sharp.push_back(e);
    parent[Find(parent, e.v0().idx())] = Find(parent, e.v1().idx());
  }
  std::vector<int> line_edges(work.n_vertices(), 0);
  for (auto e : sharp) ++line_edges[Find(parent, e.v0().idx())];
  std::vector<int> count(work.n_vertices(), 0);
  for (auto e : sharp) {
    if (line_edges[Find(parent, e.v0().idx())] < min_edges) continue;
    work.status(e).set_feature(true);
    for (auto v : {e.v0(), e.v1()}) {
      work.status(v).set_feature(true);
      ++count[v.idx()];
    }
  }
  for (auto v : work.vertices()) {
    if (count[v.idx()] != 0 && count[v.idx()] != 2) work.status(v).set_locked(true);
  }
  return count;
}

ControlMesh Compact(const TriMesh& work, const std::vector<int>& feature_count) {
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
    if (work.status(e).deleted() || !work.status(e).feature()) continue;
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
  const std::vector<int> feature_count = TagFeatures(work, feature_angle_deg, min_crease_edges);
  Decimater decimater(work);
  Quadric::Handle quadric;
  NormalFlipping::Handle flipping;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.module(flipping).set_max_normal_deviation(kMaxNormalTurnDeg);
  if (!decimater.initialize()) {
    return absl::InvalidArgumentError(
        absl::StrCat("subdiv: the decimater cannot start on a mesh of ", work.n_faces(), " faces"));
  }
  const size_t target = static_cast<size_t>(std::max<int64_t>(target_faces, 1));
  Progress progress(ctx,
                    std::max<size_t>(1, (work.n_faces() - std::min(target, work.n_faces())) / 2));
  decimater.set_observer(&progress);
  decimater.decimate_to_faces(0, target);
  decimater.set_observer(nullptr);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("subdiv"));
  return Compact(work, feature_count);
}

}  // namespace meshseg::subdiv_internal
