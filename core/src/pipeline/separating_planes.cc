#include "pipeline/separating_planes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

namespace meshseg::pipeline_internal {
namespace {

// Half the gap between the air and the material samples along `n` (unit),
// and the offset of the plane in its middle.
struct Gap {
  double margin = -std::numeric_limits<double>::infinity();
  double offset = 0.0;
};

Gap GapAlong(const Eigen::Vector3d& n, std::span<const Eigen::Vector3d> inside,
             std::span<const Eigen::Vector3d> outside) {
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& a : inside) top = std::max(top, n.dot(a));
  for (const Eigen::Vector3d& b : outside) bottom = std::min(bottom, n.dot(b));
  return {0.5 * (bottom - top), 0.5 * (bottom + top)};
}

}  // namespace

std::vector<int> InteriorRegionOfVertex(const TriMesh& mesh, std::span<const int> face_labels) {
  std::vector<int> ring1(mesh.n_vertices(), -1);
  for (const auto v : mesh.vertices()) {
    int r = -2;
    for (const auto f : mesh.vf_range(v)) {
      const int l = face_labels[f.idx()];
      if (r == -2) r = l;
      if (l != r || l < 0) {
        r = -1;
        break;
      }
    }
    ring1[v.idx()] = r < 0 ? -1 : r;
  }
  std::vector<int> ring2(mesh.n_vertices(), -1);
  for (const auto v : mesh.vertices()) {
    const int r = ring1[v.idx()];
    if (r < 0) continue;
    bool all = true;
    for (const auto w : mesh.vv_range(v)) all = all && ring1[w.idx()] == r;
    if (all) ring2[v.idx()] = r;
  }
  return ring2;
}

std::optional<SeparatingPlane> MaxMarginPlane(std::span<const Eigen::Vector3d> inside,
                                              std::span<const Eigen::Vector3d> outside,
                                              const Plane& start) {
  if (inside.empty() || outside.empty()) return std::nullopt;
  Eigen::Vector3d n0 = start.normal.normalized();
  // Orient to the air: the outside samples lie above the inside ones.
  double along = 0.0;
  for (const Eigen::Vector3d& b : outside) along += n0.dot(b);
  for (const Eigen::Vector3d& a : inside) along -= n0.dot(a);
  if (along < 0.0) n0 = -n0;
  const Eigen::Vector3d t1 = n0.unitOrthogonal(), t2 = n0.cross(t1);
  const double reach = std::tan(kMaxTurnDeg * std::numbers::pi / 180.0);
  const auto normal_at = [&](double u, double v) { return (n0 + u * t1 + v * t2).normalized(); };
  // The margin is the minimum of functions linear in (u, v) over |n|, so
  // concave near the start: a grid of 7 x 7 points around the best so far,
  // recentred on its best point and halved when the best is the centre,
  // climbs it down to 1e-7 radians.
  constexpr int kHalfGrid = 3;
  double u = 0.0, v = 0.0;
  double best = GapAlong(n0, inside, outside).margin;
  for (double step = reach / kHalfGrid; step > 1e-7;) {
    double bu = u, bv = v;
    for (int i = -kHalfGrid; i <= kHalfGrid; ++i) {
      for (int j = -kHalfGrid; j <= kHalfGrid; ++j) {
        const double cu = u + i * step, cv = v + j * step;
        if ((i == 0 && j == 0) || std::hypot(cu, cv) > reach) continue;
        const double m = GapAlong(normal_at(cu, cv), inside, outside).margin;
        if (m > best) best = m, bu = cu, bv = cv;
      }
    }
    if (bu == u && bv == v) {
      step *= 0.5;
    } else {
      u = bu, v = bv;
    }
  }
  if (!(best > 0.0)) return std::nullopt;
  const Eigen::Vector3d n = normal_at(u, v);
  const Gap gap = GapAlong(n, inside, outside);
  // The plane's point: the samples' centroid, projected onto it.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& a : inside) centroid += a;
  for (const Eigen::Vector3d& b : outside) centroid += b;
  centroid /= static_cast<double>(inside.size() + outside.size());
  const Eigen::Vector3d point = centroid - (n.dot(centroid) - gap.offset) * n;
  return SeparatingPlane{Plane{.point = point, .normal = n}, gap.margin};
}

void RefitPlanesBySeparation(const TriMesh& mesh, std::span<const int> face_labels,
                             const BinaryVertices& binary, std::vector<Region>* regions) {
  // Fewer samples than this say little about a plane's normal.
  constexpr std::size_t kMinSamples = 12;
  const std::vector<int> interior = InteriorRegionOfVertex(mesh, face_labels);
  std::vector<std::vector<Eigen::Vector3d>> inside(regions->size()), outside(regions->size());
  for (const auto v : mesh.vertices()) {
    const int r = interior[v.idx()];
    if (r < 0 || !std::holds_alternative<Plane>((*regions)[r].surface)) continue;
    inside[r].push_back(binary.inside[v.idx()]);
    outside[r].push_back(binary.outside[v.idx()]);
  }
  // All vertices of each region, for its distances.
  std::vector<std::vector<int>> members(regions->size());
  for (const auto f : mesh.faces()) {
    const int r = face_labels[f.idx()];
    if (r < 0 || inside[r].size() < kMinSamples) continue;
    for (const auto v : mesh.fv_range(f)) members[r].push_back(v.idx());
  }
  for (Region& region : *regions) {
    const auto* plane = std::get_if<Plane>(&region.surface);
    if (plane == nullptr || inside[region.id].size() < kMinSamples) continue;
    const std::optional<SeparatingPlane> separating =
        MaxMarginPlane(inside[region.id], outside[region.id], *plane);
    if (!separating) continue;
    // Keep the region's orientation of the normal.
    Plane fitted = separating->plane;
    if (fitted.normal.dot(plane->normal) < 0.0) fitted.normal = -fitted.normal;
    std::vector<int>& ids = members[region.id];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    double sum = 0.0, farthest = 0.0;
    for (const int id : ids) {
      const Eigen::Vector3d p = ToEigen(mesh.point(TriMesh::VertexHandle(id)));
      const double e = std::abs(fitted.normal.dot(p - fitted.point));
      sum += e * e;
      farthest = std::max(farthest, e);
    }
    region.surface = fitted;
    region.rms_distance = ids.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(ids.size()));
    region.max_distance = farthest;
  }
}

}  // namespace meshseg::pipeline_internal
