#include "pipeline/point_labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "mesh/point_index.h"
#include "meshseg/fit.h"
#include "meshseg/voxel.h"

namespace meshseg::pipeline_internal {
namespace {

// The label of the face of `mesh` nearest to `p` among the faces around
// vertex `nearest` (-1 if it has none).
int NearestFaceLabel(const TriMesh& mesh, std::span<const int> face_labels, uint32_t nearest,
                     const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  int label = -1;
  for (auto f = mesh.cvf_iter(TriMesh::VertexHandle(static_cast<int>(nearest))); f.is_valid();
       ++f) {
    auto v = mesh.cfv_iter(*f);
    const Eigen::Vector3d a = ToEigen(mesh.point(*v));
    const Eigen::Vector3d b = ToEigen(mesh.point(*++v));
    const Eigen::Vector3d c = ToEigen(mesh.point(*++v));
    const double d = SquaredDistanceToTriangle(p, a, b, c);
    if (d < best) {
      best = d;
      label = face_labels[f->idx()];
    }
  }
  return label;
}

bool Trusted(const Region& r, const SurfaceLabelParams& params) {
  const bool analytic = r.type == SurfaceType::kPlane || r.type == SurfaceType::kCylinder ||
                        r.type == SurfaceType::kCone || r.type == SurfaceType::kSphere ||
                        r.type == SurfaceType::kTorus;
  return analytic && params.trusted[r.id] != 0;
}

// The region among those of the faces within two rings of `nearest` whose
// surface is nearest to `p`; `label` (the nearest face's) wins ties and
// stays when it is not Trusted or within keep_distance of its surface.
int NearestSurfaceLabel(const TriMesh& mesh, std::span<const int> face_labels,
                        std::span<const Region> regions, const SurfaceLabelParams& params,
                        uint32_t nearest, const Eigen::Vector3d& p, int label) {
  if (!Trusted(regions[label], params)) return label;
  double best = std::abs(SignedDistance(regions[label].surface, p));
  if (!(best > params.keep_distance)) return label;
  std::vector<int> candidates;
  const auto add_faces_of = [&](TriMesh::VertexHandle v) {
    for (auto f = mesh.cvf_iter(v); f.is_valid(); ++f) {
      const int l = face_labels[f->idx()];
      if (l >= 0 && l != label && Trusted(regions[l], params) &&
          std::find(candidates.begin(), candidates.end(), l) == candidates.end()) {
        candidates.push_back(l);
      }
    }
  };
  const TriMesh::VertexHandle centre(static_cast<int>(nearest));
  add_faces_of(centre);
  for (auto v = mesh.cvv_iter(centre); v.is_valid(); ++v) add_faces_of(*v);
  for (const int l : candidates) {
    const double d = std::abs(SignedDistance(regions[l].surface, p));
    if (d < best) best = d, label = l;  // NaN never wins
  }
  return label;
}

}  // namespace

std::vector<int> PointLabels(const TriMesh& mesh, std::span<const int> face_labels,
                             std::span<const Eigen::Vector3d> points,
                             std::span<const uint8_t> is_outlier) {
  return PointLabelsBySurface(mesh, face_labels, {}, {}, points, is_outlier);
}

std::vector<int> PointLabelsBySurface(const TriMesh& mesh, std::span<const int> face_labels,
                                      std::span<const Region> regions,
                                      const SurfaceLabelParams& params,
                                      std::span<const Eigen::Vector3d> points,
                                      std::span<const uint8_t> is_outlier) {
  std::vector<int> labels(points.size(), -1);
  if (mesh.n_vertices() == 0) return labels;
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) vertices.push_back(ToEigen(mesh.point(v)));
  const mesh_internal::PointIndex index(vertices);
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t k) {
    if (!is_outlier.empty() && is_outlier[k]) return;
    const uint32_t nearest = index.Closest(points[k]);
    labels[k] = NearestFaceLabel(mesh, face_labels, nearest, points[k]);
    if (!regions.empty() && !params.trusted.empty() && labels[k] >= 0) {
      labels[k] =
          NearestSurfaceLabel(mesh, face_labels, regions, params, nearest, points[k], labels[k]);
    }
  });
  return labels;
}

}  // namespace meshseg::pipeline_internal
