#include "reconstruct/close_unsupported.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include <Eigen/Geometry>

#include "absl/strings/str_cat.h"
#include "mesh/union_find.h"
#include "meshseg/status_macros.h"
#include "reconstruct/close_hole.h"
#include "reconstruct/close_tube.h"
#include "reconstruct/split_at_cap.h"
#include "reconstruct/surface_mesh.h"
#include "reconstruct/tube_rims.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

using Kernel = HoleKernel;
using Sm = HoleMesh;

// Marks every face of a vertex whose fan alternates kept/removed more than
// once; returns whether it marked any.
bool RemovePinches(const TriMesh& tri, std::vector<uint8_t>* removed) {
  bool changed = false;
  for (const auto v : tri.vertices()) {
    int changes = 0;
    uint8_t first = 2, last = 2;
    for (const auto f : tri.vf_range(v)) {
      const uint8_t r = (*removed)[f.idx()];
      if (first == 2) first = r;
      if (last != 2 && r != last) ++changes;
      last = r;
    }
    if (last != first) ++changes;  // the fan is a cycle
    if (changes <= 2) continue;
    for (const auto f : tri.vf_range(v)) (*removed)[f.idx()] = 1;
    changed = true;
  }
  return changed;
}

// Marks the kept edge-connected pieces with fewer faces than min_fraction of
// the largest; returns whether it marked any.
bool RemoveSmallPieces(const TriMesh& tri, double min_fraction, std::vector<uint8_t>* removed) {
  std::vector<int> parent = FacePieces(tri, *removed, 0);
  std::vector<int64_t> size(tri.n_faces(), 0);
  for (size_t f = 0; f < parent.size(); ++f) {
    if (!(*removed)[f]) ++size[FindRoot(parent, static_cast<int>(f))];
  }
  const int64_t largest = *std::max_element(size.begin(), size.end());
  bool changed = false;
  for (size_t f = 0; f < parent.size(); ++f) {
    if ((*removed)[f] || size[FindRoot(parent, static_cast<int>(f))] >= min_fraction * largest)
      continue;
    (*removed)[f] = 1;
    changed = true;
  }
  return changed;
}

// The kept faces as a Surface_mesh; `filled` is 1 on every face added later
// and on kept faces flagged in `prior_filled` (if not empty). `tri_vertex`
// gets the vertex of `tri` of each of its vertices.
Sm KeptFaces(const TriMesh& tri, const std::vector<uint8_t>& removed,
             const std::vector<uint8_t>& prior_filled, std::vector<int>* tri_vertex) {
  Sm sm;
  std::vector<Sm::Vertex_index> vertex(tri.n_vertices());
  std::vector<uint8_t> used(tri.n_vertices(), 0);
  for (const auto f : tri.faces()) {
    if (removed[f.idx()]) continue;
    for (const auto v : tri.fv_range(f)) used[v.idx()] = 1;
  }
  for (const auto v : tri.vertices()) {
    if (!used[v.idx()]) continue;
    const auto& p = tri.point(v);
    vertex[v.idx()] = sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
    tri_vertex->push_back(v.idx());
  }
  auto filled = sm.add_property_map<Sm::Face_index, uint8_t>("f:filled", 1).first;
  for (const auto f : tri.faces()) {
    if (removed[f.idx()]) continue;
    std::array<Sm::Vertex_index, 3> corner;
    int k = 0;
    for (const auto v : tri.fv_range(f)) corner[k++] = vertex[v.idx()];
    filled[sm.add_face(corner[0], corner[1], corner[2])] =
        prior_filled.empty() ? 0 : prior_filled[f.idx()];
  }
  return sm;
}

// One border halfedge per border loop of `sm`.
std::vector<Sm::Halfedge_index> BorderLoops(const Sm& sm, std::vector<size_t>* lengths) {
  std::vector<Sm::Halfedge_index> loops;
  std::vector<uint8_t> seen(sm.num_halfedges(), 0);
  for (const auto h : sm.halfedges()) {
    if (!sm.is_border(h) || seen[h]) continue;
    loops.push_back(h);
    size_t n = 0;
    for (auto g = h; !seen[g]; g = sm.next(g), ++n) seen[g] = 1;
    lengths->push_back(n);
  }
  return loops;
}

// +1 when the faces of the closed `tri` face outwards (positive volume), else -1.
double Outwards(const TriMesh& tri) {
  double volume = 0.0;
  for (const auto f : tri.faces()) {
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for (const auto v : tri.fv_range(f)) c[k++] = ToEigen(tri.point(v));
    volume += c[0].dot(c[1].cross(c[2]));
  }
  return volume >= 0 ? 1.0 : -1.0;
}

int Components(const TriMesh& tri) {
  std::vector<int> parent(tri.n_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto e : tri.edges()) {
    const auto h = tri.halfedge_handle(e, 0);
    parent[FindRoot(parent, tri.from_vertex_handle(h).idx())] =
        FindRoot(parent, tri.to_vertex_handle(h).idx());
  }
  int count = 0;
  for (size_t v = 0; v < parent.size(); ++v)
    count += FindRoot(parent, static_cast<int>(v)) == static_cast<int>(v);
  return count;
}

}  // namespace

int64_t BorderLoopCount(const TriMesh& tri) {
  int64_t loops = 0;
  std::vector<uint8_t> seen(tri.n_halfedges(), 0);
  for (const auto h : tri.halfedges()) {
    if (!tri.is_boundary(h) || seen[h.idx()]) continue;
    ++loops;
    for (auto g = h; !seen[g.idx()]; g = tri.next_halfedge_handle(g)) seen[g.idx()] = 1;
  }
  return loops;
}

