// CollapseEdges(): quadric edge collapse over a heap with lazy deletion (see
// edge_collapse.h). An edge's stamp changes whenever a collapse moves one of
// its ends, merges it or deletes it; a heap entry remembers the stamp it was
// pushed with and is stale once it differs, so each cost is computed once
// per change of an end instead of once per change anywhere in the one-ring.
#include "voxel/edge_collapse.h"

#include <cmath>
#include <optional>
#include <utility>

#include "absl/strings/str_cat.h"

namespace meshseg::voxel_internal {
namespace {

enum Kind : uint8_t { kFree = 0, kCrease = 1, kLocked = 2 };

using HalfedgeHandle = TriMesh::HalfedgeHandle;
using VertexHandle = TriMesh::VertexHandle;

struct Entry {
  float cost;
  int halfedge;    // v0 = from (removed), v1 = to (kept)
  uint32_t stamp;  // the edge's stamp when pushed
  uint32_t pad;    // to 16 bytes: four children per cache line
};

// A 4-ary min-heap of 16-byte entries: a node's four children share one
// 64-byte cache line, so a pop from a heap of millions misses the cache
// about half as often as a binary heap's would.
class EntryHeap {
 public:
  bool empty() const { return items_.empty(); }
  size_t size() const { return items_.size(); }
  const Entry& top() const { return items_.front(); }
  void Reserve(size_t n) { items_.reserve(n); }
  // Drops the entries `stale` says are stale and rebuilds the heap order
  // bottom-up (linear time).
  template <typename Stale>
  void Purge(Stale stale) {
    std::erase_if(items_, stale);
    for (size_t i = items_.size(); i-- > 0;) SiftDown(i, items_[i]);
  }
  void Push(const Entry& e) {
    size_t i = items_.size();
    items_.push_back(e);
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!(e.cost < items_[parent].cost)) break;
      items_[i] = items_[parent];
      i = parent;
    }
    items_[i] = e;
  }
  void Pop() {
    const Entry last = items_.back();
    items_.pop_back();
    if (!items_.empty()) SiftDown(0, last);
  }

 private:
  // Places e at or below slot i.
  void SiftDown(size_t i, const Entry e) {
    const size_t n = items_.size();
    while (true) {
      const size_t first = 4 * i + 1;
      if (first >= n) break;
      size_t best = first;
      const size_t end = std::min(first + 4, n);
      for (size_t c = first + 1; c < end; ++c) {
        if (items_[c].cost < items_[best].cost) best = c;
      }
      if (!(items_[best].cost < e.cost)) break;
      items_[i] = items_[best];
      i = best;
    }
    items_[i] = e;
  }

  std::vector<Entry> items_;
};

// argmin q over space if A is well conditioned (determinant against the cube
// of its trace) and the optimum is near the edge, else over the segment.
Eigen::Vector3d OnSegment(const Quadric& q, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) {
  const Eigen::Vector3d d = p1 - p0;
  const double dad = d.dot(q.a * d);
  double t = 0.5;
  if (dad > 0.0) t = std::clamp(-(d.dot(q.a * p0) + q.b.dot(d)) / dad, 0.0, 1.0);
  return p0 + t * d;
}

Eigen::Vector3d Optimum(const Quadric& q, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) {
  const double trace = q.a.trace();
  const double det = q.a.determinant();
  if (trace > 0.0 && det > 1e-6 * trace * trace * trace) {
    const Eigen::Vector3d x = -(q.a.inverse() * q.b);
    // Stay near the edge: an optimum far off it is a conditioning artefact.
    if ((x - 0.5 * (p0 + p1)).squaredNorm() <= 4.0 * (p1 - p0).squaredNorm()) return x;
  }
  return OnSegment(q, p0, p1);
}

class Collapser {
 public:
  Collapser(TriMesh& mesh, const CollapseParams& params, std::span<const uint8_t> locked,
            std::span<const uint8_t> crease)
      : m_(mesh), params_(params) {
    kind_.assign(m_.n_vertices(), kFree);
    stamp_.assign(m_.n_edges(), 0);
    crease_.assign(m_.n_edges(), 0);
    if (!crease.empty()) std::copy(crease.begin(), crease.end(), crease_.begin());
    for (auto e : m_.edges()) {
      if (!crease_[e.idx()]) continue;
      for (int i = 0; i < 2; ++i)
        kind_[m_.to_vertex_handle(m_.halfedge_handle(e, i)).idx()] = kCrease;
    }
    for (size_t v = 0; v < kind_.size(); ++v) {
      if (!locked.empty() && locked[v]) kind_[v] = kLocked;
    }
    InitQuadrics();
  }

  const std::vector<uint8_t>& crease() const { return crease_; }

