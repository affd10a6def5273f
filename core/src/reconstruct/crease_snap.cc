#include "reconstruct/crease_snap.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace meshseg::reconstruct_internal {
namespace {

// A move may shrink a triangle of the vertex to this fraction of its area,
// no further (a sliver is still a triangle; a collapsed one is not).
constexpr double kMinAreaKept = 1e-3;

// Whether moving `v` to `to` keeps every triangle around it facing the way
// the surface around v faces (the area-weighted mean normal of its triangles
// before the move) and not collapsed. A chord triangle turns by up to the
// crease angle as it goes into one of the planes: its own old normal is no
// reference, the one-ring's mean is.
bool MoveKeepsTriangles(const TriMesh& mesh, TriMesh::VertexHandle v, const Eigen::Vector3d& to) {
  const Eigen::Vector3d from = ToEigen(mesh.point(v));
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> fan;  // the other two corners
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (auto h = mesh.cvoh_iter(v); h.is_valid(); ++h) {
    if (mesh.is_boundary(*h)) continue;
    const Eigen::Vector3d b = ToEigen(mesh.point(mesh.to_vertex_handle(*h)));
    const Eigen::Vector3d c =
        ToEigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(*h))));
    mean += (b - from).cross(c - from);
    fan.emplace_back(b, c);
  }
  for (const auto& [b, c] : fan) {
    const Eigen::Vector3d before = (b - from).cross(c - from);
    const Eigen::Vector3d after = (b - to).cross(c - to);
    if (!(after.dot(mean) > 0) || !(after.norm() > kMinAreaKept * before.norm())) return false;
  }
  return true;
}

}  // namespace

CreaseSnap SnapToCreases(const std::vector<std::pair<int, Crease>>& creases, TriMesh* mesh) {
  std::vector<int> crease_of(mesh->n_vertices(), -1);
  for (size_t i = 0; i < creases.size(); ++i) crease_of[creases[i].first] = static_cast<int>(i);
  std::vector<uint8_t> on_line(mesh->n_vertices(), 0);
  CreaseSnap done;
  // Edges added by splits all end on the line: only the first ones cross.
  const int edge_count = static_cast<int>(mesh->n_edges());
  for (int ei = 0; ei < edge_count; ++ei) {
    const TriMesh::EdgeHandle e(ei);
    const auto h = mesh->halfedge_handle(e, 0);
    const TriMesh::VertexHandle ends[2] = {mesh->from_vertex_handle(h), mesh->to_vertex_handle(h)};
    const int c0 = crease_of[ends[0].idx()], c1 = crease_of[ends[1].idx()];
    if (on_line[ends[0].idx()] || on_line[ends[1].idx()]) continue;
    const Eigen::Vector3d p[2] = {ToEigen(mesh->point(ends[0])), ToEigen(mesh->point(ends[1]))};
    // The crease of an end, else of a neighbour of an end: a fit spans more
    // than an edge, and with noise a vertex a few spacings from the edge may
    // not tell two planes from one.
    const Crease* model = nullptr;
    const auto consider = [&](int c) {
      if (c >= 0 && !model && creases[c].second.Side(p[0]) != creases[c].second.Side(p[1])) {
        model = &creases[c].second;
      }
    };
    consider(c0);
    consider(c1);
    for (int k = 0; k < 2 && !model; ++k) {
      for (const auto n : mesh->vv_range(ends[k])) consider(crease_of[n.idx()]);
    }
    if (!model) continue;
    // Where the edge crosses the bisecting plane g0 = g1 of the crease.
    const double s0 = model->g(0, p[0]) - model->g(1, p[0]);
    const double s1 = model->g(0, p[1]) - model->g(1, p[1]);
    const double t = std::clamp(s0 / (s0 - s1), 0.0, 1.0);
    const int near = t < 0.5 ? 0 : 1;
    if (std::min(t, 1.0 - t) < kCreaseSnapFraction) {
      const int own_index = near == 0 ? c0 : c1;
      const Crease& own = own_index >= 0 ? creases[own_index].second : *model;
      const Eigen::Vector3d to = own.OntoLine(p[near]);
      if ((to - p[near]).squaredNorm() < (p[1] - p[0]).squaredNorm() &&
          MoveKeepsTriangles(*mesh, ends[near], to)) {
        mesh->set_point(ends[near], TriMesh::Point(to[0], to[1], to[2]));
        on_line[ends[near].idx()] = 1;
        ++done.moved;
        continue;
      }
    }
    // Split at the crossing (on the edge: no triangle folds), then onto the
    // line.
    const Eigen::Vector3d at = p[0] + t * (p[1] - p[0]);
    const TriMesh::VertexHandle mid = mesh->split(e, TriMesh::Point(at[0], at[1], at[2]));
    on_line.resize(mesh->n_vertices(), 0);
    crease_of.resize(mesh->n_vertices(), -1);
    on_line[mid.idx()] = 1;
    ++done.inserted;
    const Eigen::Vector3d to = model->OntoLine(at);
    if ((to - at).squaredNorm() < (p[1] - p[0]).squaredNorm() &&
        MoveKeepsTriangles(*mesh, mid, to)) {
      mesh->set_point(mid, TriMesh::Point(to[0], to[1], to[2]));
    }
  }
  return done;
}

int RemoveFlatTriangles(TriMesh* mesh) {
  // A few passes: a flip or collapse can leave a neighbour flat.
  constexpr int kPasses = 3;
  int changed = 0;
  for (int pass = 0; pass < kPasses; ++pass) {
    int this_pass = 0;
    for (const auto f : mesh->faces()) {
      if (mesh->status(f).deleted()) continue;
      TriMesh::HalfedgeHandle h[3];
      h[0] = mesh->halfedge_handle(f);
      h[1] = mesh->next_halfedge_handle(h[0]);
      h[2] = mesh->next_halfedge_handle(h[1]);
      double length[3];
      for (int k = 0; k < 3; ++k) length[k] = mesh->calc_edge_length(h[k]);
      const Eigen::Vector3d a = ToEigen(mesh->point(mesh->from_vertex_handle(h[0])));
      const Eigen::Vector3d b = ToEigen(mesh->point(mesh->from_vertex_handle(h[1])));
      const Eigen::Vector3d c = ToEigen(mesh->point(mesh->from_vertex_handle(h[2])));
      const int longest = static_cast<int>(std::max_element(length, length + 3) - length);
      const int shortest = static_cast<int>(std::min_element(length, length + 3) - length);
      const double l2 = length[longest] * length[longest];
      if ((b - a).cross(c - a).norm() > kFlatTriangle * l2) continue;
      const auto e = mesh->edge_handle(h[longest]);
      if (length[shortest] >= kNeedleEdge * length[longest] && !mesh->is_boundary(e) &&
          mesh->is_flip_ok(e)) {
        mesh->flip(e);
        ++this_pass;
        continue;
      }
      // A needle, or a cap whose flip would duplicate an edge: collapse.
      for (const auto hh : {h[shortest], mesh->opposite_halfedge_handle(h[shortest])}) {
        if (mesh->is_collapse_ok(hh)) {
          mesh->collapse(hh);
          ++this_pass;
          break;
        }
      }
    }
    changed += this_pass;
    if (this_pass == 0) break;
  }
  if (changed > 0) mesh->garbage_collection();
  return changed;
}

}  // namespace meshseg::reconstruct_internal
