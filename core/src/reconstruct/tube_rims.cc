#include "reconstruct/tube_rims.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include "mesh/union_find.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

using Sm = HoleMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

// The rings inside a rim (in edges) whose normals give its curvature and
// its normal: past the extrapolated faces next to the border, within the
// seen surface's run.
constexpr int kNearRing = 3;
constexpr int kFarRing = 9;
// The ring halfway between: a section that curves turns its normal evenly
// from the near ring to the far one, a crease within reach at one place.
constexpr int kMidRing = (kNearRing + kFarRing) / 2;
// The outgoing direction at a loop vertex is averaged over this many loop
// vertices on either side: as far along the rim as the rings it comes from
// reach inwards (a scan's border zigzags from one edge to the next, and
// detail along the rim finer than the band the normals are read from is
// their noise).
constexpr int kDirectionWindow = kFarRing;
// A rim vertex's ring sums are pooled with this many neighbours on either
// side (one may own no vertex of a ring); a wider pool would draw the mean
// point of a ring towards the axis of a tight loop.
constexpr int kRingWindow = 2;

// The index `w` places from `k` round a loop of `n`.
size_t Around(size_t k, int w, size_t n) {
  const auto m = static_cast<long>(n);
  return static_cast<size_t>(((static_cast<long>(k) + w) % m + m) % m);
}

Eigen::Vector3d At(const Sm& sm, Sm::Vertex_index v) {
  const auto& p = sm.point(v);
  return {p.x(), p.y(), p.z()};
}

// The vertices of the border loop of `h`, in the order of the border.
std::vector<Sm::Vertex_index> LoopOf(const Sm& sm, Sm::Halfedge_index h) {
  std::vector<Sm::Vertex_index> loop;
  for (auto g = h;;) {
    loop.push_back(sm.target(g));
    g = sm.next(g);
    if (g == h) return loop;
  }
}

Eigen::Vector3d NormalAt(const Sm& sm, Sm::Vertex_index v) {
  const auto n = PMP::compute_vertex_normal(v, sm);
  return {n.x(), n.y(), n.z()};
}

}  // namespace


