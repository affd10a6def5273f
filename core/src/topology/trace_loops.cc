#include "topology/trace_loops.h"

#include <atomic>
#include <cassert>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/concurrent_union_find.h"
#include "topology/chain_curves.h"

namespace meshseg::topology_internal {
namespace {

using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;

// The next boundary halfedge of the patch on the left of `h`: turn around
// h's end vertex inside the patch until the boundary.
HalfedgeHandle NextAlongPatch(const TriMesh& mesh, std::span<const int> labels, HalfedgeHandle h) {
  HalfedgeHandle n = mesh.next_halfedge_handle(h);
  while (!IsBoundaryHalfedge(mesh, labels, n)) {
    n = mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(n));
  }
  return n;
}

// The curve use of one boundary halfedge.
CurveUse UseOf(const TriMesh& mesh, std::span<const int> halfedge_curve, HalfedgeHandle h) {
  if (halfedge_curve[h.idx()] >= 0) return {halfedge_curve[h.idx()], false};
  const int c = halfedge_curve[mesh.opposite_halfedge_handle(h).idx()];
  assert(c >= 0 && "every boundary edge lies on a curve");
  return {c, true};
}

}  // namespace

FacePatches LabelPatches(const TriMesh& mesh, std::span<const int> labels, int region_count) {
  // The patches are the components of the graph of equally labelled faces
  // across an edge, found with a concurrent union-find (each edge joined
  // once, from its lower face, side by side; mesh/concurrent_union_find.h).
  // Every component's root is its lowest face whatever order the joins ran
  // in, so numbering the roots in face order within their label gives each
  // patch the index a flood fill seeded in face order gives it.
  const int nf = static_cast<int>(mesh.n_faces());
  std::vector<std::atomic<int>> parent = mesh_internal::SingletonSets(nf);
  tbb::parallel_for(tbb::blocked_range<int>(0, nf, 4096), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      if (labels[f] < 0) continue;
      for (HalfedgeHandle h : mesh.fh_range(FaceHandle(f))) {
        const FaceHandle g = mesh.opposite_face_handle(h);
        if (g.is_valid() && g.idx() > f && labels[g.idx()] == labels[f]) {
          mesh_internal::JoinToLowest(parent, f, g.idx());
        }
      }
    }
  });
  FacePatches out;
  out.patch_count.assign(region_count, 0);
  // Roots numbered in face order within their label.
  out.face_patch = mesh_internal::NumberSets(
      parent, [&](int f) { return labels[f] >= 0; },
      [&](int f) { return out.patch_count[labels[f]]++; });
  return out;
}

TracedLoops TraceLoops(const TriMesh& mesh, std::span<const int> face_labels,
                       std::span<const int> halfedge_curve, FacePatches patches) {
  TracedLoops out;
  out.face_patch = std::move(patches.face_patch);
  out.patch_count = std::move(patches.patch_count);
  // Which halfedges can start a loop (a labelled face on the left, another
  // label across) is a test of each halfedge alone: flag them in parallel,
  // and walk only the flagged ones in index order, so the loops come out
  // exactly as from a scan of all.
  std::vector<char> boundary(mesh.n_halfedges(), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(mesh.n_halfedges()), 1 << 14),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int i = range.begin(); i < range.end(); ++i) {
                        const HalfedgeHandle h(i);
                        const FaceHandle f = mesh.face_handle(h);
                        boundary[i] = f.is_valid() && face_labels[f.idx()] >= 0 &&
                                      IsBoundaryHalfedge(mesh, face_labels, h);
                      }
                    });
  std::vector<char> visited(mesh.n_halfedges(), 0);
  for (int i = 0; i < static_cast<int>(mesh.n_halfedges()); ++i) {
    if (!boundary[i] || visited[i]) continue;
    const HalfedgeHandle start(i);
    const FaceHandle f = mesh.face_handle(start);
    Loop loop;
    loop.id = static_cast<int>(out.loops.size());
    loop.region = face_labels[f.idx()];
    loop.patch = out.face_patch[f.idx()];
    std::vector<int> vertices = {mesh.from_vertex_handle(start).idx()};
    HalfedgeHandle h = start;
    do {
      visited[h.idx()] = 1;
      vertices.push_back(mesh.to_vertex_handle(h).idx());
      const CurveUse use = UseOf(mesh, halfedge_curve, h);
      if (loop.curves.empty() || loop.curves.back().curve != use.curve) loop.curves.push_back(use);
      h = NextAlongPatch(mesh, face_labels, h);
    } while (h != start);
    // The walk may have started inside a curve: join its two pieces.
    if (loop.curves.size() > 1 && loop.curves.front().curve == loop.curves.back().curve) {
      loop.curves.pop_back();
    }
    out.loops.push_back(std::move(loop));
    out.loop_vertices.push_back(std::move(vertices));
  }
  return out;
}

}  // namespace meshseg::topology_internal
