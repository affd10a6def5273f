// Clouds sampled from the generated test parts (meshseg/generate.h), for the
// reconstruct and pipeline tests: a Shape of clouds.h whose samples lie on the
// part's exact ground-truth primitives (with their outward normals) and whose
// signed distance is measured to those primitives, so MakeCloud, Spacing and
// FractionWithin work on a part as on the analytic sphere, box and torus.
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_PART_CLOUDS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_PART_CLOUDS_H_

#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "clouds.h"
#include "meshseg/fit.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "mesh/point_index.h"

namespace meshseg::test {

namespace part_clouds_internal {

// What the Shape's functions read: a copy of the part's mesh and truth, so
// the Shape does not depend on the GeneratedPart's lifetime.
struct PartTruth {
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;  // outward (marching cubes)
  std::vector<Eigen::Vector3d> face_normals;
  std::vector<int> face_primitive;
  std::discrete_distribution<size_t> pick_face;  // by area
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3d> vertex_normals;  // outward
  std::vector<int> vertex_primitive;
  std::vector<Surface> surfaces;                                   // by primitive id
  std::unique_ptr<mesh_internal::PointIndex> vertex_index;         // over `vertices`
};

}  // namespace part_clouds_internal

// Returns the Shape of `part`'s true surface.
// sample: a point uniform by area on the part's mesh, moved to the closest
// point of the exact primitive of its face, with that primitive's normal
// turned outward (faces without a primitive keep the mesh point and normal).
// sdf: the signed distance (negative inside) to the exact primitive of the
// nearest mesh vertex. Exact except within about a voxel of the part's edges,
// where it may measure to the adjacent face's primitive, whose extension
// passes closer than its patch outside a convex edge (an underestimate there).
inline Shape PartShape(const GeneratedPart& part) {
  auto t = std::make_shared<part_clouds_internal::PartTruth>();
  const TriMesh& m = part.mesh.tri;
  std::vector<double> area;
  for (const auto f : m.faces()) {
    std::array<Eigen::Vector3d, 3> tri;
    int i = 0;
    for (const auto v : f.vertices()) tri[i++] = ToEigen(m.point(v));
    const Eigen::Vector3d cross = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
    t->triangles.push_back(tri);
    t->face_normals.push_back(cross.normalized());
    area.push_back(0.5 * cross.norm());
  }
  t->pick_face = std::discrete_distribution<size_t>(area.begin(), area.end());
  t->face_primitive = part.face_primitive;
  t->vertex_normals.assign(m.n_vertices(), Eigen::Vector3d::Zero());
  for (const auto v : m.vertices()) t->vertices.push_back(ToEigen(m.point(v)));
  for (const auto f : m.faces()) {
    for (const auto v : f.vertices())
      t->vertex_normals[v.idx()] += area[f.idx()] * t->face_normals[f.idx()];
  }
  for (auto& n : t->vertex_normals) n.normalize();
  t->vertex_primitive = part.vertex_primitive;
  for (const PrimitiveTruth& p : part.primitives) t->surfaces.push_back(p.surface);
  t->vertex_index = std::make_unique<mesh_internal::PointIndex>(t->vertices);

  Shape s;
  s.area = 0.0;
  for (const double a : area) s.area += a;
  s.sample = [t](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const size_t f = t->pick_face(rng);
    const auto& tri = t->triangles[f];
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    *p = tri[0] + a * (tri[1] - tri[0]) + b * (tri[2] - tri[0]);
    *n = t->face_normals[f];
    if (t->face_primitive[f] < 0) return;
    const Projection foot = Project(t->surfaces[t->face_primitive[f]], *p, *n);
    *p = foot.point;
    *n = foot.normal.dot(*n) >= 0 ? foot.normal : Eigen::Vector3d(-foot.normal);
  };
  s.sdf = [t](const Eigen::Vector3d& q) {
    std::vector<uint32_t> nearest;
    std::vector<double> dist2;
    t->vertex_index->Nearest(q, 1, &nearest, &dist2);
    const uint32_t v = nearest[0];
    const Eigen::Vector3d& n = t->vertex_normals[v];
    if (t->vertex_primitive[v] < 0) return (q - t->vertices[v]).dot(n);
    const Projection foot = Project(t->surfaces[t->vertex_primitive[v]], q, n);
    return foot.normal.dot(n) >= 0 ? foot.distance : -foot.distance;
  };
  return s;
}

// Returns the vertex of primitive `name` nearest the centroid of its
// vertices: a point on that face, e.g. the centre of a missing patch.
inline Eigen::Vector3d PrimitiveCenter(const GeneratedPart& part, std::string_view name) {
  int id = -1;
  for (const PrimitiveTruth& p : part.primitives) {
    if (p.name == name) id = p.id;
  }
  const TriMesh& m = part.mesh.tri;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (const auto v : m.vertices()) {
    if (part.vertex_primitive[v.idx()] != id) continue;
    sum += ToEigen(m.point(v));
    ++count;
  }
  const Eigen::Vector3d centroid = sum / std::max(count, 1);
  Eigen::Vector3d best = centroid;
  double best_d = 1e300;
  for (const auto v : m.vertices()) {
    if (part.vertex_primitive[v.idx()] != id) continue;
    const double d = (ToEigen(m.point(v)) - centroid).norm();
    if (d < best_d) best_d = d, best = ToEigen(m.point(v));
  }
  return best;
}

// Returns, per point, the primitive of the part's mesh vertex nearest to it
// (-1 where that vertex has none): the face a cloud point was sampled from,
// except within about a voxel of the part's edges.
inline std::vector<int> NearestPrimitive(const GeneratedPart& part,
                                         const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> vertices;
  for (const auto v : part.mesh.tri.vertices()) vertices.push_back(ToEigen(part.mesh.tri.point(v)));
  const mesh_internal::PointIndex index(vertices);
  std::vector<int> out;
  std::vector<uint32_t> nearest;
  std::vector<double> dist2;
  for (const Eigen::Vector3d& p : points) {
    index.Nearest(p, 1, &nearest, &dist2);
    out.push_back(part.vertex_primitive[nearest[0]]);
  }
  return out;
}

}  // namespace meshseg::test

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_PART_CLOUDS_H_
