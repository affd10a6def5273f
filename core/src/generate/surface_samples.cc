// SampleSurface: points uniform by area on a generated part's exact
// primitives (generate.h).
#include <Eigen/Geometry>
#include <array>
#include <random>

#include "meshseg/fit.h"
#include "meshseg/generate.h"

namespace meshseg {

SurfaceSamples SampleSurface(const GeneratedPart& part, int64_t count, uint64_t seed) {
  const TriMesh& m = part.mesh.tri;
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> area;
  triangles.reserve(m.n_faces());
  for (const auto f : m.faces()) {
    std::array<Eigen::Vector3d, 3> t;
    int i = 0;
    for (const auto v : f.vertices()) t[i++] = ToEigen(m.point(v));
    const Eigen::Vector3d cross = (t[1] - t[0]).cross(t[2] - t[0]);
    triangles.push_back(t);
    normals.push_back(cross.normalized());
    area.push_back(0.5 * cross.norm());
  }
  std::mt19937_64 rng(seed);
  std::discrete_distribution<size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  SurfaceSamples out;
  out.points.reserve(count);
  out.normals.reserve(count);
  out.primitive.reserve(count);
  for (int64_t k = 0; k < count; ++k) {
    const size_t f = pick(rng);
    const auto& t = triangles[f];
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    Eigen::Vector3d p = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
    Eigen::Vector3d n = normals[f];
    const int primitive = part.face_primitive[f];
    if (primitive >= 0) {
      const Projection foot = Project(part.primitives[primitive].surface, p, n);
      p = foot.point;
      n = foot.normal.dot(n) >= 0 ? foot.normal : Eigen::Vector3d(-foot.normal);
    }
    out.points.push_back(p);
    out.normals.push_back(n);
    out.primitive.push_back(primitive);
  }
  return out;
}

}  // namespace meshseg
