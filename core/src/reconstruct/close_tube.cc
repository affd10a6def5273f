#include "reconstruct/close_tube.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "mesh/union_find.h"

namespace meshseg::reconstruct_internal {

using mesh_internal::FindRoot;

namespace {

using Kernel = HoleKernel;
using Sm = HoleMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

// The rings inside a rim (in edges) whose normals give its curvature and
// its normal: past the extrapolated faces next to the border, within the
// seen surface's run.
constexpr int kNearRing = 3;
constexpr int kFarRing = 9;
// The outgoing direction at a loop vertex is averaged over this many loop
// vertices on either side: as far along the rim as the rings it comes from
// reach inwards (a scan's border zigzags from one edge to the next, and
// detail along the rim finer than the band the normals are read from is
// their noise). With ±2 the tube's p95 off a scanned ring was 2.6-5.5 sp.
constexpr int kDirectionWindow = kFarRing;
// A rim vertex's ring sums are pooled with this many neighbours on either
// side (one may own no vertex of a ring); a wider pool would draw the mean
// point of a ring towards the axis of a tight loop.
constexpr int kRingWindow = 2;
// Loops whose strip search (loop vertices × loop vertices) is larger than
// this are left to their discs.
constexpr size_t kMaxStripCells = 4'000'000;
// Rows of the tube between its rims: enough for the loop's mean edge length
// along the longest rung's arc, within these bounds.
constexpr int kMinRows = 2;
constexpr int kMaxRows = 256;
// Arcs that bend (deeper below their chords than the loops' mean edge
// length, the resolution of a curvature across the rims) must bend as the
// seen surface does at each rim: its curvature within this fraction of the
// arcs' mean curvature.
constexpr double kCurvatureTolerance = 0.5;
// Below this turning angle (radians) a rung's arc is taken as straight.
constexpr double kStraightAngle = 1e-3;

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

// A border loop of the seen surface: its vertices in the order of the
// border; at each, the unit direction in which the seen surface leaves it
// (in the tangent plane, across the border, away from the kept faces; they
// lie to the right of the border's direction seen from their front),
// averaged over kDirectionWindow vertices on either side; and the seen
// surface's mean normal curvature across the border (> 0 where it turns
// towards its inside as it goes out, as a torus's section does).
//
// The faces next to the border are the least trustworthy part of the seen
// surface: they reach up to the support step's reach past the last points,
// where the implicit function is extrapolated, and one ring of normals is
// noisier than the turn of a curved section over it. So both come from the
// rings kNearRing and kFarRing edges inside (each rim vertex owns the
// vertices nearest it in edges): the curvature is the turn of the normal
// between them over their distance, and the normal at the rim is the near
// ring's turned on by as much as the turn carries on to the rim (an arc).
struct Rim {
  std::vector<Sm::Vertex_index> loop;
  std::vector<Eigen::Vector3d> out;
  double curvature = 0.0;
};

Rim RimOf(const Sm& sm, Sm::Halfedge_index h) {
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
  // Per rim vertex and ring (near, far): sums of the owned vertices'
  // normals and points, and their count.
  std::vector<std::array<Eigen::Vector3d, 2>> normal_sum(n, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  std::vector<std::array<Eigen::Vector3d, 2>> point_sum = normal_sum;
  std::vector<std::array<int, 2>> owned(n, {0, 0});
  for (int r = 1; r <= kFarRing && !front.empty(); ++r) {
    std::vector<Sm::Vertex_index> next;
    for (const auto v : front) {
      for (const auto w : CGAL::vertices_around_target(sm.halfedge(v), sm)) {
        if (ring[w] >= 0) continue;
        ring[w] = r;
        owner[w] = owner[v];
        next.push_back(w);
        if (r != kNearRing && r != kFarRing) continue;
        const int which = r == kFarRing;
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
    Eigen::Vector3d n1 = Eigen::Vector3d::Zero(), n2 = n1, p1 = n1, p2 = n1;
    int c1 = 0, c2 = 0;
    for (int w = -kRingWindow; w <= kRingWindow; ++w) {
      const size_t j = (k + n + w) % n;
      n1 += normal_sum[j][0];
      p1 += point_sum[j][0];
      c1 += owned[j][0];
      n2 += normal_sum[j][1];
      p2 += point_sum[j][1];
      c2 += owned[j][1];
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
    turn += axis.dot(normal.cross(raw[k])) >= 0 ? angle : -angle;
    run += span;
  }
  rim.curvature = run > 0 ? turn / run : 0.0;
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
    for (int w = -kDirectionWindow; w <= kDirectionWindow; ++w) sum += raw[(k + n + w) % n];
    rim.out[k] = sum.norm() > 0 ? Eigen::Vector3d(sum.normalized()) : sum;
  }
  return rim;
}

// The mean |cosine| between the outgoing directions and the axis of the
// loop (the normal of its least-squares plane).
double LeavingCosine(const Sm& sm, Sm::Halfedge_index h) {
  const Rim rim = RimOf(sm, h);
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

// The cubic Hermite curve from `a` leaving along `da` to `b` arriving
// against `db` (b's own outgoing direction), with the tangent length of the
// circular arc that turns by the angle θ between da and −db over the chord c:
// 4 tan(θ/4) R with R = c / (2 sin(θ/2)) (three times the Bézier control
// distance of an arc), c when straight. Also gives the arc's length.
struct Rung {
  Eigen::Vector3d a, b, da, db;
  // depth: below the chord; curvature: 1 / the arc's radius
  double chord = 0.0, tangent = 0.0, arc = 0.0, depth = 0.0, curvature = 0.0;

  Rung(const Eigen::Vector3d& a_in, const Eigen::Vector3d& b_in, const Eigen::Vector3d& da_in,
       const Eigen::Vector3d& db_in)
      : a(a_in), b(b_in), da(da_in), db(db_in) {
    chord = (b - a).norm();
    const double theta = std::acos(std::clamp(-da.dot(db), -1.0, 1.0));
    if (theta < kStraightAngle) {
      tangent = arc = chord;
    } else {
      const double radius = chord / (2.0 * std::sin(0.5 * theta));
      tangent = 4.0 * std::tan(0.25 * theta) * radius;
      arc = theta * radius;
      depth = radius * (1.0 - std::cos(0.5 * theta));
      curvature = 1.0 / radius;
    }
  }

  Eigen::Vector3d At(double t) const {
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * a + (t3 - 2 * t2 + t) * tangent * da + (3 * t2 - 2 * t3) * b -
           (t3 - t2) * tangent * db;
  }
};

// The strip of least total rung length between loops `a` and `b` (both
// starting at their first vertex): pairs (i, j), from (0, 0) to (m, n), each
// step advancing one of them by one.
std::vector<std::pair<size_t, size_t>> ShortestStrip(const std::vector<Eigen::Vector3d>& a,
                                                     const std::vector<Eigen::Vector3d>& b) {
  const size_t m = a.size(), n = b.size();
  const auto at = [n](size_t i, size_t j) { return i * (n + 1) + j; };
  std::vector<double> cost((m + 1) * (n + 1), std::numeric_limits<double>::infinity());
  cost[0] = 0.0;
  for (size_t i = 0; i <= m; ++i) {
    for (size_t j = 0; j <= n; ++j) {
      if (i == 0 && j == 0) continue;
      const double rung = (a[i % m] - b[j % n]).norm();
      double best = std::numeric_limits<double>::infinity();
      if (i > 0) best = cost[at(i - 1, j)];
      if (j > 0) best = std::min(best, cost[at(i, j - 1)]);
      cost[at(i, j)] = best + rung;
    }
  }
  std::vector<std::pair<size_t, size_t>> path{{m, n}};
  for (size_t i = m, j = n; i > 0 || j > 0;) {
    if (j == 0 || (i > 0 && cost[at(i - 1, j)] <= cost[at(i, j - 1)])) {
      --i;
    } else {
      --j;
    }
    path.emplace_back(i, j);
  }
  std::reverse(path.begin(), path.end());
  return path;
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

std::vector<std::pair<size_t, size_t>> TubeRims(const TriMesh& tri,
                                                const std::vector<uint8_t>& removed,
                                                const HoleMesh& sm,
                                                const std::vector<int>& tri_vertex,
                                                const std::vector<HoleMesh::Halfedge_index>& loops,
                                                double min_rim) {
  // Removed components and their Euler characteristics.
  std::vector<int> parent = FacePieces(tri, removed, 1);
  std::vector<int64_t> chi(tri.n_faces(), 0);
  for (const auto f : tri.faces()) chi[FindRoot(parent, f.idx())] += removed[f.idx()];
  for (const auto e : tri.edges()) {
    for (int side = 0; side < 2; ++side) {
      const auto f = tri.face_handle(tri.halfedge_handle(e, side));
      if (f.is_valid() && removed[f.idx()]) {
        --chi[FindRoot(parent, f.idx())];
        break;
      }
    }
  }
  for (const auto v : tri.vertices()) {
    for (const auto f : tri.vf_range(v)) {
      if (!removed[f.idx()]) continue;
      ++chi[FindRoot(parent, f.idx())];  // one removed fan per vertex (no pinches)
      break;
    }
  }
  // The component across each loop, and the loops of each component.
  std::vector<int> component(loops.size(), -1);
  std::vector<int> loop_count(tri.n_faces(), 0);
  for (size_t i = 0; i < loops.size(); ++i) {
    const auto from = tri.vertex_handle(tri_vertex[sm.source(loops[i])]);
    const auto to = tri.vertex_handle(tri_vertex[sm.target(loops[i])]);
    const auto across = tri.find_halfedge(from, to);
    if (!across.is_valid() || tri.is_boundary(across)) continue;
    component[i] = FindRoot(parent, tri.face_handle(across).idx());
    ++loop_count[component[i]];
  }
  std::vector<std::pair<size_t, size_t>> rims;
  for (size_t i = 0; i < loops.size(); ++i) {
    const int c = component[i];
    if (c < 0 || loop_count[c] != 2 || chi[c] != 0) continue;
    for (size_t j = i + 1; j < loops.size(); ++j) {
      if (component[j] != c) continue;
      if (Perimeter(sm, loops[i]) > min_rim && Perimeter(sm, loops[j]) > min_rim &&
          LeavingCosine(sm, loops[i]) >= kMinLeavingCosine &&
          LeavingCosine(sm, loops[j]) >= kMinLeavingCosine) {
        rims.emplace_back(i, j);
      }
    }
  }
  return rims;
}

bool CloseTube(HoleMesh::Halfedge_index a, HoleMesh::Halfedge_index b, HoleMesh* sm) {
  const Rim rim_a = RimOf(*sm, a);
  Rim rim_b = RimOf(*sm, b);
  const std::vector<Sm::Vertex_index>& loop_a = rim_a.loop;
  std::vector<Sm::Vertex_index>& loop_b = rim_b.loop;
  const size_t m = loop_a.size(), n = loop_b.size();
  if (m * n > kMaxStripCells) return false;
  for (const auto v : loop_a) {
    if (std::find(loop_b.begin(), loop_b.end(), v) != loop_b.end()) return false;
  }
  const std::vector<Eigen::Vector3d>& out_a = rim_a.out;
  std::vector<Eigen::Vector3d>& out_b = rim_b.out;
  // An oriented strip runs along one rim's border and against the other's,
  // starting at the vertex of b nearest a's first.
  std::reverse(loop_b.begin(), loop_b.end());
  std::reverse(out_b.begin(), out_b.end());
  std::vector<Eigen::Vector3d> pa, pb;
  for (const auto v : loop_a) pa.push_back(At(*sm, v));
  for (const auto v : loop_b) pb.push_back(At(*sm, v));
  size_t first = 0;
  for (size_t j = 1; j < n; ++j) {
    if ((pb[j] - pa[0]).squaredNorm() < (pb[first] - pa[0]).squaredNorm()) first = j;
  }
  std::rotate(loop_b.begin(), loop_b.begin() + first, loop_b.end());
  std::rotate(out_b.begin(), out_b.begin() + first, out_b.end());
  std::rotate(pb.begin(), pb.begin() + first, pb.end());
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pa, pb);
  const size_t rungs = strip.size() - 1;  // the last is the first again
  std::vector<Rung> rung;
  double edge = 0.0, longest = 0.0;
  for (size_t k = 0; k < m; ++k) edge += (pa[(k + 1) % m] - pa[k]).norm();
  for (size_t k = 0; k < n; ++k) edge += (pb[(k + 1) % n] - pb[k]).norm();
  edge /= static_cast<double>(m + n);
  for (size_t r = 0; r < rungs; ++r) {
    const auto [i, j] = strip[r];
    rung.emplace_back(pa[i % m], pb[j % n], out_a[i % m], out_b[j % n]);
    longest = std::max(longest, rung.back().arc);
  }
  // The arcs must bend as the seen surface does at each rim, unless they
  // are straight within the resolution of that curvature.
  double arc_depth = 0.0, arc_curvature = 0.0;
  for (const Rung& r : rung) {
    arc_depth += r.depth;
    arc_curvature += r.curvature;
  }
  arc_depth /= static_cast<double>(rungs);
  arc_curvature /= static_cast<double>(rungs);
  if (arc_depth > edge) {
    for (const double seen : {rim_a.curvature, rim_b.curvature}) {
      if (std::abs(seen - arc_curvature) > kCurvatureTolerance * arc_curvature) return false;
    }
  }
  const int rows = std::clamp(static_cast<int>(std::ceil(longest / edge)), kMinRows, kMaxRows);
  // Vertex k of rung r: the rims at k = 0 and rows, new vertices between.
  std::vector<Sm::Vertex_index> added;
  for (size_t r = 0; r < rungs; ++r) {
    for (int k = 1; k < rows; ++k) {
      const Eigen::Vector3d p = rung[r].At(static_cast<double>(k) / rows);
      added.push_back(sm->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    }
  }
  const auto vertex = [&](size_t r, int k) {
    r %= rungs;
    if (k == 0) return loop_a[strip[r].first % m];
    if (k == rows) return loop_b[strip[r].second % n];
    return added[r * (rows - 1) + k - 1];
  };
  std::vector<Sm::Face_index> faces;
  bool ok = true;
  const auto add = [&](Sm::Vertex_index u, Sm::Vertex_index v, Sm::Vertex_index w) {
    if (!ok || u == v || v == w || w == u) return;
    const auto f = sm->add_face(u, v, w);
    if (f == Sm::null_face()) {
      ok = false;
    } else {
      faces.push_back(f);
    }
  };
  for (size_t r = 0; r < rungs && ok; ++r) {
    for (int k = 0; k < rows; ++k) {
      add(vertex(r, k), vertex(r + 1, k), vertex(r + 1, k + 1));
      add(vertex(r, k), vertex(r + 1, k + 1), vertex(r, k + 1));
    }
  }
  if (ok) return true;
  for (auto f = faces.rbegin(); f != faces.rend(); ++f) {
    CGAL::Euler::remove_face(sm->halfedge(*f), *sm);
  }
  for (const auto v : added) {
    if (!sm->is_removed(v)) sm->remove_vertex(v);
  }
  return false;
}

}  // namespace meshseg::reconstruct_internal