int Genus(const TriMesh& tri) {
  const int64_t loops = BorderLoopCount(tri);
  const int64_t chi = static_cast<int64_t>(tri.n_vertices()) - static_cast<int64_t>(tri.n_edges()) +
                      static_cast<int64_t>(tri.n_faces());
  return static_cast<int>((2 * Components(tri) - chi - loops) / 2);
}

absl::StatusOr<ClosedSurface> CloseUnsupported(const Mesh& mesh,
                                               const std::vector<uint8_t>& supported,
                                               double min_component_fraction, bool leave_open,
                                               const std::vector<uint8_t>& prior_filled,
                                               bool bend_onto_seen_planes, double min_tube_rim) {
  const TriMesh& tri = mesh.tri;
  ClosedSurface out;
  std::vector<uint8_t> removed(tri.n_faces());
  for (size_t f = 0; f < removed.size(); ++f) removed[f] = !supported[f];
  if (std::find(removed.begin(), removed.end(), 1) != removed.end()) {
    bool changed = true;
    while (changed) {
      changed = RemovePinches(tri, &removed);
      if (min_component_fraction > 0 &&
          std::find(removed.begin(), removed.end(), 0) != removed.end()) {
        changed = RemoveSmallPieces(tri, min_component_fraction, &removed) || changed;
      }
    }
  }
  out.removed_face_count = std::count(removed.begin(), removed.end(), 1);
  if (out.removed_face_count == 0 ||
      out.removed_face_count == static_cast<int64_t>(removed.size())) {
    // Nothing unsupported, or nothing supported (no surface to close onto).
    out.removed_face_count = 0;
    out.mesh = mesh;
    out.filled = prior_filled.empty() ? std::vector<uint8_t>(tri.n_faces(), 0) : prior_filled;
    for (const auto f : tri.faces()) {
      if (out.filled[f.idx()]) out.filled_area += tri.calc_face_area(f);
    }
    return out;
  }
  std::vector<int> tri_vertex;
  Sm sm = KeptFaces(tri, removed, prior_filled, &tri_vertex);
  std::vector<size_t> lengths;
  const std::vector<Sm::Halfedge_index> loops = BorderLoops(sm, &lengths);
  out.hole_count = static_cast<int64_t>(loops.size());
  if (!leave_open) {
    const double sign = Outwards(tri);
    std::vector<uint8_t> closed(loops.size(), 0);
    if (min_tube_rim >= 0) {
      // Both read the loops before any is closed.
      const auto tube_rims = TubeRims(tri, removed, sm, tri_vertex, loops, min_tube_rim);
      const auto lone_rims = LoneBoreRims(tri, removed, sm, tri_vertex, loops, min_tube_rim);
      for (const auto& [i, j] : tube_rims) {
        if (CloseTube(loops[i], loops[j], sign, bend_onto_seen_planes, &sm)) {
          closed[i] = closed[j] = 1;
        }
      }
      // A bore's rim and the rim round the unseen face its axis meets, left
      // in two removed components (tube_rims.h LoneBoreRims).
      for (const auto& [i, j] : lone_rims) {
        if (closed[i] || closed[j]) continue;
        if (SplitAtCap(RimOf(sm, loops[i], sign), RimOf(sm, loops[j], sign), sign,
                       bend_onto_seen_planes, &sm)) {
          closed[i] = closed[j] = 1;
        }
      }
    }
    for (size_t i = 0; i < loops.size(); ++i) {
      if (!closed[i]) CloseHole(loops[i], lengths[i], sign, bend_onto_seen_planes, &sm);
    }
  }
  if (sm.has_garbage()) sm.collect_garbage();  // a tube given up
  FlipFlatPatchFaces(&sm);
  const auto filled = sm.property_map<Sm::Face_index, uint8_t>("f:filled").first;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> index(sm.num_vertices(), -1);
  for (const auto v : sm.vertices()) {
    index[v] = static_cast<int>(points.size());
    const auto& p = sm.point(v);
    points.emplace_back(p.x(), p.y(), p.z());
  }
  // Every face is a triangle: the kept ones, CGAL's patches and the fans.
  std::vector<std::array<int, 3>> triangles;
  for (const auto f : sm.faces()) {
    const auto h = sm.halfedge(f);
    triangles.push_back({index[sm.source(h)], index[sm.target(h)], index[sm.target(sm.next(h))]});
    out.filled.push_back(filled[f]);
    if (!filled[f]) continue;
    const Eigen::Vector3d& a = points[triangles.back()[0]];
    out.filled_area +=
        0.5 * (points[triangles.back()[1]] - a).cross(points[triangles.back()[2]] - a).norm();
  }
  // SurfaceMesh refuses a triangle that would make the result non-manifold.
  MESHSEG_ASSIGN_OR_RETURN(Mesh result, SurfaceMesh(points, triangles, mesh.name));
  if (!leave_open) {
    for (const auto e : result.tri.edges()) {
      if (result.tri.is_boundary(e)) {
        return absl::InternalError(
            absl::StrCat("reconstruct: \"", mesh.name, "\": a closed hole left an open edge"));
      }
    }
  }
  out.mesh = std::move(result);
  return out;
}

}  // namespace meshseg::reconstruct_internal
