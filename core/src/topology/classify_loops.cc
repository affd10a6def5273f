#include "topology/classify_loops.h"

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include <Eigen/Geometry>

namespace meshseg::topology_internal {
namespace {

using Eigen::Vector3d;

// Turns of the closed polyline around the axis (signed).
double WindingAround(const AxisLine& axis, const std::vector<Vector3d>& points) {
  const Vector3d d = axis.direction.normalized();
  const Vector3d e1 = d.unitOrthogonal();
  const Vector3d e2 = d.cross(e1);
  double total = 0.0;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const Vector3d a = points[i] - axis.point;
    const Vector3d b = points[i + 1] - axis.point;
    const double angle_a = std::atan2(a.dot(e2), a.dot(e1));
    const double angle_b = std::atan2(b.dot(e2), b.dot(e1));
    double step = angle_b - angle_a;
    if (step > std::numbers::pi) step -= 2.0 * std::numbers::pi;
    if (step < -std::numbers::pi) step += 2.0 * std::numbers::pi;
    total += step;
  }
  return total / (2.0 * std::numbers::pi);
}

// Vector area 1/2 Σ p_i × p_{i+1} of a closed polyline.
Vector3d VectorArea(const std::vector<Vector3d>& points) {
  Vector3d area = Vector3d::Zero();
  for (size_t i = 0; i + 1 < points.size(); ++i) area += points[i].cross(points[i + 1]);
  return 0.5 * area;
}

}  // namespace

void ClassifyLoops(const TriMesh& mesh, std::span<const int> face_labels,
                   std::span<const Region> regions, TracedLoops* traced) {
  // Area-weighted outward normal per (region, patch).
  std::map<std::pair<int, int>, Vector3d> patch_normal;
  for (OpenMesh::FaceHandle f : mesh.faces()) {
    const int label = face_labels[f.idx()];
    if (label < 0) continue;
    auto [it, inserted] =
        patch_normal.try_emplace({label, traced->face_patch[f.idx()]}, Vector3d::Zero());
    it->second += mesh.calc_face_area(f) * ToEigen(mesh.normal(f));
  }
  std::map<std::pair<int, int>, bool> has_axial;
  std::map<std::pair<int, int>, std::pair<double, int>> best_outer;  // score, loop id
  std::vector<double> score(traced->loops.size(), 0.0);
  for (Loop& loop : traced->loops) {
    std::vector<Vector3d> points;
    for (const int v : traced->loop_vertices[loop.id]) {
      points.push_back(ToEigen(mesh.point(OpenMesh::VertexHandle(v))));
    }
    const std::pair<int, int> key{loop.region, loop.patch};
    const std::optional<AxisLine> axis = AxisOf(regions[loop.region].surface);
    if (axis && std::abs(WindingAround(*axis, points)) > 0.5) {
      loop.kind = LoopKind::kAxial;
      has_axial[key] = true;
      continue;
    }
    loop.kind = LoopKind::kInner;
    score[loop.id] = VectorArea(points).dot(patch_normal[key]);
    auto [it, inserted] = best_outer.try_emplace(key, score[loop.id], loop.id);
    if (!inserted && score[loop.id] > it->second.first) it->second = {score[loop.id], loop.id};
  }
  for (const auto& [key, best] : best_outer) {
    if (!has_axial[key]) traced->loops[best.second].kind = LoopKind::kOuter;
  }
}

}  // namespace meshseg::topology_internal
