#include "reconstruct/close_tube.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include "reconstruct/seen_planes.h"
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
// Feet of the bore's rim on the cap plane nearer than this fraction of the
// loops' mean edge to the last kept one are one foot.
constexpr double kMinFootSpacing = 0.5;

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

// The faces and vertices a strip added, to take them back.
struct Added {
  std::vector<Sm::Face_index> faces;
  std::vector<Sm::Vertex_index> vertices;
};

void TakeBack(const Added& added, Sm* sm) {
  for (auto f = added.faces.rbegin(); f != added.faces.rend(); ++f) {
    CGAL::Euler::remove_face(sm->halfedge(*f), *sm);
  }
  for (const auto v : added.vertices) {
    if (!sm->is_removed(v)) sm->remove_vertex(v);
  }
}

// Adds the strip whose rung r joins side_a[strip[r].first] to
// side_b[strip[r].second] (indices modulo the sides' sizes; the last pair is
// the first again) through rows[r] − 1 new vertices at(r, k / rows[r]).
// Neighbouring rungs with different rows are zipped by their parameters
// (each step advances the rung whose next vertex lies nearer its start).
// side_a runs along its border, side_b against its own. False when CGAL
// refuses a face.
bool AddStrip(const std::vector<Sm::Vertex_index>& side_a,
              const std::vector<Sm::Vertex_index>& side_b,
              const std::vector<std::pair<size_t, size_t>>& strip,
              const std::function<Eigen::Vector3d(size_t, double)>& at,
              const std::vector<int>& rows, Sm* sm, Added* added) {
  const size_t m = side_a.size(), n = side_b.size(), rungs = strip.size() - 1;
  std::vector<size_t> first(rungs);
  for (size_t r = 0; r < rungs; ++r) {
    first[r] = added->vertices.size();
    for (int k = 1; k < rows[r]; ++k) {
      const Eigen::Vector3d p = at(r, static_cast<double>(k) / rows[r]);
      added->vertices.push_back(sm->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    }
  }
  const auto vertex = [&](size_t r, int k) {
    r %= rungs;
    if (k == 0) return side_a[strip[r].first % m];
    if (k == rows[r]) return side_b[strip[r].second % n];
    return added->vertices[first[r] + k - 1];
  };
  bool ok = true;
  const auto add = [&](Sm::Vertex_index u, Sm::Vertex_index v, Sm::Vertex_index w) {
    if (!ok || u == v || v == w || w == u) return;
    const auto f = sm->add_face(u, v, w);
    if (f == Sm::null_face()) {
      ok = false;
    } else {
      added->faces.push_back(f);
    }
  };
  for (size_t r = 0; r < rungs && ok; ++r) {
    const int here = rows[r], next = rows[(r + 1) % rungs];
    for (int i = 0, j = 0; i < here || j < next;) {
      if (j == next || (i < here && (i + 1) * next < (j + 1) * here)) {
        add(vertex(r, i), vertex(r + 1, j), vertex(r, i + 1));
        ++i;
      } else {
        add(vertex(r, i), vertex(r + 1, j), vertex(r + 1, j + 1));
        ++j;
      }
    }
  }
  return ok;
}

std::vector<Eigen::Vector3d> Points(const Sm& sm, const std::vector<Sm::Vertex_index>& loop) {
  std::vector<Eigen::Vector3d> p;
  for (const auto v : loop) p.push_back(At(sm, v));
  return p;
}

double MeanEdge(const std::vector<Eigen::Vector3d>& pa, const std::vector<Eigen::Vector3d>& pb) {
  return (LoopPerimeter(pa) + LoopPerimeter(pb)) / static_cast<double>(pa.size() + pb.size());
}

// The index of the point of `p` nearest `q` (the first of equals).
size_t Nearest(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& q) {
  size_t nearest = 0;
  for (size_t j = 1; j < p.size(); ++j) {
    if ((p[j] - q).squaredNorm() < (p[nearest] - q).squaredNorm()) nearest = j;
  }
  return nearest;
}

int Rows(double longest, double edge) {
  return std::clamp(static_cast<int>(std::ceil(longest / edge)), kMinRows, kMaxRows);
}

// Rows for each rung of a straight strip: its own length over the loops'
// mean edge, so the vertices along every rung lie about one edge apart.
std::vector<int> RowsPerRung(const std::vector<std::pair<size_t, size_t>>& strip,
                             const std::vector<Eigen::Vector3d>& a,
                             const std::vector<Eigen::Vector3d>& b, double edge) {
  std::vector<int> rows;
  for (size_t r = 0; r + 1 < strip.size(); ++r) {
    const double length = (b[strip[r].second % b.size()] - a[strip[r].first % a.size()]).norm();
    rows.push_back(std::clamp(static_cast<int>(std::ceil(length / edge)), 1, kMaxRows));
  }
  return rows;
}

// The outward normals (`sign` × the area-weighted normal of their faces) of
// the seen surface at the vertices of `loop`, taken before a strip borders it.
std::vector<Eigen::Vector3d> SeenNormals(const Sm& sm, const std::vector<Sm::Vertex_index>& loop,
                                         double sign) {
  std::vector<Eigen::Vector3d> normals;
  for (const auto v : loop) {
    const auto n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, sm);
    normals.push_back(sign * Eigen::Vector3d(n.x(), n.y(), n.z()));
  }
  return normals;
}