Rim RimOf(const HoleMesh& sm, HoleMesh::Halfedge_index h, double sign) {
  Rim rim;
  rim.loop = LoopOf(sm, h);
  const size_t n = rim.loop.size();
  // Rings inwards from the loop, each vertex owned by its nearest rim vertex.
  const size_t count = sm.num_vertices() + sm.number_of_removed_vertices();
  std::vector<int> ring(count, -1), owner(count, -1);
  std::vector<Sm::Vertex_index> front;
  for (size_t k = 0; k < n; ++k) {
    ring[rim.loop[k]] = 0;
    owner[rim.loop[k]] = static_cast<int>(k);
    front.push_back(rim.loop[k]);
  }
  // Per rim vertex and ring (near, far, mid): sums of the owned vertices'
  // normals and points, and their count.
  std::vector<std::array<Eigen::Vector3d, 3>> normal_sum(
      n, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  std::vector<std::array<Eigen::Vector3d, 3>> point_sum = normal_sum;
  std::vector<std::array<int, 3>> owned(n, {0, 0, 0});
  for (int r = 1; r <= kFarRing && !front.empty(); ++r) {
    std::vector<Sm::Vertex_index> next;
    for (const auto v : front) {
      for (const auto w : CGAL::vertices_around_target(sm.halfedge(v), sm)) {
        if (ring[w] >= 0) continue;
        ring[w] = r;
        owner[w] = owner[v];
        next.push_back(w);
        if (r != kNearRing && r != kFarRing && r != kMidRing) continue;
        const int which = r == kNearRing ? 0 : r == kFarRing ? 1 : 2;
        normal_sum[owner[w]][which] += NormalAt(sm, w);
        point_sum[owner[w]][which] += At(sm, w);
        ++owned[owner[w]][which];
      }
    }
    front = std::move(next);
  }
  std::vector<Eigen::Vector3d> raw(n, Eigen::Vector3d::Zero());
  double turn = 0.0, run = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d p = At(sm, rim.loop[k]);
    const Eigen::Vector3d along = At(sm, rim.loop[(k + 1) % n]) - At(sm, rim.loop[(k + n - 1) % n]);
    // Windowed sums: a rim vertex may own no vertex of a ring.
    Eigen::Vector3d n1 = Eigen::Vector3d::Zero(), n2 = n1, n3 = n1, p1 = n1, p2 = n1, p3 = n1;
    int c1 = 0, c2 = 0, c3 = 0;
    for (int w = -kRingWindow; w <= kRingWindow; ++w) {
      const size_t j = Around(k, w, n);
      n1 += normal_sum[j][0];
      p1 += point_sum[j][0];
      c1 += owned[j][0];
      n2 += normal_sum[j][1];
      p2 += point_sum[j][1];
      c2 += owned[j][1];
      n3 += normal_sum[j][2];
      p3 += point_sum[j][2];
      c3 += owned[j][2];
    }
    if (c1 == 0 || c2 == 0 || !(n1.norm() > 0) || !(n2.norm() > 0)) continue;
    p1 /= c1;
    p2 /= c2;
    n1.normalize();
    n2.normalize();
    const double span = (p1 - p2).norm(), rest = (p - p1).norm();
    if (!(span > 0)) continue;
    const Eigen::Vector3d axis = n2.cross(n1);
    const double angle = std::atan2(axis.norm(), n2.dot(n1));
    Eigen::Vector3d normal = n1;
    if (axis.norm() > 0) {
      normal = Eigen::AngleAxisd(angle * rest / span, axis.normalized()) * n1;
    }
    raw[k] = normal.cross(along).normalized();
    if (!raw[k].allFinite()) {
      raw[k].setZero();
      continue;
    }
    // Going out, the normal of a convex section turns towards the way out.
    // Only its turn about the rim's tangent is curvature across the border
    // (the rest is the rim's own bend along it, between the rings' owned
    // vertices).
    const Eigen::Vector3d tangent = normal.cross(raw[k]).normalized();
    const auto signed_turn = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
      const Eigen::Vector3d about = to.cross(from);
      const double by = std::atan2(about.norm(), to.dot(from));
      return about.norm() > 0 ? by * about.normalized().dot(tangent) : 0.0;
    };
    double rate = signed_turn(n1, n2) / span;
    // A section that curves turns as fast from the near ring to the middle
    // one as from there to the far one; a crease within reach (the rim of a
    // countersink above a bore's) turns it in one of the halves only. The
    // rate is the slower half's, so a crease does not read as curvature.
    if (c3 > 0 && n3.norm() > 0) {
      p3 /= c3;
      n3.normalize();
      const double near_span = (p1 - p3).norm(), far_span = (p3 - p2).norm();
      if (near_span > 0 && far_span > 0) {
        const double near_rate = signed_turn(n1, n3) / near_span;
        const double far_rate = signed_turn(n3, n2) / far_span;
        rate = std::abs(near_rate) <= std::abs(far_rate) ? near_rate : far_rate;
      }
    }
    turn += rate * span;
    run += span;
  }
  rim.curvature = run > 0 ? sign * turn / run : 0.0;
  // A rim vertex whose window owns no vertex of a ring (its neighbours
  // reached them first) takes the direction of the nearest one that does.
  std::vector<Eigen::Vector3d> filled = raw;
  for (size_t k = 0; k < n; ++k) {
    for (size_t step = 1; step <= n / 2 && filled[k].squaredNorm() == 0; ++step) {
      if (raw[(k + step) % n].squaredNorm() > 0) {
        filled[k] = raw[(k + step) % n];
      } else if (raw[(k + n - step) % n].squaredNorm() > 0) {
        filled[k] = raw[(k + n - step) % n];
      }
    }
  }
  raw = std::move(filled);
  rim.out.resize(n);
  for (size_t k = 0; k < n; ++k) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int w = -kDirectionWindow; w <= kDirectionWindow; ++w) sum += raw[Around(k, w, n)];
    rim.out[k] = sum.norm() > 0 ? Eigen::Vector3d(sum.normalized()) : sum;
  }
  return rim;
}

namespace {

// The mean |cosine| between the outgoing directions and the axis of the
// loop (the normal of its least-squares plane).
double LeavingCosine(const Sm& sm, Sm::Halfedge_index h) {
  const Rim rim = RimOf(sm, h, 1.0);
  const std::vector<Sm::Vertex_index>& loop = rim.loop;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto v : loop) mean += At(sm, v);
  mean /= static_cast<double>(loop.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto v : loop) cov += (At(sm, v) - mean) * (At(sm, v) - mean).transpose();
  const Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  double sum = 0.0;
  for (const Eigen::Vector3d& d : rim.out) sum += std::abs(d.dot(axis));
  return sum / static_cast<double>(loop.size());
}

