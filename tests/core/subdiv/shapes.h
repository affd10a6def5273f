// Generated smooth and creased bodies with known surfaces for the fit tests.
#ifndef MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_
#define MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "meshseg/mesh.h"
#include "meshseg/voxel.h"
#include "server/test_files.h"

namespace meshseg::testing {

struct Triangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
};

// The unit icosahedron split `levels` times at edge midpoints, on the unit
// sphere: 20 * 4^levels faces.
inline Triangles UnitIcosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Triangles m;
  m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : m.vertices) v.normalize();
  m.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = mid.try_emplace(key, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> faces;
    for (const auto& f : m.faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      faces.push_back({f[0], ab, ca});
      faces.push_back({f[1], bc, ab});
      faces.push_back({f[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.faces = std::move(faces);
  }
  return m;
}

// The superellipsoid |x|^p + |y|^p + |z|^p = r^p.
struct Superellipsoid {
  double r = 10.0;
  double p = 3.0;
  // (sum |x_i|^p)^(1/p): homogeneous of degree 1, = r on the surface.
  double Gauge(const Eigen::Vector3d& x) const {
    return std::pow(
        std::pow(std::abs(x.x()), p) + std::pow(std::abs(x.y()), p) + std::pow(std::abs(x.z()), p),
        1.0 / p);
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const {
    const double g = Gauge(x);
    Eigen::Vector3d d;
    for (int i = 0; i < 3; ++i) {
      d[i] = std::pow(std::abs(x[i]) / g, p - 1) * (x[i] < 0 ? -1.0 : 1.0);
    }
    return d;
  }
  // Signed distance to first order, (G - r) / |grad G|.
  double Distance(const Eigen::Vector3d& x) const { return (Gauge(x) - r) / Gradient(x).norm(); }
  Eigen::Vector3d Project(const Eigen::Vector3d& direction) const {
    return direction * (r / Gauge(direction));
  }
};

// Returns the mean edge length of `m`.
inline double MeanEdge(const Triangles& m) {
  double sum = 0.0;
  for (const auto& f : m.faces) {
    for (int i = 0; i < 3; ++i) sum += (m.vertices[f[i]] - m.vertices[f[(i + 1) % 3]]).norm();
  }
  return sum / (3.0 * m.faces.size());
}

// Moves each vertex along `normal(v)` by Gaussian noise of deviation sigma.
template <class Normal>
void AddNoise(Triangles& m, double sigma, Normal normal, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& v : m.vertices) v += noise(rng) * normal(v).normalized();
}

// The superellipsoid `shape` at the vertices of UnitIcosphere(levels), moved
// along its normal by Gaussian noise of noise_in_h times the mean edge h.
struct NoisySample {
  Triangles mesh;
  double h = 0.0;
  double sigma = 0.0;
};
inline NoisySample NoisySuperellipsoid(const Superellipsoid& shape, int levels, double noise_in_h,
                                       unsigned seed) {
  NoisySample out{UnitIcosphere(levels)};
  for (auto& v : out.mesh.vertices) v = shape.Project(v);
  out.h = MeanEdge(out.mesh);
  out.sigma = noise_in_h * out.h;
  AddNoise(out.mesh, out.sigma, [&](const Eigen::Vector3d& p) { return shape.Gradient(p); }, seed);
  return out;
}

// A cube [-s, s]^3, each side an n x n grid of squares split along a
// diagonal (the service tests' SplitBox, centred).
inline Triangles Cube(double s, int n) {
  const testing_files::TestMesh box = testing_files::SplitBox(n, Eigen::Vector3d::Constant(2 * s));
  Triangles m{box.v, box.f};
  for (auto& v : m.vertices) v -= Eigen::Vector3d::Constant(s);
  return m;
}

// Distance from p to the surface of the cube [-s, s]^3.
inline double CubeDistance(const Eigen::Vector3d& p, double s) {
  const Eigen::Vector3d q = p.cwiseAbs() - Eigen::Vector3d::Constant(s);
  const double outside = q.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : -q.maxCoeff();
}

// A tube of radius `a` around the (2, 3) torus knot of scale `scale`:
// c(t) = scale ((2 + cos 3t) cos 2t, (2 + cos 3t) sin 2t, sin 3t), a
// trefoil of length 31.9 scale; its strands pass at least 1.66 scale apart
// and it bends at radii of at least 1.43 scale (measured on 1500 samples),
// so a < 0.8 scale keeps the tube embedded.
struct KnotTube {
  double scale = 2.0;
  double a = 1.0;
  Eigen::Vector3d Curve(double t) const {
    const double w = 2.0 + std::cos(3 * t);
    return scale * Eigen::Vector3d(w * std::cos(2 * t), w * std::sin(2 * t), std::sin(3 * t));
  }
  Eigen::Vector3d Tangent(double t) const {
    const double w = 2.0 + std::cos(3 * t), dw = -3.0 * std::sin(3 * t);
    return Eigen::Vector3d(dw * std::cos(2 * t) - 2 * w * std::sin(2 * t),
                           dw * std::sin(2 * t) + 2 * w * std::cos(2 * t), 3 * std::cos(3 * t))
        .normalized();
  }
  // The tube as a grid of `along` x `around` quads split along a diagonal,
  // each vertex moved along the tube's normal by Gaussian noise of deviation
  // sigma. The frame (z x T, T x (z x T)) is a function of t, so the grid
  // closes; a point at distance a from c(t) in its normal plane is on the
  // tube, with the normal cos(phi) u + sin(phi) v.
  Triangles Mesh(int along, int around, double sigma, unsigned seed) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    Triangles m;
    for (int i = 0; i < along; ++i) {
      const double t = 2 * M_PI * i / along;
      const Eigen::Vector3d tan = Tangent(t);
      const Eigen::Vector3d u = Eigen::Vector3d::UnitZ().cross(tan).normalized();
      const Eigen::Vector3d v = tan.cross(u);
      for (int j = 0; j < around; ++j) {
        const double phi = 2 * M_PI * j / around;
        const Eigen::Vector3d n = std::cos(phi) * u + std::sin(phi) * v;
        m.vertices.push_back(Curve(t) + (a + noise(rng)) * n);
      }
    }
    for (int i = 0; i < along; ++i) {
      for (int j = 0; j < around; ++j) {
        const int i1 = (i + 1) % along, j1 = (j + 1) % around;
        const int p = i * around + j, q = i * around + j1, r = i1 * around + j,
                  s = i1 * around + j1;
        m.faces.push_back({p, r, q});
        m.faces.push_back({q, r, s});
      }
    }
    return m;
  }
  // Distance from x to the tube's centre line minus a: the closest curve
  // parameter by a dense scan, refined by Newton steps on |c(t) - x|^2.
  double Distance(const Eigen::Vector3d& x) const {
    double best_t = 0.0, best = 1e300;
    for (int k = 0; k < 500; ++k) {  // 0.13 scale apart, strands 1.66 scale
      const double t = 2 * M_PI * k / 500;
      const double d = (Curve(t) - x).squaredNorm();
      if (d < best) best = d, best_t = t;
    }
    double t = best_t;
    for (int it = 0; it < 20; ++it) {
      const double e = 1e-6;
      const double f0 = (Curve(t - e) - x).squaredNorm(), f1 = (Curve(t) - x).squaredNorm(),
                   f2 = (Curve(t + e) - x).squaredNorm();
      const double g = (f2 - f0) / (2 * e), hh = (f2 - 2 * f1 + f0) / (e * e);
      if (hh <= 0) break;
      t -= g / hh;
    }
    return (Curve(t) - x).norm() - a;
  }
};

// Two bodies meeting in sharp creases: the superellipsoid |x|^3 + |y|^3 +
// |z|^3 = 10^3 unioned with the capped cylinder x^2 + y^2 <= 4^2, 0 <= z <=
// 14, which leaves it through the top. Creases: the concave curve where the
// cylinder meets the superellipsoid (normals about 60-90 degrees apart) and
// the convex rim of the cap (90 degrees).
struct BlendedBody {
  Superellipsoid body;
  double rho = 4.0;
  double top = 14.0;
  double Cylinder(const Eigen::Vector3d& x) const {  // signed distance
    const double dxy = std::hypot(x.x(), x.y()) - rho;
    const double dz = std::max(-x.z(), x.z() - top);
    return std::hypot(std::max(dxy, 0.0), std::max(dz, 0.0)) + std::min(std::max(dxy, dz), 0.0);
  }
  // Signed distance to the union (first order on the superellipsoid).
  double Distance(const Eigen::Vector3d& x) const {
    return std::min(body.Distance(x), Cylinder(x));
  }
  Eigen::Vector3d Normal(const Eigen::Vector3d& x) const {
    Eigen::Vector3d g;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d[i] = 1e-6;
      g[i] = Distance(x + d) - Distance(x - d);
    }
    return g.normalized();
  }
  // Marching cubes on a grid of step h (vertices placed on the surface by
  // bisection along their grid edge), then Gaussian noise of deviation sigma
  // along the normal.
  Triangles Mesh(double h, double sigma, unsigned seed) const {
    // min(G - r, cylinder) has the union's sign and zero set, and no
    // singularity at the origin as the normalised distance has.
    auto field = [this](const Eigen::Vector3d& x) {
      return std::min(body.Gauge(x) - body.r, Cylinder(x));
    };
    const Eigen::Vector3d origin(-11.0, -11.0, -11.0);
    SampledField grid;
    grid.dims = {static_cast<int>(22.0 / h) + 1, static_cast<int>(22.0 / h) + 1,
                 static_cast<int>(26.0 / h) + 1};
    auto at = [&](int i, int j, int k) -> Eigen::Vector3d {
      return origin + h * Eigen::Vector3d(i, j, k);
    };
    grid.slice = [&](int k, std::vector<double>& values) {
      values.resize(static_cast<size_t>(grid.dims[0]) * grid.dims[1]);
      for (int j = 0; j < grid.dims[1]; ++j) {
        for (int i = 0; i < grid.dims[0]; ++i) values[j * grid.dims[0] + i] = field(at(i, j, k));
      }
      return absl::OkStatus();
    };
    grid.edge_vertex = [&](int i, int j, int k, int axis, double fa, double) {
      Eigen::Vector3d lo = at(i, j, k), hi = lo;
      hi[axis] += h;
      for (int it = 0; it < 50; ++it) {
        const Eigen::Vector3d mid = 0.5 * (lo + hi);
        ((field(mid) < 0) == (fa < 0) ? lo : hi) = mid;
      }
      return SampledField::Vertex{0.5 * (lo + hi)};
    };
    const absl::StatusOr<IsoSurface> iso = MarchingCubes(grid);
    Triangles m;
    if (!iso.ok()) {
      ADD_FAILURE() << iso.status();
      return m;
    }
    m.vertices = iso->vertices;
    m.faces = iso->triangles;
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (auto& v : m.vertices) v += noise(rng) * Normal(v);
    return m;
  }
};

inline absl::StatusOr<Mesh> ToMesh(const Triangles& t, std::string name) {
  return BuildMesh(t.vertices, t.faces, std::move(name));
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_SUBDIV_SHAPES_H_
