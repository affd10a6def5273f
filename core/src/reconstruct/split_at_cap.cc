#include "reconstruct/split_at_cap.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include "reconstruct/seen_planes.h"
#include "reconstruct/tube_strip.h"

namespace meshseg::reconstruct_internal {
namespace {

using Kernel = HoleKernel;
using Sm = HoleMesh;

// Feet of the bore's rim on the cap plane nearer than this fraction of the
// loops' mean edge to the last kept one are one foot.
constexpr double kMinFootSpacing = 0.5;

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
    const Eigen::Vector3d a = PointOf(*sm, sm->source(h)), b = PointOf(*sm, sm->target(h));
    patch_normal += sign * (b - a).cross(PointOf(*sm, sm->target(sm->next(h))) - a);
  }
  std::vector<Eigen::Vector3d> free_vertices;
  for (const auto v : vertices) free_vertices.push_back(PointOf(*sm, v));
  if (!BendOntoSeenPlanes(loop, normals, patch_normal, &free_vertices)) return;
  for (size_t i = 0; i < vertices.size(); ++i) {
    sm->point(vertices[i]) =
        Kernel::Point_3(free_vertices[i].x(), free_vertices[i].y(), free_vertices[i].z());
  }
}

}  // namespace

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
  // The outer rim is the longer loop, so straight rungs from it fan in
  // onto the bore's circle; the face is laid as contours no denser than a
  // mesh of the loops' mean edge (tube_strip.h).
  const size_t face_faces = added.faces.size(), face_vertices = added.vertices.size();
  ok = ok && AddContourStrip(outer.loop, pouter, inner, pinner, edge, sm, &added);
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

}  // namespace meshseg::reconstruct_internal
