#include "reconstruct/isotropic_steps.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <numbers>

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

const double kMinFoldCos = std::cos(kMaxFoldDeg * std::numbers::pi / 180.0);
// A face whose area falls below this fraction of target² counts as
// collapsed (no operation may make one).
constexpr double kMinAreaFraction = 1e-6;

Eigen::Vector3d P(const TriMesh& m, TriMesh::VertexHandle v) { return ToEigen(m.point(v)); }

// Twice the area vector of triangle abc.
Eigen::Vector3d Cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a);
}

// True if moving `moved` to `to` keeps every face around it (except those
// also holding `other`, which the collapse removes) unfolded and non-flat.
bool FacesStayUpright(const TriMesh& m, TriMesh::VertexHandle moved, TriMesh::VertexHandle other,
                      const Eigen::Vector3d& to, double min_area2) {
  for (const auto f : m.vf_range(moved)) {
    Eigen::Vector3d before[3], after[3];
    int i = 0;
    bool holds_other = false;
    for (const auto v : m.fv_range(f)) {
      holds_other |= v == other;
      before[i] = P(m, v);
      after[i] = v == moved || v == other ? to : before[i];
      ++i;
    }
    if (holds_other) continue;
    const Eigen::Vector3d n0 = Cross(before[0], before[1], before[2]);
    const Eigen::Vector3d n1 = Cross(after[0], after[1], after[2]);
    if (n1.squaredNorm() <= min_area2) return false;
    if (n0.squaredNorm() > 0.0 && n0.dot(n1) < kMinFoldCos * n0.norm() * n1.norm()) return false;
  }
  return true;
}

// True if no neighbour of a or b lies farther than `max_length` from `at`.
bool NoLongEdge(const TriMesh& m, TriMesh::VertexHandle a, TriMesh::VertexHandle b,
                const Eigen::Vector3d& at, double max_length) {
  for (const auto v : {a, b}) {
    for (const auto w : m.vv_range(v)) {
      if ((P(m, w) - at).squaredNorm() > max_length * max_length) return false;
    }
  }
  return true;
}

int Deviation(int valence) { return (valence - 6) * (valence - 6); }

}  // namespace

int64_t SplitLongEdges(double target, TriMesh* mesh) {
  const double max_length = (4.0 / 3.0) * target;
  const auto length = [&](TriMesh::EdgeHandle e) {
    const auto h = mesh->halfedge_handle(e, 0);
    return (P(*mesh, mesh->from_vertex_handle(h)) - P(*mesh, mesh->to_vertex_handle(h))).norm();
  };
  int64_t splits = 0;
  // Longest first, in passes (Rivara's longest-edge bisection, which ends):
  // splitting in edge order instead cascaded around the fans of the
  // marching-tetrahedra mesh, each split making a new spoke as long as the fan.
  for (;;) {
    std::vector<std::pair<double, int>> long_edges;
    for (const auto e : mesh->edges()) {
      if (mesh->status(e).deleted()) continue;
      const double l = length(e);
      if (l > max_length) long_edges.emplace_back(l, e.idx());
    }
    if (long_edges.empty()) return splits;
    std::sort(long_edges.begin(), long_edges.end(), std::greater<>());
    for (const auto& [unused, index] : long_edges) {
      const TriMesh::EdgeHandle e(index);
      if (length(e) <= max_length) continue;
      const auto h = mesh->halfedge_handle(e, 0);
      const Eigen::Vector3d mid =
          0.5 * (P(*mesh, mesh->from_vertex_handle(h)) + P(*mesh, mesh->to_vertex_handle(h)));
      mesh->split(e, TriMesh::Point(mid.x(), mid.y(), mid.z()));
      ++splits;
    }
  }
}