  absl::Status Run(const RunContext& ctx) {
    heap_.Reserve(2 * m_.n_edges());
    for (auto e : m_.edges()) Push(e);
    size_t faces = m_.n_faces();
    const size_t start = faces;
    size_t done = 0;
    while (!heap_.empty() && faces > params_.target_faces) {
      const Entry top = heap_.top();
      heap_.Pop();
      if (stamp_[top.halfedge / 2] != top.stamp) {
        // Most popped entries are stale (a collapse invalidates about a
        // dozen); when they outnumber the edges, drop them all at once.
        if (heap_.size() > 2 * m_.n_edges() - 2 * 3 * done) {
          heap_.Purge([&](const Entry& e) { return stamp_[e.halfedge / 2] != e.stamp; });
        }
        continue;
      }
      const HalfedgeHandle h(top.halfedge);
      const Eigen::Vector3d x = Placement(h);
      if (!m_.is_collapse_ok(h) || !NormalsKept(h, x)) continue;
      faces -= m_.is_boundary(m_.edge_handle(h)) ? 1 : 2;
      Collapse(h, x);
      if (++done % 4096 == 0) {
        if (ctx.stop_requested()) return absl::CancelledError("simplify: stopped");
        ctx.Progress("simplify", 0.9 * static_cast<double>(start - faces) /
                                     std::max<double>(1.0, start - params_.target_faces));
      }
    }
    return absl::OkStatus();
  }

 private:
  void InitQuadrics() {
    quadric_.assign(m_.n_vertices(), Quadric{});
    for (auto f : m_.faces()) {
      auto it = m_.cfv_iter(f);
      const VertexHandle a = *it++, b = *it++, c = *it;
      const Eigen::Vector3d p0 = ToEigen(m_.point(a)), p1 = ToEigen(m_.point(b)),
                            p2 = ToEigen(m_.point(c));
      Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
      const double twice_area = n.norm();
      if (twice_area == 0.0) continue;
      n /= twice_area;
      Quadric q;
      q.AddPlane(n, -n.dot(p0), 0.5 * twice_area);
      quadric_[a.idx()] += q;
      quadric_[b.idx()] += q;
      quadric_[c.idx()] += q;
    }
    // Garland and Heckbert's constraint planes: through each crease or
    // border edge, perpendicular to each of its faces, weighted like the
    // face. They price moving the line sideways within the surface, which
    // the face planes alone do not (a flat border's corner would slide).
    for (auto e : m_.edges()) {
      if (!crease_[e.idx()]) continue;
      if (!params_.interior_crease_planes && !m_.is_boundary(e)) continue;
      for (int i = 0; i < 2; ++i) {
        const auto h = m_.halfedge_handle(e, i);
        const auto f = m_.face_handle(h);
        if (!f.is_valid()) continue;
        const Eigen::Vector3d p0 = ToEigen(m_.point(m_.from_vertex_handle(h)));
        const Eigen::Vector3d p1 = ToEigen(m_.point(m_.to_vertex_handle(h)));
        const Eigen::Vector3d p2 =
            ToEigen(m_.point(m_.to_vertex_handle(m_.next_halfedge_handle(h))));
        const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
        Eigen::Vector3d side = (p1 - p0).cross(n);
        const double length = side.norm();
        if (length == 0.0) continue;
        side /= length;
        Quadric q;
        q.AddPlane(side, -side.dot(p0), 0.5 * n.norm());
        q.area = 0.0;  // a constraint, not surface: the rms bound is per area
        quadric_[m_.from_vertex_handle(h).idx()] += q;
        quadric_[m_.to_vertex_handle(h).idx()] += q;
      }
    }
  }

  bool Legal(HalfedgeHandle h) const {
    const Kind k0 = static_cast<Kind>(kind_[m_.from_vertex_handle(h).idx()]);
    if (k0 == kLocked) return false;
    if (k0 == kCrease) {
      // Along its own line onto a crease or locked vertex only.
      return crease_[m_.edge_handle(h).idx()] != 0;
    }
    return true;
  }

  Eigen::Vector3d Placement(HalfedgeHandle h) const {
    const VertexHandle v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
    const Eigen::Vector3d p0 = ToEigen(m_.point(v0)), p1 = ToEigen(m_.point(v1));
    if (kind_[v1.idx()] == kLocked) return p1;
    if (kind_[v0.idx()] == kFree && kind_[v1.idx()] == kCrease) return p1;
    Quadric q = quadric_[v0.idx()];
    q += quadric_[v1.idx()];
    return kind_[v0.idx()] == kCrease ? OnSegment(q, p0, p1) : Optimum(q, p0, p1);
  }