// Bends the strip `faces` (free vertices `vertices`) across the face a bore
// opens onto onto the seen planes round it (seen_planes.h), as a disc over
// that face would be: where the outer rim climbs a wall, straight rungs from
// it to the bore's circle cut the corner between the wall and the face. The
// hull is that of the outer rim `loop` (seen normals `normals`) alone: its
// loop is the convex one; the bore's wall is concave and no face of it.
void BendFace(const std::vector<Eigen::Vector3d>& loop, const std::vector<Eigen::Vector3d>& normals,
              double sign, const std::vector<Sm::Face_index>& faces,
              const std::vector<Sm::Vertex_index>& vertices, Sm* sm) {
  Eigen::Vector3d patch_normal = Eigen::Vector3d::Zero();
  for (const auto f : faces) {
    const auto h = sm->halfedge(f);
    const Eigen::Vector3d a = At(*sm, sm->source(h)), b = At(*sm, sm->target(h));
    patch_normal += sign * (b - a).cross(At(*sm, sm->target(sm->next(h))) - a);
  }
  std::vector<Eigen::Vector3d> free_vertices;
  for (const auto v : vertices) free_vertices.push_back(At(*sm, v));
  if (!BendOntoSeenPlanes(loop, normals, patch_normal, &free_vertices)) return;
  for (size_t i = 0; i < vertices.size(); ++i) {
    sm->point(vertices[i]) =
        Kernel::Point_3(free_vertices[i].x(), free_vertices[i].y(), free_vertices[i].z());
  }
}