double Perimeter(const Sm& sm, Sm::Halfedge_index h) {
  const std::vector<Sm::Vertex_index> loop = LoopOf(sm, h);
  double length = 0.0;
  for (size_t k = 0; k < loop.size(); ++k) {
    length += (At(sm, loop[(k + 1) % loop.size()]) - At(sm, loop[k])).norm();
  }
  return length;
}

}  // namespace

std::vector<int> FacePieces(const TriMesh& tri, const std::vector<uint8_t>& removed,
                            uint8_t side) {
  std::vector<int> parent(tri.n_faces());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto e : tri.edges()) {
    if (tri.is_boundary(e)) continue;
    const int f = tri.face_handle(tri.halfedge_handle(e, 0)).idx();
    const int g = tri.face_handle(tri.halfedge_handle(e, 1)).idx();
    if (removed[f] == side && removed[g] == side) parent[FindRoot(parent, f)] = FindRoot(parent, g);
  }
  return parent;
}

namespace {

// Per loop: its removed component (-1 where none) and whether it is a
// candidate rim, (b) and (c) of close_tube.h; per component, its candidates.
struct RimCandidates {
  std::vector<int> component;
  std::vector<uint8_t> candidate;
  std::vector<int> count;  // per face index of a component's root
};

RimCandidates CandidatesOf(const TriMesh& tri, const std::vector<uint8_t>& removed,
                           const HoleMesh& sm, const std::vector<int>& tri_vertex,
                           const std::vector<HoleMesh::Halfedge_index>& loops, double min_rim) {
  std::vector<int> parent = FacePieces(tri, removed, 1);
  RimCandidates c;
  c.component.assign(loops.size(), -1);
  for (size_t i = 0; i < loops.size(); ++i) {
    const auto from = tri.vertex_handle(tri_vertex[sm.source(loops[i])]);
    const auto to = tri.vertex_handle(tri_vertex[sm.target(loops[i])]);
    const auto across = tri.find_halfedge(from, to);
    if (!across.is_valid() || tri.is_boundary(across)) continue;
    c.component[i] = FindRoot(parent, tri.face_handle(across).idx());
  }
  c.count.assign(tri.n_faces(), 0);
  c.candidate.assign(loops.size(), 0);
  for (size_t i = 0; i < loops.size(); ++i) {
    if (c.component[i] < 0) continue;
    c.candidate[i] = Perimeter(sm, loops[i]) > min_rim &&
                     LeavingCosine(sm, loops[i]) >= kMinLeavingCosine;
    c.count[c.component[i]] += c.candidate[i];
  }
  return c;
}

// The centroid and the least-squares plane's unit normal of a loop.
std::pair<Eigen::Vector3d, Eigen::Vector3d> LoopPlane(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& x : p) mean += x;
  mean /= static_cast<double>(p.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& x : p) cov += (x - mean) * (x - mean).transpose();
  return {mean, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0)};
}

// Whether the axis of loop `bore` (the normal of its plane through its
// centroid) meets the plane of loop `outer` within 45° of square and inside
// that loop (winding number of the loop round the meeting point, both
// projected on the outer loop's plane); `run` is set to the distance along
// the axis from the bore loop's centroid to that point.
bool AxisMeetsInside(const std::vector<Eigen::Vector3d>& bore,
                     const std::vector<Eigen::Vector3d>& outer, double* run) {
  const auto [cb, ab] = LoopPlane(bore);
  const auto [co, ao] = LoopPlane(outer);
  const double cosine = ab.dot(ao);
  if (!(std::abs(cosine) >= kMinLeavingCosine)) return false;
  const double t = (co - cb).dot(ao) / cosine;
  *run = std::abs(t);
  const Eigen::Vector3d meet = cb + t * ab;
  const Eigen::Vector3d u = ao.unitOrthogonal(), v = ao.cross(u);
  double winding = 0.0;
  for (size_t k = 0; k < outer.size(); ++k) {
    const Eigen::Vector3d a = outer[k] - meet, b = outer[(k + 1) % outer.size()] - meet;
    const Eigen::Vector2d pa(a.dot(u), a.dot(v)), pb(b.dot(u), b.dot(v));
    winding += std::atan2(pa.x() * pb.y() - pa.y() * pb.x(), pa.dot(pb));
  }
  return std::abs(winding) > M_PI;
}

