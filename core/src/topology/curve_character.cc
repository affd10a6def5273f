#include "topology/curve_character.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "meshseg/fit.h"
#include "topology/chain_curves.h"

namespace meshseg::topology_internal {
namespace {

using Eigen::Vector3d;

// The halfedge from a to b with `left` on its left.
OpenMesh::HalfedgeHandle HalfedgeWithLeft(const TriMesh& mesh, std::span<const int> labels,
                                          int a, int b, int left) {
  const OpenMesh::HalfedgeHandle h =
      mesh.find_halfedge(OpenMesh::VertexHandle(a), OpenMesh::VertexHandle(b));
  if (h.is_valid() && LeftLabel(mesh, labels, h) == left) return h;
  return OpenMesh::HalfedgeHandle();
}

// The surface normal at p turned to agree with the face normal.
Vector3d OutwardNormal(const Surface& s, const Vector3d& p, const Vector3d& face_normal) {
  const Vector3d n = Project(s, p, face_normal).normal;
  return n.dot(face_normal) >= 0.0 ? n : Vector3d(-n);
}

}  // namespace

CurveCharacter CurveCharacterOf(const TriMesh& mesh, std::span<const int> face_labels,
                                std::span<const Region> regions, const BoundaryCurve& curve,
                                double sharp_angle_deg) {
  CurveCharacter out;
  if (curve.left_region < 0 || curve.right_region < 0) return out;
  const Surface& left = regions[curve.left_region].surface;
  const Surface& right = regions[curve.right_region].surface;
  double angle_sum = 0.0;
  double turn = 0.0;  // Σ (n_left × n_right) · edge, > 0 convex
  int edges = 0;
  for (size_t i = 0; i + 1 < curve.vertices.size(); ++i) {
    const OpenMesh::HalfedgeHandle h = HalfedgeWithLeft(
        mesh, face_labels, curve.vertices[i], curve.vertices[i + 1], curve.left_region);
    if (!h.is_valid()) continue;
    const OpenMesh::HalfedgeHandle o = mesh.opposite_halfedge_handle(h);
    const Vector3d a = ToEigen(mesh.point(mesh.from_vertex_handle(h)));
    const Vector3d b = ToEigen(mesh.point(mesh.to_vertex_handle(h)));
    const Vector3d mid = 0.5 * (a + b);
    const Vector3d edge = b - a;
    const Vector3d fl = ToEigen(mesh.normal(mesh.face_handle(h)));
    const Vector3d fr = ToEigen(mesh.normal(mesh.face_handle(o)));
    const Vector3d nl = OutwardNormal(left, mid, fl);
    const Vector3d nr = OutwardNormal(right, mid, fr);
    angle_sum += std::acos(std::clamp(nl.dot(nr), -1.0, 1.0));
    // Tangent surfaces have equal normals on the curve: compare them one
    // edge length into each region, where the fitted curvature shows.
    const Vector3d into_left = nl.cross(edge);
    const Vector3d into_right = -nr.cross(edge);
    const Vector3d off_l = OutwardNormal(left, mid + into_left, fl);
    const Vector3d off_r = OutwardNormal(right, mid + into_right, fr);
    turn += off_l.cross(off_r).dot(edge);
    ++edges;
  }
  if (edges == 0) return out;
  out.normal_angle_deg = angle_sum / edges * 180.0 / std::numbers::pi;
  out.sharp = out.normal_angle_deg > sharp_angle_deg;
  out.convexity = turn >= 0.0 ? CurveConvexity::kConvex : CurveConvexity::kConcave;
  return out;
}

}  // namespace meshseg::topology_internal
