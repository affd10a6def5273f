#include "reconstruct/close_tube.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <CGAL/boost/graph/Euler_operations.h>

#include "reconstruct/tube_rims.h"

namespace meshseg::reconstruct_internal {
namespace {

using Kernel = HoleKernel;
using Sm = HoleMesh;

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

bool CloseTube(HoleMesh::Halfedge_index a, HoleMesh::Halfedge_index b, double sign,
               HoleMesh* sm) {
  const Rim rim_a = RimOf(*sm, a, sign);
  Rim rim_b = RimOf(*sm, b, sign);
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
