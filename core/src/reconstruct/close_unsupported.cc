#include "reconstruct/close_unsupported.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>

#include <Eigen/Geometry>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "absl/strings/str_cat.h"
#include "mesh/union_find.h"
#include "meshseg/status_macros.h"
#include "reconstruct/seen_planes.h"
#include "reconstruct/surface_mesh.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Sm = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Loops longer than this skip CGAL's cubic search over all triangles of the
// loop when the Delaunay search space fails (O(n³) time, about 1 s CPU at 400
// vertices), so they are split by a chord first (SplitHole); a fan closes
// what still fails. The underside of a scanned part is such a loop,
// zigzagging along the walls' lowest seen rows, and its fan (no inner vertex,
// spokes as long as the part) cannot be bent onto the seen planes.
constexpr size_t kMaxCubicLoop = 500;
// A triangle is flat when twice its area is at most this fraction of its
// longest edge squared (a hundred times the mesh readers' limit).
constexpr double kFlatRatio = 1e-10;
// Rounds of flipping flat patch triangles at most.
constexpr int kFlatFlipPasses = 3;

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
  std::vector<int> parent(tri.n_faces());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto e : tri.edges()) {
    if (tri.is_boundary(e)) continue;
    const int a = tri.face_handle(tri.halfedge_handle(e, 0)).idx();
    const int b = tri.face_handle(tri.halfedge_handle(e, 1)).idx();
    if ((*removed)[a] || (*removed)[b]) continue;
    parent[FindRoot(parent, a)] = FindRoot(parent, b);
  }
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
// and on kept faces flagged in `prior_filled` (if not empty).
Sm KeptFaces(const TriMesh& tri, const std::vector<uint8_t>& removed,
             const std::vector<uint8_t>& prior_filled) {
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

// Closes the loop of `h` by a fan around the centroid of its vertices.
void FanClose(Sm::Halfedge_index h, Sm* sm) {
  Kernel::Vector_3 sum(0, 0, 0);
  int n = 0;
  for (auto g = h;;) {
    sum = sum + (sm->point(sm->target(g)) - CGAL::ORIGIN);
    ++n;
    g = sm->next(g);
    if (g == h) break;
  }
  CGAL::Euler::fill_hole(h, *sm);  // h now borders the new polygon
  const auto spoke = CGAL::Euler::add_center_vertex(h, *sm);
  sm->point(sm->target(spoke)) = CGAL::ORIGIN + sum / n;
}

Eigen::Vector3d ToEigen3(const Kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

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

// The vertices of the loop of border halfedge `h` and the outward normals of
// the surface there (`sign` × the area-weighted normal of their faces).
void LoopWithNormals(const Sm& sm, Sm::Halfedge_index h, double sign,
                     std::vector<Eigen::Vector3d>* loop, std::vector<Eigen::Vector3d>* normals) {
  loop->clear();
  normals->clear();
  for (auto g = h;;) {
    const auto v = sm.target(g);
    loop->push_back(ToEigen3(sm.point(v)));
    const auto n = PMP::compute_vertex_normal(v, sm);
    normals->push_back(sign * Eigen::Vector3d(n.x(), n.y(), n.z()));
    g = sm.next(g);
    if (g == h) break;
  }
}

// Bends the patch `faces` (free vertices `vertices`) of a hole whose loop was
// `loop` onto the seen planes (seen_planes.h).
void BendPatch(const std::vector<Eigen::Vector3d>& loop,
               const std::vector<Eigen::Vector3d>& normals, double sign,
               const std::vector<Sm::Face_index>& faces,
               const std::vector<Sm::Vertex_index>& vertices, Sm* sm) {
  Eigen::Vector3d patch_normal = Eigen::Vector3d::Zero();
  for (const auto f : faces) {
    const auto h = sm->halfedge(f);
    const Eigen::Vector3d a = ToEigen3(sm->point(sm->source(h)));
    const Eigen::Vector3d b = ToEigen3(sm->point(sm->target(h)));
    const Eigen::Vector3d c = ToEigen3(sm->point(sm->target(sm->next(h))));
    patch_normal += sign * (b - a).cross(c - a);
  }
  std::vector<Eigen::Vector3d> free_vertices;
  for (const auto v : vertices) free_vertices.push_back(ToEigen3(sm->point(v)));
  if (!BendOntoSeenPlanes(loop, normals, patch_normal, &free_vertices)) return;
  for (size_t i = 0; i < vertices.size(); ++i) {
    sm->point(vertices[i]) =
        Kernel::Point_3(free_vertices[i].x(), free_vertices[i].y(), free_vertices[i].z());
  }
}

// Splits the hole of border halfedge `h` (a loop of `n` vertices) in two by
// a chord between the two loop vertices nearest each other in space among
// those at least a third of the loop apart along it, so each half has at most
// about 2 n / 3 vertices; the chord lies across the unseen area, in the
// surface where the loop's two sides are near. Returns a halfedge of the
// chord whose face is one half's polygon (the other half's polygon lies
// across it), or nothing when every such pair is already joined by an edge.
std::optional<Sm::Halfedge_index> SplitHole(Sm::Halfedge_index h, size_t n, Sm* sm) {
  std::vector<Sm::Halfedge_index> loop;
  for (auto g = h; loop.size() < n; g = sm->next(g)) loop.push_back(g);
  const size_t min_arc = n / 3;
  double best = std::numeric_limits<double>::infinity();
  size_t bi = 0, bj = 0;
  for (size_t i = 0; i < n; ++i) {
    const auto u = sm->target(loop[i]);
    for (size_t j = i + min_arc; j + min_arc <= i + n && j < n; ++j) {
      const auto w = sm->target(loop[j]);
      const double d2 = CGAL::squared_distance(sm->point(u), sm->point(w));
      if (d2 >= best || u == w || CGAL::halfedge(u, w, *sm).second) continue;
      best = d2;
      bi = i;
      bj = j;
    }
  }
  if (!std::isfinite(best)) return std::nullopt;
  CGAL::Euler::fill_hole(h, *sm);
  return CGAL::Euler::split_face(loop[bi], loop[bj], *sm);
}

// The number of halfedges around the cycle of `h`.
size_t CycleLength(Sm::Halfedge_index h, const Sm& sm) {
  size_t n = 0;
  for (auto g = h;;) {
    ++n;
    g = sm.next(g);
    if (g == h) return n;
  }
}

// Closes the hole of border halfedge `h` (a loop of `n` vertices) by CGAL's
// triangulation, refinement and fairing (Liepa 2003), or by a fan when that
// fails; a loop over kMaxCubicLoop vertices is first split by a chord
// (SplitHole). With `bend`, each patch is bent onto the seen planes of the
// whole hole's `loop` (with outward `normals`; seen_planes.h).
void CloseHole(Sm::Halfedge_index h, size_t n, const std::vector<Eigen::Vector3d>& loop,
               const std::vector<Eigen::Vector3d>& normals, double sign, bool bend, Sm* sm) {
  if (n > kMaxCubicLoop) {
    if (const auto chord = SplitHole(h, n, sm)) {
      const auto other = sm->opposite(*chord);
      CGAL::Euler::make_hole(*chord, *sm);
      CloseHole(*chord, CycleLength(*chord, *sm), loop, normals, sign, bend, sm);
      CGAL::Euler::make_hole(other, *sm);
      CloseHole(other, CycleLength(other, *sm), loop, normals, sign, bend, sm);
      return;
    }
  }
  std::vector<Sm::Face_index> faces;
  std::vector<Sm::Vertex_index> vertices;
  PMP::triangulate_refine_and_fair_hole(
      *sm, h, std::back_inserter(faces), std::back_inserter(vertices),
      PMP::parameters::fairing_continuity(0).do_not_use_cubic_algorithm(n > kMaxCubicLoop));
  if (faces.empty() && sm->is_border(h)) {
    FanClose(h, sm);
  } else if (bend) {
    BendPatch(loop, normals, sign, faces, vertices, sm);
  }
}

// A patch triangle on three (nearly) collinear vertices (loop vertices the
// refinement put on one straight crease line) has no area: mesh readers drop
// it, and the surface read back is open. Flipping its longest edge, when a
// patch face lies across it, replaces it by two triangles with the apex of
// that face.
void FlipFlatPatchFaces(Sm* sm) {
  const auto filled = sm->property_map<Sm::Face_index, uint8_t>("f:filled").first;
  for (int pass = 0; pass < kFlatFlipPasses; ++pass) {
    bool changed = false;
    for (const auto f : sm->faces()) {
      if (!filled[f]) continue;
      Sm::Halfedge_index longest;
      double longest2 = -1.0;
      for (const auto h : CGAL::halfedges_around_face(sm->halfedge(f), *sm)) {
        const double l2 = CGAL::squared_distance(sm->point(sm->source(h)), sm->point(sm->target(h)));
        if (l2 > longest2) {
          longest2 = l2;
          longest = h;
        }
      }
      const Eigen::Vector3d a = ToEigen3(sm->point(sm->source(longest)));
      const Eigen::Vector3d b = ToEigen3(sm->point(sm->target(longest)));
      const Eigen::Vector3d c = ToEigen3(sm->point(sm->target(sm->next(longest))));
      if ((b - a).cross(c - a).norm() > kFlatRatio * longest2) continue;
      const auto across = sm->opposite(longest);
      if (sm->is_border(across) || !filled[sm->face(across)]) continue;
      const auto u = sm->target(sm->next(longest)), w = sm->target(sm->next(across));
      if (u == w || CGAL::halfedge(u, w, *sm).second) continue;
      CGAL::Euler::flip_edge(longest, *sm);
      changed = true;
    }
    if (!changed) break;
  }
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
                                               bool bend_onto_seen_planes) {
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
  Sm sm = KeptFaces(tri, removed, prior_filled);
  std::vector<size_t> lengths;
  const std::vector<Sm::Halfedge_index> loops = BorderLoops(sm, &lengths);
  out.hole_count = static_cast<int64_t>(loops.size());
  if (!leave_open) {
    const double sign = Outwards(tri);
    std::vector<Eigen::Vector3d> loop, normals;
    for (size_t i = 0; i < loops.size(); ++i) {
      LoopWithNormals(sm, loops[i], sign, &loop, &normals);
      CloseHole(loops[i], lengths[i], loop, normals, sign, bend_onto_seen_planes, &sm);
    }
  }
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
