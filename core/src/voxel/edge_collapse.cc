// CollapseEdges(): quadric edge collapse over a heap with lazy deletion (see
// edge_collapse.h). Each edge remembers its one live heap entry (cost and
// direction); a collapse that moves one of its ends, merges it or deletes it
// clears that, so older entries are recognised as stale when popped and each
// cost is computed once per change of an end instead of once per change
// anywhere in the one-ring.
#include "voxel/edge_collapse.h"

#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "voxel/entry_heap.h"

namespace meshseg::voxel_internal {
namespace {

enum Kind : uint8_t { kFree = 0, kCrease = 1, kLocked = 2 };

using HalfedgeHandle = TriMesh::HalfedgeHandle;
using VertexHandle = TriMesh::VertexHandle;

constexpr double kLaneKeep = 1.5;  // see Collapser::Run
constexpr uint8_t kBand = 0xff;    // lane_ of a vertex between the lanes

// One collapse loop's own state. Its edges are those whose two ends are
// both in the lane (lane_ == id).
struct Lane {
  uint8_t id = 0;
  EntryHeap heap;
  std::vector<int> was_crease;  // scratch of Collapse()
  size_t edges = 0;             // live edges of the lane at the start
  size_t removed = 0;           // faces removed so far
};

class Collapser {
 public:
  Collapser(TriMesh& mesh, const CollapseParams& params, std::span<const uint8_t> locked,
            std::span<const uint8_t> crease)
      : m_(mesh), params_(params) {
    kind_.assign(m_.n_vertices(), kFree);
    current_.assign(m_.n_edges(), kNoEntry);
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
    const size_t start = m_.n_faces();
    const size_t target = std::min(params_.target_faces, start);
    size_t faces = start;
    lane_.assign(m_.n_vertices(), 0);
    if (start >= params_.two_lanes_min_faces) {
      // Two lanes collapse their halves of the mesh at once; the band of
      // vertices between them waits for the whole-mesh pass below.
      const std::array<size_t, 2> lane_faces = AssignLanes();
      std::array<Lane, 2> lanes;
      std::array<absl::Status, 2> status;
      for (int i = 0; i < 2; ++i) {
        lanes[i].id = static_cast<uint8_t>(i);
        PushAll(lanes[i]);  // before either lane changes the mesh
      }
      // Each half keeps kLaneKeep times the share asked of the whole; the
      // last collapses are chosen across the whole mesh, cheapest first, so
      // neither half is forced beyond what its surface allows.
      const double keep =
          std::min(1.0, kLaneKeep * static_cast<double>(target) / static_cast<double>(start));
      const auto run = [&](int i, double span) {
        const size_t budget =
            lane_faces[i] - static_cast<size_t>(std::llround(keep * lane_faces[i]));
        status[i] = Loop(lanes[i], budget, 0.0, span, ctx);
      };
      // Lane 1 as a task, lane 0 on the calling thread, which alone may
      // report progress (RunContext).
      tbb::task_group group;
      group.run([&] { run(1, 0.0); });
      run(0, 0.8);
      group.wait();
      for (int i = 0; i < 2; ++i) {
        MESHSEG_RETURN_IF_ERROR(status[i]);
        faces -= lanes[i].removed;
      }
      std::fill(lane_.begin(), lane_.end(), 0);
    }
    Lane whole;
    PushAll(whole);
    const double before = faces < start ? 0.8 : 0.0;
    return Loop(whole, faces > target ? faces - target : 0, before, 0.9 - before, ctx);
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

  // Collapses the lane's edges (pushed by PushAll) in order of cost until
  // `budget` faces are gone or no legal collapse is left; reports progress
  // from `from` over `span` of the whole, unless span is 0.
  absl::Status Loop(Lane& lane, size_t budget, double from, double span, const RunContext& ctx) {
    size_t done = 0;
    while (!lane.heap.empty() && lane.removed < budget) {
      const Entry top = lane.heap.top();
      lane.heap.Pop();
      Entry& current = current_[top.halfedge / 2];
      if (current != top) {
        // Most popped entries are stale (a collapse invalidates about a
        // dozen); when they outnumber the live edges, drop them all at once.
        if (lane.heap.size() > 2 * (lane.edges - std::min(lane.edges, 3 * done))) {
          lane.heap.Purge([&](const Entry& e) { return current_[e.halfedge / 2] != e; });
        }
        continue;
      }
      current = kNoEntry;  // popped: pushed again when an end changes
      const HalfedgeHandle h(top.halfedge);
      const Eigen::Vector3d x = Placement(h);
      if (!m_.is_collapse_ok(h) || !NormalsKept(h, x)) continue;
      lane.removed += m_.is_boundary(m_.edge_handle(h)) ? 1 : 2;
      Collapse(lane, h, x);
      if (++done % 4096 == 0) {
        if (ctx.stop_requested()) return absl::CancelledError("simplify: stopped");
        if (span > 0.0) {
          ctx.Progress("simplify", from + span * static_cast<double>(lane.removed) /
                                              std::max<double>(1.0, budget));
        }
      }
    }
    return absl::OkStatus();
  }

  // Splits the vertices in two lanes at the median along the longest side of
  // the bounding box; a vertex with a neighbour across the cut joins the
  // band (kBand). No band vertex then neighbours both lanes, and a collapse
  // within a lane only links its vertices to ones it already neighbours, so
  // the two lanes never touch the same vertex, edge or face and may run at
  // once. Returns each lane's faces (those with a vertex of the lane).
  std::array<size_t, 2> AssignLanes() {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
    for (auto v : m_.vertices()) {
      const Eigen::Vector3d p = ToEigen(m_.point(v));
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    std::vector<double> coordinate(m_.n_vertices());
    for (auto v : m_.vertices()) coordinate[v.idx()] = m_.point(v)[axis];
    std::vector<double> sorted = coordinate;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double cut = sorted[sorted.size() / 2];
    for (size_t v = 0; v < coordinate.size(); ++v) lane_[v] = coordinate[v] < cut ? 0 : 1;
    std::vector<uint8_t> band(m_.n_vertices(), 0);
    for (auto e : m_.edges()) {
      const HalfedgeHandle h = m_.halfedge_handle(e, 0);
      const int a = m_.from_vertex_handle(h).idx(), b = m_.to_vertex_handle(h).idx();
      if (lane_[a] != lane_[b]) band[a] = band[b] = 1;
    }
    for (size_t v = 0; v < band.size(); ++v) {
      if (band[v]) lane_[v] = kBand;
    }
    std::array<size_t, 2> faces{0, 0};
    for (auto f : m_.faces()) {
      for (auto v : m_.fv_range(f)) {
        if (lane_[v.idx()] != kBand) {
          ++faces[lane_[v.idx()]];
          break;
        }
      }
    }
    return faces;
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

  // Where the kept vertex goes when h collapses; q is the sum of both ends'
  // quadrics.
  Eigen::Vector3d Placement(HalfedgeHandle h, const Quadric& q) const {
    const VertexHandle v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
    const Eigen::Vector3d p0 = ToEigen(m_.point(v0)), p1 = ToEigen(m_.point(v1));
    if (kind_[v1.idx()] == kLocked) return p1;
    if (kind_[v0.idx()] == kFree && kind_[v1.idx()] == kCrease) return p1;
    return kind_[v0.idx()] == kCrease ? OnSegment(q, p0, p1) : Optimum(q, p0, p1);
  }
  Eigen::Vector3d Placement(HalfedgeHandle h) const {
    Quadric q = quadric_[m_.from_vertex_handle(h).idx()];
    q += quadric_[m_.to_vertex_handle(h).idx()];
    return Placement(h, q);
  }

  // The cost of collapsing h, or nothing when illegal or over the bound.
  std::optional<float> Cost(HalfedgeHandle h, const Quadric& q) const {
    if (!Legal(h)) return std::nullopt;
    const double error = q.Error(Placement(h, q));
    if (params_.max_error > 0.0 && q.area > 0.0 &&
        error > params_.max_error * params_.max_error * q.area) {
      return std::nullopt;
    }
    return static_cast<float>(error);
  }

  // The heap entry of e: its cheaper legal direction. Between two free
  // vertices both directions place the kept vertex at the same optimum of
  // the same quadric (Optimum() and OnSegment() are symmetric in the ends),
  // so one evaluation serves both.
  Entry Best(TriMesh::EdgeHandle e) const {
    const HalfedgeHandle h0 = m_.halfedge_handle(e, 0);
    Quadric q = quadric_[m_.from_vertex_handle(h0).idx()];
    q += quadric_[m_.to_vertex_handle(h0).idx()];
    const bool both_free = kind_[m_.from_vertex_handle(h0).idx()] == kFree &&
                           kind_[m_.to_vertex_handle(h0).idx()] == kFree;
    Entry best = kNoEntry;
    for (int i = 0; i < (both_free ? 1 : 2); ++i) {
      const HalfedgeHandle h = m_.halfedge_handle(e, i);
      const std::optional<float> c = Cost(h, q);
      if (c && (best.halfedge < 0 || *c < best.cost)) best = {*c, h.idx()};
    }
    return best;
  }

  // Whether the lane owns e: both ends are its vertices.
  bool Owns(const Lane& lane, TriMesh::EdgeHandle e) const {
    const HalfedgeHandle h = m_.halfedge_handle(e, 0);
    return lane_[m_.from_vertex_handle(h).idx()] == lane.id &&
           lane_[m_.to_vertex_handle(h).idx()] == lane.id;
  }

  void Push(Lane& lane, TriMesh::EdgeHandle e) {
    if (!Owns(lane, e)) return;
    const Entry best = Best(e);
    current_[e.idx()] = best;
    if (best.halfedge >= 0) lane.heap.Push(best);
  }

  // The entries of the lane's live edges, evaluated on all cores, then
  // heaped in linear time.
  void PushAll(Lane& lane) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, m_.n_edges()),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i < r.end(); ++i) {
                          const TriMesh::EdgeHandle e(static_cast<int>(i));
                          if (!m_.status(e).deleted() && Owns(lane, e)) current_[i] = Best(e);
                        }
                      });
    std::vector<Entry> entries;
    for (size_t i = 0; i < current_.size(); ++i) {
      const TriMesh::EdgeHandle e(static_cast<int>(i));
      if (m_.status(e).deleted() || !Owns(lane, e)) continue;
      ++lane.edges;
      if (current_[i].halfedge >= 0) entries.push_back(current_[i]);
    }
    lane.heap.Reserve(2 * entries.size());
    lane.heap.Assign(entries);
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
  void Collapse(Lane& lane, HalfedgeHandle h, const Eigen::Vector3d& x) {
    const VertexHandle v0 = m_.from_vertex_handle(h), v1 = m_.to_vertex_handle(h);
    std::vector<int>& was_crease = lane.was_crease;
    was_crease.clear();
    for (const VertexHandle vh : {v0, v1}) {
      for (auto oh : m_.voh_range(vh)) {
        const int e = m_.edge_handle(oh).idx();
        current_[e] = kNoEntry;  // merged, deleted or re-pushed below
        if (crease_[e]) was_crease.push_back(m_.to_vertex_handle(oh).idx());
      }
    }
    m_.set_point(v1, TriMesh::Point(x.x(), x.y(), x.z()));
    m_.collapse(h);
    quadric_[v1.idx()] += quadric_[v0.idx()];
    for (auto oh : m_.voh_range(v1)) {
      const int w = m_.to_vertex_handle(oh).idx();
      crease_[m_.edge_handle(oh).idx()] =
          std::find(was_crease.begin(), was_crease.end(), w) != was_crease.end();
    }
    for (auto e : m_.ve_range(v1)) Push(lane, e);
  }

  TriMesh& m_;
  const CollapseParams params_;
  std::vector<uint8_t> kind_;
  std::vector<Entry> current_;  // each edge's live heap entry (or kNoEntry)
  std::vector<uint8_t> crease_;
  std::vector<Quadric> quadric_;
  std::vector<uint8_t> lane_;  // per vertex: its lane, or kBand
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