int64_t CollapseShortEdges(double target, TriMesh* mesh) {
  const double min2 = (4.0 / 5.0) * target * (4.0 / 5.0) * target;
  const double max_length = (4.0 / 3.0) * target;
  const double min_area2 = 4.0 * std::pow(kMinAreaFraction * target * target, 2);
  int64_t collapses = 0;
  for (size_t i = 0; i < mesh->n_edges(); ++i) {
    const TriMesh::EdgeHandle e(static_cast<int>(i));
    if (mesh->status(e).deleted()) continue;
    for (int side = 0; side < 2; ++side) {
      const auto h = mesh->halfedge_handle(e, side);
      const auto from = mesh->from_vertex_handle(h);
      const auto to = mesh->to_vertex_handle(h);
      const Eigen::Vector3d a = P(*mesh, from), b = P(*mesh, to);
      if ((a - b).squaredNorm() >= min2) break;
      const Eigen::Vector3d mid = 0.5 * (a + b);
      if (!mesh->is_collapse_ok(h) || !NoLongEdge(*mesh, from, to, mid, max_length) ||
          !FacesStayUpright(*mesh, from, to, mid, min_area2) ||
          !FacesStayUpright(*mesh, to, from, mid, min_area2)) {
        continue;
      }
      mesh->set_point(to, TriMesh::Point(mid.x(), mid.y(), mid.z()));
      mesh->collapse(h);
      ++collapses;
      break;
    }
  }
  return collapses;
}

int64_t EqualizeValences(TriMesh* mesh) {
  int64_t flips = 0;
  for (const auto e : mesh->edges()) {
    if (mesh->status(e).deleted() || !mesh->is_flip_ok(e)) continue;
    const auto h0 = mesh->halfedge_handle(e, 0);
    const auto h1 = mesh->halfedge_handle(e, 1);
    const auto a = mesh->to_vertex_handle(h0), b = mesh->to_vertex_handle(h1);
    const auto c = mesh->to_vertex_handle(mesh->next_halfedge_handle(h0));
    const auto d = mesh->to_vertex_handle(mesh->next_halfedge_handle(h1));
    const int va = static_cast<int>(mesh->valence(a)), vb = static_cast<int>(mesh->valence(b));
    const int vc = static_cast<int>(mesh->valence(c)), vd = static_cast<int>(mesh->valence(d));
    const int before = Deviation(va) + Deviation(vb) + Deviation(vc) + Deviation(vd);
    const int after = Deviation(va - 1) + Deviation(vb - 1) + Deviation(vc + 1) + Deviation(vd + 1);
    if (after >= before || va <= 3 || vb <= 3) continue;
    // Faces (b, a, c) and (a, b, d) around the quad (a, c, b, d) become
    // (a, c, d) and (c, b, d); these must face the way the old pair did.
    const Eigen::Vector3d pa = P(*mesh, a), pb = P(*mesh, b), pc = P(*mesh, c), pd = P(*mesh, d);
    const Eigen::Vector3d n0 = Cross(pb, pa, pc), n1 = Cross(pa, pb, pd);
    if (n0.dot(n1) < kMinFoldCos * n0.norm() * n1.norm()) continue;  // a crease
    const Eigen::Vector3d m0 = Cross(pa, pc, pd), m1 = Cross(pc, pb, pd);
    const Eigen::Vector3d n = n0 + n1;
    if (m0.dot(n) < kMinFoldCos * m0.norm() * n.norm() ||
        m1.dot(n) < kMinFoldCos * m1.norm() * n.norm() || m0.squaredNorm() <= 0.0 ||
        m1.squaredNorm() <= 0.0) {
      continue;
    }
    mesh->flip(e);
    ++flips;
  }
  return flips;
}

void RelaxTangentially(TriMesh* mesh) {
  const size_t n = mesh->n_vertices();
  std::vector<Eigen::Vector3d> next(n);
  tbb::parallel_for(size_t{0}, n, [&](size_t i) {
    const TriMesh::VertexHandle v(static_cast<int>(i));
    next[i] = P(*mesh, v);
    if (mesh->status(v).deleted()) return;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int count = 0;
    for (const auto f : mesh->vf_range(v)) {
      Eigen::Vector3d c[3];
      int k = 0;
      for (const auto w : mesh->fv_range(f)) c[k++] = P(*mesh, w);
      normal += Cross(c[0], c[1], c[2]);
    }
    for (const auto w : mesh->vv_range(v)) {
      mean += P(*mesh, w);
      ++count;
    }
    if (count == 0 || normal.squaredNorm() == 0.0) return;
    normal.normalize();
    const Eigen::Vector3d move = mean / count - next[i];
    next[i] += move - normal.dot(move) * normal;
  });
  for (size_t i = 0; i < n; ++i) {
    mesh->set_point(TriMesh::VertexHandle(static_cast<int>(i)),
                    TriMesh::Point(next[i].x(), next[i].y(), next[i].z()));
  }
}

}  // namespace meshseg::reconstruct_internal
