#include "reconstruct/support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::reconstruct_internal {
namespace {

// Points whose second principal spread is under this fraction of the first
// lie along a line (a single row of samples) and span no plane.
constexpr double kMinSpread = 0.01;

// Whether the points `near` (each with its squared distance to c) leave an
// angular gap over π around c in their least-squares plane (in the plane
// normal to `normal`, unit, when they lie along a line and span no plane):
// c lies beyond the border of the sampled area.
bool BeyondSampledBorder(const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                         const std::vector<Eigen::Vector3d>& points,
                         const std::vector<std::pair<uint32_t, double>>& near,
                         std::vector<double>* angles) {
  if (near.size() < 3) return true;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& [j, unused] : near) mean += points[j];
  mean /= static_cast<double>(near.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& [j, unused] : near) {
    const Eigen::Vector3d d = points[j] - mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  Eigen::Vector3d u = eigen.eigenvectors().col(2), v = eigen.eigenvectors().col(1);
  if (!(eigen.eigenvalues()[1] > kMinSpread * eigen.eigenvalues()[2])) {
    u = normal.unitOrthogonal();
    v = normal.cross(u);
  }
  angles->clear();
  for (const auto& [j, unused] : near) {
    const Eigen::Vector3d d = points[j] - c;
    const double x = d.dot(u), y = d.dot(v);
    if (x * x + y * y > 0) angles->push_back(std::atan2(y, x));
  }
  if (angles->size() < 3) return true;
  std::sort(angles->begin(), angles->end());
  double gap = angles->front() + 2.0 * M_PI - angles->back();
  for (size_t k = 1; k < angles->size(); ++k) gap = std::max(gap, (*angles)[k] - (*angles)[k - 1]);
  return gap > M_PI;
}

// Area-weighted unit vertex normals of `tri` (zero at a vertex with no area).
std::vector<Eigen::Vector3d> VertexNormals(const TriMesh& tri) {
  std::vector<Eigen::Vector3d> normal(tri.n_vertices(), Eigen::Vector3d::Zero());
  for (const auto f : tri.faces()) {
    std::array<int, 3> v;
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for (const auto u : tri.fv_range(f)) {
      v[k] = u.idx();
      c[k++] = ToEigen(tri.point(u));
    }
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
    for (const int u : v) normal[u] += n;
  }
  for (Eigen::Vector3d& n : normal) {
    if (n.norm() > 0) n.normalize();
  }
  return normal;
}

// Whether `q` lies within `spacings` × s + `band` of its nearest point, s
// measured at that point.
bool NearPoints(const Eigen::Vector3d& q, const std::vector<Eigen::Vector3d>& points,
                const mesh_internal::PointIndex& index, double spacings, double band,
                std::vector<uint32_t>* near, std::vector<double>* dist2) {
  const Eigen::Vector3d& p = points[index.Closest(q)];
  return (q - p).norm() <= spacings * SpacingAtPoint(p, index, near, dist2) + band;
}

}  // namespace

double ChordError(const std::array<Eigen::Vector3d, 3>& corner,
                  const std::array<Eigen::Vector3d, 3>& normal) {
  const Eigen::Vector3d centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
  double error = 0.0;
  for (int k = 0; k < 3; ++k) {
    error = std::max(error, std::abs((centroid - corner[k]).dot(normal[k])));
  }
  return error;
}

double SpacingAtPoint(const Eigen::Vector3d& p, const mesh_internal::PointIndex& index,
                      std::vector<uint32_t>* near, std::vector<double>* dist2) {
  // p finds itself first.
  index.Nearest(p, kSpacingNeighbors + 1, near, dist2);
  double s = 0.0;
  for (size_t k = 1; k < dist2->size(); ++k) s += std::sqrt((*dist2)[k]);
  if (dist2->size() > 1) s /= static_cast<double>(dist2->size() - 1);
  return s;
}

std::vector<uint8_t> SupportedFaces(const TriMesh& tri, const std::vector<Eigen::Vector3d>& points,
                                    const mesh_internal::PointIndex& index, double spacings,
                                    double band, double max_chord_edge) {
  std::vector<uint8_t> supported(tri.n_faces(), 0);
  // The chord error needs the vertex normals; without a resolution to allow
  // it at (max_chord_edge 0) no face gains, and they are not computed.
  const std::vector<Eigen::Vector3d> vertex_normal =
      max_chord_edge > 0 ? VertexNormals(tri) : std::vector<Eigen::Vector3d>{};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tri.n_faces()), [&](const auto& range) {
    std::vector<uint32_t> near;
    std::vector<double> dist2;
    std::vector<std::pair<uint32_t, double>> around;
    std::vector<double> angles;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const TriMesh::FaceHandle f(static_cast<int>(i));
      std::array<Eigen::Vector3d, 3> corner, corner_normal;
      int k = 0;
      for (const auto v : tri.fv_range(f)) {
        if (!vertex_normal.empty()) corner_normal[k] = vertex_normal[v.idx()];
        corner[k++] = ToEigen(tri.point(v));
      }
      const Eigen::Vector3d centroid = (corner[0] + corner[1] + corner[2]) / 3.0;
      const Eigen::Vector3d& p = points[index.Closest(centroid)];
      const Eigen::Vector3d offset = centroid - p;
      const double s = SpacingAtPoint(p, index, &near, &dist2);
      double reach = spacings * s + band;
      if (!(offset.norm() <= reach)) {
        // A face on the points chords the surface: allow for its own chord
        // error, but only when it is no longer than the mesh's resolution (a
        // tent is not) and its corners are on the points (a flap into empty
        // space has corners off them).
        const double longest = std::max({(corner[1] - corner[0]).norm(),
                                         (corner[2] - corner[1]).norm(),
                                         (corner[0] - corner[2]).norm()});
        if (!(max_chord_edge > 0 && longest <= max_chord_edge)) continue;
        const bool corners_near = std::all_of(corner.begin(), corner.end(), [&](const auto& c) {
          return NearPoints(c, points, index, spacings, band, &near, &dist2);
        });
        if (!corners_near) continue;
        reach += ChordError(corner, corner_normal);
        if (!(offset.norm() <= reach)) continue;
      }
      // Along the surface: across the face's normal (a sliver's normal is
      // noise, but its centroid is then near a point anyway or tested below).
      const Eigen::Vector3d normal = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
      const double along =
          normal.norm() > 0 ? (offset - offset.dot(normal) / normal.squaredNorm() * normal).norm()
                            : offset.norm();
      if (along <= kBorderSpacings * s) {
        supported[i] = 1;
        continue;
      }
      // A gap the support bridges from both sides (up to 2 reaches wide) is
      // inside the sampled area: look for points across it that far (first
      // within one reach, which surrounds almost every centroid inside).
      const Eigen::Vector3d n = normal.norm() > 0 ? normal.normalized() : Eigen::Vector3d::UnitZ();
      index.WithinRadiusUnordered(centroid, reach, &around);
      if (!BeyondSampledBorder(centroid, n, points, around, &angles)) {
        supported[i] = 1;
        continue;
      }
      index.WithinRadiusUnordered(centroid, 2.0 * reach, &around);
      supported[i] = !BeyondSampledBorder(centroid, n, points, around, &angles);
    }
  });
  return supported;
}

}  // namespace meshseg::reconstruct_internal