// The annulus between a bore's rim and the rim round the face it opens onto,
// both seen as straight walls (close_tube.h, the split at the cap): the
// bore's wall run on along its axis to the cap plane, and the strip of
// straight rungs between the outer rim and the bore's circle on that plane.
bool SplitAtCap(const Rim& rim_a, const Rim& rim_b, double sign, bool bend, Sm* sm) {
  const std::vector<Eigen::Vector3d> pa = Points(*sm, rim_a.loop), pb = Points(*sm, rim_b.loop);
  const double edge = MeanEdge(pa, pb);
  const bool a_is_bore = LoopPerimeter(pa) < LoopPerimeter(pb);
  const Rim& bore = a_is_bore ? rim_a : rim_b;
  const Rim& outer = a_is_bore ? rim_b : rim_a;
  const std::vector<Eigen::Vector3d>& pbore = a_is_bore ? pa : pb;
  const std::vector<Eigen::Vector3d>& pouter = a_is_bore ? pb : pa;
  // The bore's axis: the direction its wall's normals are all square to (a
  // cylinder's or prism's normals lie on a great circle of the Gauss map:
  // the least eigenvector of their scatter), facing the way the wall leaves
  // the rim. A normal is the border's tangent across the outgoing direction.
  const size_t n = pbore.size();
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  Eigen::Vector3d way = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d normal =
        (pbore[(k + 1) % n] - pbore[(k + n - 1) % n]).cross(bore.out[k]).normalized();
    if (normal.allFinite()) scatter += normal * normal.transpose();
    way += bore.out[k];
  }
  Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
  if (axis.dot(way) < 0) axis = -axis;
  // The cap plane: the plane the most of the outer rim lies on, as the
  // seen planes find it for a disc over the face (seen_planes.h); the bore
  // runs square to it.
  Eigen::Vector3d normal;
  double cap = 0.0;
  if (!SeenCapPlane(pouter, axis, &normal, &cap)) return false;
  if (normal.dot(axis) < kMinLeavingCosine) return false;  // no cap square to the bore
  axis = normal;
  // The bore's circle on the cap plane; the cap must lie beyond its rim.
  // Rim vertices stacked along the axis (where the rim climbs the bore's
  // wall) have one foot: the first of them keeps it, the others join the
  // strip to their neighbours' feet.
  std::vector<Eigen::Vector3d> foot;
  for (size_t k = 0; k < n; ++k) {
    const double run = cap - axis.dot(pbore[k]);
    if (run < edge) return false;
    const Eigen::Vector3d p = pbore[k] + run * axis;
    if (foot.empty() || (p - foot.back()).norm() >= kMinFootSpacing * edge) foot.push_back(p);
  }
  while (foot.size() > 1 && (foot.back() - foot.front()).norm() < kMinFootSpacing * edge) {
    foot.pop_back();
  }
  if (foot.size() < 3) return false;
  const std::vector<Eigen::Vector3d> outer_normals = SeenNormals(*sm, outer.loop, sign);
  Added added;
  std::vector<Sm::Vertex_index> feet;
  for (const Eigen::Vector3d& p : foot) {
    feet.push_back(sm->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    added.vertices.push_back(feet.back());
  }
  const std::vector<std::pair<size_t, size_t>> down = ShortestStrip(pbore, foot);
  const auto on_wall = [&](size_t r, double t) {
    const auto [i, j] = down[r];
    return Eigen::Vector3d(pbore[i % n] + t * (foot[j % foot.size()] - pbore[i % n]));
  };
  bool ok = AddStrip(bore.loop, feet, down, on_wall, RowsPerRung(down, pbore, foot, edge), sm,
                     &added);
  // The face the bore opens onto: the outer rim along its border, the
  // bore's circle against the tube's new border (which runs as the bore's).
  std::vector<Sm::Vertex_index> inner(feet.rbegin(), feet.rend());
  std::vector<Eigen::Vector3d> pinner(foot.rbegin(), foot.rend());
  const size_t first = Nearest(pinner, pouter[0]);
  std::rotate(inner.begin(), inner.begin() + first, inner.end());
  std::rotate(pinner.begin(), pinner.begin() + first, pinner.end());
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pouter, pinner);
  const auto on_face = [&](size_t r, double t) {
    const auto [i, j] = strip[r];
    const Eigen::Vector3d& p = pouter[i % pouter.size()];
    return Eigen::Vector3d(p + t * (pinner[j % pinner.size()] - p));
  };
  const size_t face_faces = added.faces.size(), face_vertices = added.vertices.size();
  ok = ok && AddStrip(outer.loop, inner, strip, on_face, RowsPerRung(strip, pouter, pinner, edge),
                      sm, &added);
  if (!ok) {
    TakeBack(added, sm);
    return false;
  }
  if (bend) {
    BendFace(pouter, outer_normals, sign,
             std::vector<Sm::Face_index>(added.faces.begin() + face_faces, added.faces.end()),
             std::vector<Sm::Vertex_index>(added.vertices.begin() + face_vertices,
                                           added.vertices.end()),
             sm);
  }
  return true;
}

}  // namespace

bool CloseTube(HoleMesh::Halfedge_index a, HoleMesh::Halfedge_index b, double sign, bool bend,
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
  const Rim rim_b_border = rim_b;
  // An oriented strip runs along one rim's border and against the other's,
  // starting at the vertex of b nearest a's first.
  std::reverse(loop_b.begin(), loop_b.end());
  std::reverse(out_b.begin(), out_b.end());
  const std::vector<Eigen::Vector3d> pa = Points(*sm, loop_a);
  std::vector<Eigen::Vector3d> pb = Points(*sm, loop_b);
  const size_t first = Nearest(pb, pa[0]);
  std::rotate(loop_b.begin(), loop_b.begin() + first, loop_b.end());
  std::rotate(out_b.begin(), out_b.begin() + first, out_b.end());
  std::rotate(pb.begin(), pb.begin() + first, pb.end());
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pa, pb);
  const size_t rungs = strip.size() - 1;  // the last is the first again
  std::vector<Rung> rung;
  const double edge = MeanEdge(pa, pb);
  double longest = 0.0;
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
  const double tolerance = kCurvatureTolerance * arc_curvature;
  const auto off_arcs = [&](double seen) { return std::abs(seen - arc_curvature) > tolerance; };
  const auto curved = [&](double seen) { return std::abs(seen) > tolerance; };
  if (arc_depth > edge && (off_arcs(rim_a.curvature) || off_arcs(rim_b.curvature))) {
    // Straight walls at both rims (flatter than the arcs by the same
    // tolerance) run on to the face between them.
    if (curved(rim_a.curvature) || curved(rim_b.curvature)) return false;
    return SplitAtCap(rim_a, rim_b_border, sign, bend, sm);
  }
  Added added;
  const bool ok = AddStrip(
      loop_a, loop_b, strip, [&](size_t r, double t) { return rung[r].At(t); },
      std::vector<int>(rungs, Rows(longest, edge)), sm, &added);
  if (!ok) TakeBack(added, sm);
  return ok;
}

}  // namespace meshseg::reconstruct_internal