  // The cost of collapsing h, or nothing when illegal or over the bound.
  std::optional<float> Cost(HalfedgeHandle h) const {
    if (!Legal(h)) return std::nullopt;
    Quadric q = quadric_[m_.from_vertex_handle(h).idx()];
    q += quadric_[m_.to_vertex_handle(h).idx()];
    const double error = q.Error(Placement(h));
    if (params_.max_error > 0.0 && q.area > 0.0 &&
        error > params_.max_error * params_.max_error * q.area) {
      return std::nullopt;
    }
    return static_cast<float>(error);
  }

  void Push(TriMesh::EdgeHandle e) {
    std::optional<float> best;
    HalfedgeHandle best_h;
    for (int i = 0; i < 2; ++i) {
      const HalfedgeHandle h = m_.halfedge_handle(e, i);
      const std::optional<float> c = Cost(h);
      if (c && (!best || *c < *best)) best = c, best_h = h;
    }
    if (!best) return;
    heap_.Push({*best, best_h.idx(), stamp_[e.idx()], 0});
  }

  // No face around v0 or v1 that survives the collapse turns by more than
  // the limit or loses almost all its area when the merged vertex goes to x.
  bool NormalsKept(HalfedgeHandle h, const Eigen::Vector3d& x) const {
    const VertexHandle v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
    const auto fl = m_.face_handle(h), fr = m_.face_handle(m_.opposite_halfedge_handle(h));
    for (const VertexHandle vh : {v0, v1}) {
      for (auto f : m_.vf_range(vh)) {
        if (f == fl || f == fr) continue;
        Eigen::Vector3d p[3], q[3];
        int c = 0;
        for (auto v : m_.fv_range(f)) {
          p[c] = ToEigen(m_.point(v));
          q[c] = (v == v0 || v == v1) ? x : p[c];
          ++c;
        }
        const Eigen::Vector3d n0 = (p[1] - p[0]).cross(p[2] - p[0]);
        const Eigen::Vector3d n1 = (q[1] - q[0]).cross(q[2] - q[0]);
        const double l0 = n0.norm(), l1 = n1.norm();
        if (l0 == 0.0) continue;
        if (l1 <= 1e-8 * l0) return false;
        if (n0.dot(n1) < params_.min_cos_normal * l0 * l1) return false;
      }
    }
    return true;
  }

  // Collapses h with the kept vertex at x; the crease flags of the edges
  // that merge are or-ed (an edge v1-w is a crease if v0-w or v1-w was).
  void Collapse(HalfedgeHandle h, const Eigen::Vector3d& x) {
    const VertexHandle v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
    was_crease_.clear();
    for (const VertexHandle vh : {v0, v1}) {
      for (auto oh : m_.voh_range(vh)) {
        const int e = m_.edge_handle(oh).idx();
        ++stamp_[e];  // merged, deleted or re-pushed below
        if (crease_[e]) was_crease_.push_back(m_.to_vertex_handle(oh).idx());
      }
    }
    m_.set_point(v1, TriMesh::Point(x.x(), x.y(), x.z()));
    m_.collapse(h);
    quadric_[v1.idx()] += quadric_[v0.idx()];
    for (auto oh : m_.voh_range(v1)) {
      const int w = m_.to_vertex_handle(oh).idx();
      crease_[m_.edge_handle(oh).idx()] =
          std::find(was_crease_.begin(), was_crease_.end(), w) != was_crease_.end();
    }
    for (auto e : m_.ve_range(v1)) Push(e);
  }

  TriMesh& m_;
  const CollapseParams params_;
  std::vector<uint8_t> kind_;
  std::vector<uint32_t> stamp_;
  std::vector<uint8_t> crease_;
  std::vector<Quadric> quadric_;
  std::vector<int> was_crease_;
  EntryHeap heap_;
};

}  // namespace

absl::Status CollapseEdges(TriMesh& mesh, const CollapseParams& params,
                           std::span<const uint8_t> locked, std::span<const uint8_t> crease,
                           const RunContext& ctx, std::vector<uint8_t>* crease_after) {
  if (!locked.empty() && locked.size() != mesh.n_vertices()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "simplify: ", locked.size(), " vertex flags for ", mesh.n_vertices(), " vertices"));
  }
  if (!crease.empty() && crease.size() != mesh.n_edges()) {
    return absl::InvalidArgumentError(
        absl::StrCat("simplify: ", crease.size(), " crease flags for ", mesh.n_edges(), " edges"));
  }
  Collapser collapser(mesh, params, locked, crease);
  const absl::Status status = collapser.Run(ctx);
  if (crease_after != nullptr) *crease_after = collapser.crease();
  return status;
}

}  // namespace meshseg::voxel_internal
