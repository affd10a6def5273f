#include "reconstruct/handles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/container/flat_hash_map.h"
#include "mesh/union_find.h"
#include "meshseg/status_macros.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/handle_strips.h"
#include "reconstruct/support.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

int SeenGenus(const TriMesh& tri, const std::vector<uint8_t>& filled) {
  if (filled.size() != tri.n_faces()) return Genus(tri);  // no flags: all seen
  const auto seen = [&](TriMesh::FaceHandle f) { return f.is_valid() && !filled[f.idx()]; };
  // χ = V − E + F and the components of the seen faces.
  int64_t chi = 0;
  std::vector<int> parent(tri.n_faces());
  for (const auto f : tri.faces()) {
    parent[f.idx()] = f.idx();
    chi += seen(f);
  }
  for (const auto v : tri.vertices()) {
    for (const auto f : tri.vf_range(v)) {
      if (!seen(f)) continue;
      ++chi;
      break;
    }
  }
  for (const auto e : tri.edges()) {
    const auto f = tri.face_handle(tri.halfedge_handle(e, 0));
    const auto g = tri.face_handle(tri.halfedge_handle(e, 1));
    if (!seen(f) && !seen(g)) continue;
    --chi;
    if (seen(f) && seen(g)) parent[FindRoot(parent, f.idx())] = FindRoot(parent, g.idx());
  }
  int64_t components = 0, loops = 0;
  for (const auto f : tri.faces()) components += seen(f) && FindRoot(parent, f.idx()) == f.idx();
  // Border loops: each border halfedge of the seen faces (its face seen, the
  // other side not) leads to the next round its loop's start.
  std::vector<uint8_t> walked(tri.n_halfedges(), 0);
  const auto on_border = [&](TriMesh::HalfedgeHandle h) {
    return seen(tri.face_handle(h)) && !seen(tri.opposite_face_handle(h));
  };
  for (const auto start : tri.halfedges()) {
    if (walked[start.idx()] || !on_border(start)) continue;
    ++loops;
    for (auto h = start; !walked[h.idx()];) {
      walked[h.idx()] = 1;
      auto next = tri.next_halfedge_handle(h);
      while (!on_border(next)) next = tri.next_halfedge_handle(tri.opposite_halfedge_handle(next));
      h = next;
    }
  }
  return static_cast<int>((2 * components - chi - loops) / 2);
}

namespace {

// MaxHandleLoops at the vertices whose entry in `*max_loop` is negative.
void FillMaxHandleLoops(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                        const mesh_internal::PointIndex& index, double handle_spacings,
                        double min_spacing, std::vector<double>* max_loop) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tri.n_vertices()), [&](const auto& range) {
    std::vector<uint32_t> near;
    std::vector<double> dist2;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if ((*max_loop)[i] >= 0) continue;
      const Eigen::Vector3d& p =
          points[index.Closest(ToEigen(tri.point(TriMesh::VertexHandle(static_cast<int>(i)))))];
      (*max_loop)[i] =
          M_PI * handle_spacings * std::max(min_spacing, SpacingAtPoint(p, index, &near, &dist2));
    }
  });
}

using Position = std::array<double, 3>;

Position PositionOf(const TriMesh& tri, TriMesh::VertexHandle v) {
  const auto& p = tri.point(v);
  return {p[0], p[1], p[2]};
}

}  // namespace

std::vector<double> MaxHandleLoops(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index, double handle_spacings,
                                   double min_spacing) {
  std::vector<double> max_loop(tri.n_vertices(), -1.0);
  FillMaxHandleLoops(tri, points, index, handle_spacings, min_spacing, &max_loop);
  return max_loop;
}

absl::Status CutUnsupportedHandles(const std::vector<Eigen::Vector3d>& points,
                                   const mesh_internal::PointIndex& index,
                                   const ReconstructParams& params, Mesh* mesh,
                                   std::vector<uint8_t>* filled, ReconstructStats* stats) {
  // After the first round, only loops near the patches of the last one.
  std::vector<uint8_t> near;
  absl::flat_hash_map<Position, double> known;  // max_loop by vertex position
  // The spacing the refined mesh follows (refine.h); 0 without refinement.
  const double mesh_spacing = params.refine_edge_length > 0
                                  ? stats->refine_edge_length / params.refine_edge_length
                                  : 0.0;
  // Loops up to twice the round-hole loop first; once those leave nothing
  // to cut, the longer slit search (balls twice as large) from scratch.
  double search = 2.0;
  for (int round = 0; round < 2 * kHandleRounds; ++round) {
    // The patches add genus only by construction: a disc none, a tube
    // (close_tube.h) one, a handle its rims show the points resolve. By
    // Euler's formula the closed surface's genus is the seen surface's (the
    // faces not filled) plus one per tube, so the handles the points may not
    // support are at most the seen surface's genus, and there is nothing
    // to search for when it is 0.
    const int genus = std::min(Genus(mesh->tri), SeenGenus(mesh->tri, *filled));
    if (genus <= 0) break;
    // Round holes up to handle_spacings × s across have loops up to π times
    // that; loops up to `search` times as long are looked at for slits as
    // narrow, and for holes whose void the scan points fill (HoleAtMost).
    // The bound is a function of a vertex's position alone (the nearest
    // point's spacing): a vertex the last round kept where it was keeps it.
    std::vector<double> max_loop(mesh->tri.n_vertices(), -1.0);
    for (const auto v : mesh->tri.vertices()) {
      const auto it = known.find(PositionOf(mesh->tri, v));
      if (it != known.end()) max_loop[v.idx()] = it->second;
    }
    FillMaxHandleLoops(mesh->tri, points, index, params.handle_spacings, mesh_spacing, &max_loop);
    known.clear();
    for (const auto v : mesh->tri.vertices()) {
      known.emplace(PositionOf(mesh->tri, v), max_loop[v.idx()]);
    }
    std::vector<double> max_width(max_loop.size());
    for (size_t v = 0; v < max_loop.size(); ++v) {
      max_width[v] = max_loop[v] / M_PI;
      max_loop[v] *= search;
    }
    const HandleStrips strips = ShortHandleStrips(mesh->tri, max_loop, genus, near, max_width, {&points, &index});
    if (strips.cut_count == 0) {
      if (search == kSlitLoops) break;
      search = kSlitLoops;
      near.clear();
      continue;
    }
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