std::vector<Eigen::Vector3d> LoopPoints(const Sm& sm, Sm::Halfedge_index h) {
  std::vector<Eigen::Vector3d> p;
  for (const auto v : LoopOf(sm, h)) p.push_back(At(sm, v));
  return p;
}

}  // namespace

std::vector<std::pair<size_t, size_t>> TubeRims(const TriMesh& tri,
                                                const std::vector<uint8_t>& removed,
                                                const HoleMesh& sm,
                                                const std::vector<int>& tri_vertex,
                                                const std::vector<HoleMesh::Halfedge_index>& loops,
                                                double min_rim) {
  // Removed components, and the loops across which each meets the seen
  // surface.
  const RimCandidates c = CandidatesOf(tri, removed, sm, tri_vertex, loops, min_rim);
  // The candidate rims of each component: loops (b) longer than the points
  // resolve as holes that (c) the seen surface leaves as a wall. A
  // component with exactly two joins them through the unseen region (a),
  // whatever its genus: handles inside it are no more supported by points
  // than the rest of it, and go with it. Its other loops, which the seen
  // surface closes as a sheet, are holes in that sheet (the implicit
  // function dug under a seen face into the unseen region): each is closed
  // by its own disc on the sheet, and says nothing of the tube.
  std::vector<std::pair<size_t, size_t>> rims;
  for (size_t i = 0; i < loops.size(); ++i) {
    if (!c.candidate[i] || c.count[c.component[i]] != 2) continue;
    for (size_t j = i + 1; j < loops.size(); ++j) {
      if (c.component[j] == c.component[i] && c.candidate[j]) rims.emplace_back(i, j);
    }
  }
  return rims;
}

std::vector<std::pair<size_t, size_t>> LoneBoreRims(
    const TriMesh& tri, const std::vector<uint8_t>& removed, const HoleMesh& sm,
    const std::vector<int>& tri_vertex, const std::vector<HoleMesh::Halfedge_index>& loops,
    double min_rim) {
  const RimCandidates c = CandidatesOf(tri, removed, sm, tri_vertex, loops, min_rim);
  std::vector<size_t> lone;
  for (size_t i = 0; i < loops.size(); ++i) {
    if (c.candidate[i] && c.count[c.component[i]] == 1) lone.push_back(i);
  }
  std::vector<std::vector<Eigen::Vector3d>> points;
  std::vector<double> perimeter, curvature;
  for (const size_t i : lone) {
    points.push_back(LoopPoints(sm, loops[i]));
    perimeter.push_back(Perimeter(sm, loops[i]));
    curvature.push_back(std::abs(RimOf(sm, loops[i], 1.0).curvature));
  }
  // meets[a]: the lone rims (indices into `lone`) a's axis meets inside.
  std::vector<std::vector<size_t>> meets(lone.size()), met_by(lone.size());
  for (size_t a = 0; a < lone.size(); ++a) {
    for (size_t b = 0; b < lone.size(); ++b) {
      if (c.component[lone[a]] == c.component[lone[b]] || !(perimeter[a] < perimeter[b])) continue;
      // A straight wall: bent as the rim reads it, it would turn by less
      // than 45° (the square the leaving test allows) on its run to the
      // face; one that turns more is a curved section running on into the
      // unseen part (a round), not a bore.
      double run = 0.0;
      if (!AxisMeetsInside(points[a], points[b], &run)) continue;
      if (!(curvature[a] * run < 0.25 * M_PI)) continue;
      meets[a].push_back(b);
      met_by[b].push_back(a);
    }
  }
  std::vector<std::pair<size_t, size_t>> rims;
  for (size_t a = 0; a < lone.size(); ++a) {
    if (meets[a].size() != 1 || met_by[meets[a][0]].size() != 1) continue;
    rims.emplace_back(lone[a], lone[meets[a][0]]);
  }
  return rims;
}

}  // namespace meshseg::reconstruct_internal
