#include "reconstruct/close_hole.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "reconstruct/seen_planes.h"

namespace meshseg::reconstruct_internal {
namespace {

using Kernel = HoleKernel;
using Sm = HoleMesh;
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
// A faired patch vertex may lie this many mean loop edges outside the loop's
// bounding box (the cotangent weights' excess over the maximum principle).
constexpr double kMembraneSlackEdges = 1.0;
// Rounds of flipping flat patch triangles at most.
constexpr int kFlatFlipPasses = 3;

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

// The weights of the umbrella operator (every neighbour 1): positive, so the
// harmonic patch they give obeys the maximum principle.
struct UniformWeights {
  double w_ij(Sm::Halfedge_index) const { return 1.0; }
  double w_i(Sm::Vertex_index) const { return 1.0; }
};

}  // namespace

void KeepMembraneInsideItsLoop(const std::vector<Eigen::Vector3d>& loop,
                               const std::vector<HoleMesh::Vertex_index>& vertices, HoleMesh* sm) {
  if (loop.empty() || vertices.empty()) return;
  Eigen::Vector3d lo = loop[0], hi = loop[0];
  for (const Eigen::Vector3d& p : loop) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double slack = kMembraneSlackEdges * LoopPerimeter(loop) / static_cast<double>(loop.size());
  const bool outside = std::any_of(vertices.begin(), vertices.end(), [&](Sm::Vertex_index v) {
    const Eigen::Vector3d x = ToEigen3(sm->point(v));
    return (x - x.cwiseMax(lo).cwiseMin(hi)).norm() > slack;
  });
  if (!outside) return;
  PMP::fair(*sm, vertices,
            PMP::parameters::weight_calculator(UniformWeights{}).fairing_continuity(0));
}

namespace {

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

// CloseHole below, with the whole hole's `loop` and outward `normals`.
void CloseLoop(Sm::Halfedge_index h, size_t n, const std::vector<Eigen::Vector3d>& loop,
               const std::vector<Eigen::Vector3d>& normals, double sign, bool bend, Sm* sm) {
  if (n > kMaxCubicLoop) {
    if (const auto chord = SplitHole(h, n, sm)) {
      const auto other = sm->opposite(*chord);
      CGAL::Euler::make_hole(*chord, *sm);
      CloseLoop(*chord, CycleLength(*chord, *sm), loop, normals, sign, bend, sm);
      CGAL::Euler::make_hole(other, *sm);
      CloseLoop(other, CycleLength(other, *sm), loop, normals, sign, bend, sm);
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
    return;
  }
  KeepMembraneInsideItsLoop(loop, vertices, sm);
  if (bend) BendPatch(loop, normals, sign, faces, vertices, sm);
}

}  // namespace

void CloseHole(HoleMesh::Halfedge_index h, size_t n, double sign, bool bend, HoleMesh* sm) {
  std::vector<Eigen::Vector3d> loop, normals;
  LoopWithNormals(*sm, h, sign, &loop, &normals);
  CloseLoop(h, n, loop, normals, sign, bend, sm);
}

namespace {

// Whether every face around `v` is a patch face (flagged in `filled`): `v`
// is a free vertex of a patch, not on its loop.
bool FreePatchVertex(Sm::Vertex_index v, Sm::Property_map<Sm::Face_index, uint8_t> filled,
                     const Sm& sm) {
  for (const auto g : CGAL::faces_around_target(sm.halfedge(v), sm)) {
    if (g == Sm::null_face() || !filled[g]) return false;
  }
  return true;
}

// Collapses `e` (a free patch vertex at one end at least) into one vertex at
// the position of the end that is not free, or of either; false when the
// collapse would break the surface (the link condition).
bool MergeEnds(Sm::Edge_index e, Sm::Property_map<Sm::Face_index, uint8_t> filled, Sm* sm) {
  const auto h = sm->halfedge(e);
  const bool source_free = FreePatchVertex(sm->source(h), filled, *sm);
  if (!source_free && !FreePatchVertex(sm->target(h), filled, *sm)) return false;
  if (!CGAL::Euler::does_satisfy_link_condition(e, *sm)) return false;
  const auto at = sm->point(source_free ? sm->target(h) : sm->source(h));
  sm->point(CGAL::Euler::collapse_edge(e, *sm)) = at;
  return true;
}

// Collapses each edge of a patch face of `sm` (flagged in `filled`) whose
// ends coincide, within kFlatRatio of the face's longest edge squared, into
// the position of its end that is not a free patch vertex, if one is not;
// true when any was.
bool CollapseCoincidentPatchEnds(Sm::Property_map<Sm::Face_index, uint8_t> filled, Sm* sm) {
  bool collapsed = false;
  for (const auto f : sm->faces()) {
    if (sm->is_removed(f) || !filled[f]) continue;
    double longest2 = 0.0;
    for (const auto h : CGAL::halfedges_around_face(sm->halfedge(f), *sm)) {
      longest2 = std::max(longest2, CGAL::squared_distance(sm->point(sm->source(h)),
                                                           sm->point(sm->target(h))));
    }
    for (const auto h : CGAL::halfedges_around_face(sm->halfedge(f), *sm)) {
      if (CGAL::squared_distance(sm->point(sm->source(h)), sm->point(sm->target(h))) >
          kFlatRatio * longest2) {
        continue;
      }
      // A loop vertex stays where it is; two are the kept surface's.
      if (!MergeEnds(sm->edge(h), filled, sm)) continue;
      collapsed = true;
      break;  // f is gone
    }
  }
  return collapsed;
}

}  // namespace

void FlipFlatPatchFaces(Sm* sm) {
  const auto filled = sm->property_map<Sm::Face_index, uint8_t>("f:filled").first;
  bool removed = false;
  for (int pass = 0; pass < kFlatFlipPasses; ++pass) {
    // Two coincident vertices (a zero-length edge) bound no area: one point
    // of the surface given twice. Merging them leaves the surface as it is,
    // where no flip could: the flip's apex would be an end of its edge.
    bool changed = CollapseCoincidentPatchEnds(filled, sm);
    removed = removed || changed;
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
      // The apex lies on the longest edge, so the flip splits the face
      // across at the apex into two triangles that cover it exactly: the
      // surface is unchanged whether that face is a patch face or a kept one
      // (a loop edge, when the apex is a loop vertex on a straight crease).
      // The two faces carry the flag of the face across, whose area they
      // cover.
      const auto across = sm->opposite(longest);
      if (sm->is_border(across)) continue;
      const auto u = sm->target(sm->next(longest)), w = sm->target(sm->next(across));
      if (u == w) continue;
      const uint8_t flag = filled[sm->face(across)];
      if (CGAL::halfedge(u, w, *sm).second) {
        // The flip's edge is there already: an end x of the longest edge has
        // valence 3, its third face x w u. That face lies in the plane of
        // the face across (u is on the line of the longest edge) and folds
        // back over it; removing x leaves the one triangle (u, other end, w)
        // the three faces amount to, the same surface.
        for (const auto into : {longest, across}) {
          const auto x = sm->target(into);
          if (CGAL::degree(x, *sm) != 3 || sm->is_border(x)) continue;
          filled[sm->face(CGAL::Euler::remove_center_vertex(into, *sm))] = flag;
          removed = changed = true;
          break;
        }
        continue;
      }
      CGAL::Euler::flip_edge(longest, *sm);
      filled[sm->face(longest)] = flag;
      filled[sm->face(sm->opposite(longest))] = flag;
      changed = true;
    }
    if (!changed) break;
  }
  if (removed) sm->collect_garbage();
}

}  // namespace meshseg::reconstruct_internal
