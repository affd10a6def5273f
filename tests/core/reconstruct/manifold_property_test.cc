// Property test of Reconstruct (issue 38, "manifold and watertight always"):
// many small random clouds of the shapes that stress the inside/outside
// labels and the refinement (smooth blobs, thin plates, close parallel
// sheets, touching bodies, clouds with outliers and noise) all come out as a
// closed, consistently oriented 2-manifold: every edge has exactly two faces,
// the faces around every vertex form one fan, no face has zero area. The
// checks run on the plain face list, so they do not depend on what a
// half-edge structure can represent. The million-point case is a benchmark
// (bench/reconstruct/reconstruct_timing with `meshseg generate
// --surface-points`).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "clouds.h"
#include "meshseg/reconstruct.h"

namespace meshseg {
namespace {

using test::CloudSpec;
using test::Shape;

// What is wrong with a triangle list as a closed oriented 2-manifold; empty
// if nothing is.
struct Defects {
  int64_t open_edges = 0;             // undirected edges with one face
  int64_t non_manifold_edges = 0;     // undirected edges with three or more faces
  int64_t misoriented_edges = 0;      // two faces traverse the edge the same way
  int64_t non_manifold_vertices = 0;  // faces around the vertex form several fans
  int64_t degenerate_faces = 0;       // repeated corner or zero area
  std::string Describe() const {
    return absl::StrCat("open edges ", open_edges, ", non-manifold edges ", non_manifold_edges,
                        ", misoriented edges ", misoriented_edges, ", non-manifold vertices ",
                        non_manifold_vertices, ", degenerate faces ", degenerate_faces);
  }
  bool None() const {
    return open_edges + non_manifold_edges + misoriented_edges + non_manifold_vertices +
               degenerate_faces ==
           0;
  }
};

using Faces = std::vector<std::array<int, 3>>;

Faces FaceList(const TriMesh& m) {
  Faces faces;
  for (const auto f : m.faces()) {
    std::array<int, 3> t{};
    int i = 0;
    for (const auto v : f.vertices()) t[i++] = v.idx();
    faces.push_back(t);
  }
  return faces;
}

std::vector<Eigen::Vector3d> Positions(const TriMesh& m) {
  std::vector<Eigen::Vector3d> p;
  for (const auto v : m.vertices()) p.push_back(ToEigen(m.point(v)));
  return p;
}

Defects FindDefects(const Faces& faces, const std::vector<Eigen::Vector3d>& position) {
  Defects d;
  std::map<std::pair<int, int>, int> directed;                          // (from, to) -> count
  std::vector<std::vector<std::pair<int, int>>> link(position.size());  // opposite edge per face
  for (const auto& t : faces) {
    const Eigen::Vector3d& a = position[t[0]];
    const Eigen::Vector3d& b = position[t[1]];
    const Eigen::Vector3d& c = position[t[2]];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || (b - a).cross(c - a).norm() == 0.0) {
      ++d.degenerate_faces;
    }
    for (int k = 0; k < 3; ++k) {
      ++directed[{t[k], t[(k + 1) % 3]}];
      link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    }
  }
  std::map<std::pair<int, int>, std::pair<int, int>> undirected;  // -> (faces, same-way pairs)
  for (const auto& [e, count] : directed) {
    auto& u = undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}];
    u.first += count;
    u.second += count > 1;
  }
  for (const auto& [e, u] : undirected) {
    d.open_edges += u.first == 1;
    d.non_manifold_edges += u.first > 2;
    d.misoriented_edges += u.first == 2 && u.second > 0;
  }
  // A manifold vertex's link (the edges opposite it) is one closed cycle.
  for (const auto& edges : link) {
    if (edges.empty()) continue;
    std::map<int, int> next;
    for (const auto& [from, to] : edges) next[from] = to;
    if (next.size() != edges.size()) {
      ++d.non_manifold_vertices;
      continue;
    }
    size_t walked = 0;
    int at = edges[0].first;
    do {
      const auto it = next.find(at);
      if (it == next.end()) break;
      at = it->second;
      ++walked;
    } while (at != edges[0].first && walked <= edges.size());
    d.non_manifold_vertices += walked != edges.size() || at != edges[0].first;
  }
  return d;
}

// Samples of the union of `parts`: each part's surface points that lie
// outside every other part (sdf > 0), so the cloud has no points inside the
// solid, as a scan of bodies touching each other has none.
Shape Union(std::vector<Shape> parts) {
  Shape s;
  s.sdf = [parts](const Eigen::Vector3d& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& part : parts) d = std::min(d, part.sdf(p));
    return d;
  };
  double area = 0.0;
  std::vector<double> weights;
  for (const auto& part : parts) {
    area += part.area;
    weights.push_back(part.area);
  }
  s.area = area;
  s.sample = [parts, weights](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::discrete_distribution<int> pick(weights.begin(), weights.end());
    for (;;) {
      const int i = pick(rng);
      parts[i].sample(rng, p, n);
      bool outside = true;
      for (size_t j = 0; j < parts.size(); ++j) {
        if (static_cast<int>(j) != i && parts[j].sdf(*p) <= 0.0) outside = false;
      }
      if (outside) return;
    }
  };
  return s;
}

Shape Translated(Shape shape, const Eigen::Vector3d& offset) {
  Shape s = shape;
  s.sdf = [shape, offset](const Eigen::Vector3d& p) { return shape.sdf(p - offset); };
  s.sample = [shape, offset](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    shape.sample(rng, p, n);
    *p += offset;
  };
  return s;
}

// A star-shaped blob: the unit sphere with its radius modulated by three
// random low-frequency waves of amplitude up to 0.25 in all. Surface samples
// are the sphere's, pushed out radially (density varies with the stretch, as
// a scan's does); normals from the gradient of |p| − r(p / |p|).
Shape Blob(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Eigen::Vector3d, 3> k;
  std::array<double, 3> phase{}, amp{};
  for (int i = 0; i < 3; ++i) {
    k[i] = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 3.0;
    phase[i] = u(rng) * M_PI;
    amp[i] = 0.08 * std::abs(u(rng));
  }
  const auto radius = [k, phase, amp](const Eigen::Vector3d& dir) {
    double r = 1.0;
    for (int i = 0; i < 3; ++i) r += amp[i] * std::sin(k[i].dot(dir) + phase[i]);
    return r;
  };
  const auto f = [radius](const Eigen::Vector3d& p) { return p.norm() - radius(p.normalized()); };
  Shape s;
  s.sdf = f;
  s.sample = [radius, f](std::mt19937& rng, Eigen::Vector3d* p, Eigen::Vector3d* n) {
    std::normal_distribution<double> g;
    const Eigen::Vector3d dir = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    *p = radius(dir) * dir;
    constexpr double kStep = 1e-5;
    Eigen::Vector3d grad;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d e = kStep * Eigen::Vector3d::Unit(a);
      grad[a] = f(*p + e) - f(*p - e);
    }
    *n = grad.normalized();
  };
  s.area = 4.0 * M_PI * 1.1;  // about; only sets the nominal spacing
  return s;
}

struct Case {
  std::string name;
  Shape shape;
  CloudSpec spec;
  // The union is one closed surface of genus 0 (one component, Euler
  // characteristic 2); checked where the reconstruction is known to get the
  // topology right. Thin plates (fragments and holes at 3-6 spacings thick),
  // 5 % uniform outliers with noise 0.3 spacings (a handle on one draw in
  // two) and ghost sheets (handles to the stray clumps) are issue 38's open
  // "no handle the points do not support"; only the manifold property is
  // checked on them here.
  bool sphere_like = false;
};

constexpr int kPoints = 2500;

// Random cases from `seed`: each draws its shape's sizes and its noise.
std::vector<Case> Cases(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Case> out;
  const auto spec = [&](double noise, double outliers) {
    CloudSpec c;
    c.points = kPoints;
    c.noise = noise;
    c.outliers = outliers;
    c.normals = u(rng) < 0.5;
    c.seed = rng();
    return c;
  };
  out.push_back({"blob", Blob(rng), spec(0.2 * u(rng), 0.0), true});
  {
    // A plate 3-5 nominal spacings thick, 1.5-2.5 leaf cells of the octree
    // (ReconstructParams::leaf_cell_size): both faces within one support.
    const Eigen::Vector3d half(1.0, 0.6 + 0.4 * u(rng), 0.0);
    const double h = std::sqrt(8.0 * half.x() * half.y() / kPoints);
    Eigen::Vector3d plate = half;
    plate.z() = (1.5 + u(rng)) * h;
    out.push_back({"thin plate", test::Box(plate), spec(0.1 * u(rng), 0.0), false});
  }
  {
    // Two plates 2-4 spacings apart: the gap is as thin as the plates.
    const Eigen::Vector3d half(1.0, 0.7, 0.0);
    const double h = std::sqrt(16.0 * half.x() * half.y() / kPoints);
    Eigen::Vector3d plate = half;
    plate.z() = (1.0 + u(rng)) * h;
    const double gap = (2.0 + 2.0 * u(rng)) * h;
    const Eigen::Vector3d up(0, 0, plate.z() + 0.5 * gap);
    out.push_back({"close sheets",
                   Union({Translated(test::Box(plate), up), Translated(test::Box(plate), -up)}),
                   spec(0.1 * u(rng), 0.0), false});
  }
  {
    // A box standing on a larger one, face to face: their union.
    const Eigen::Vector3d base(1.0, 0.8, 0.3), top(0.4 + 0.2 * u(rng), 0.4, 0.3);
    const Eigen::Vector3d shift(0.3 * u(rng), 0.2 * u(rng), base.z() + top.z());
    out.push_back({"touching boxes", Union({test::Box(base), Translated(test::Box(top), shift)}),
                   spec(0.1 * u(rng), 0.0), true});
  }
  {
    // Two spheres overlapping by a few spacings.
    const double r = 0.5 + 0.3 * u(rng);
    const Eigen::Vector3d c(0.0, 0.0, 1.0 + r - 0.1);
    out.push_back({"touching spheres", Union({test::Sphere(1.0), Translated(test::Sphere(r), c)}),
                   spec(0.1 * u(rng), 0.0), true});
  }
  out.push_back({"outliers", test::Box({1.0, 0.5 + 0.5 * u(rng), 0.4}), spec(0.3, 0.05), false});
  {
    // Ghost sheets: small flat clumps of stray points that pass the outlier
    // flags (reconstruct_test.cc), placed in the bounding box at least 6
    // spacings from the surface (MakeCloud), so the shape must leave room.
    CloudSpec s = spec(0.3, 0.05);
    s.clumps = 3;
    out.push_back({"ghost sheets", test::Sphere(1.0), s, false});
  }
  return out;
}

class ManifoldProperty : public ::testing::TestWithParam<unsigned> {};

TEST_P(ManifoldProperty, EveryEdgeHasTwoFacesAndEveryVertexOneFan) {
  for (const Case& c : Cases(GetParam())) {
    SCOPED_TRACE(absl::StrCat(c.name, ", seed ", GetParam()));
    const PointCloud cloud = test::MakeCloud(c.shape, c.spec);
    const auto r = Reconstruct(cloud);
    ASSERT_TRUE(r.ok()) << r.status();
    const TriMesh& m = r->mesh.tri;
    ASSERT_GT(m.n_faces(), 0u);
    const Defects d = FindDefects(FaceList(m), Positions(m));
    EXPECT_TRUE(d.None()) << d.Describe();
    if (c.sphere_like) {
      EXPECT_EQ(test::ComponentCount(m), 1);
      const int64_t euler = static_cast<int64_t>(m.n_vertices()) -
                            static_cast<int64_t>(m.n_edges()) + static_cast<int64_t>(m.n_faces());
      EXPECT_EQ(euler, 2) << "genus " << (2 - euler) / 2;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, ManifoldProperty, ::testing::Values(1u, 2u));

// The checker itself finds what it is meant to, on plain face lists (which,
// unlike a half-edge mesh, can hold every defect).
TEST(ManifoldPropertyCheck, FindsOpenEdgesPinchedVerticesFlippedAndFlatFaces) {
  // A tetrahedron, outward oriented, and a second one whose corner 4 is the
  // first one's apex 3.
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                          {1, 1, 2}, {0, 1, 2}, {0, 0, 3}};
  const Faces tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_TRUE(FindDefects(tet, p).None()) << FindDefects(tet, p).Describe();

  const Faces open(tet.begin(), tet.end() - 1);
  EXPECT_EQ(FindDefects(open, p).open_edges, 3);

  Faces flipped = tet;
  std::swap(flipped[0][1], flipped[0][2]);
  EXPECT_EQ(FindDefects(flipped, p).misoriented_edges, 3);

  Faces pinched = tet;
  for (const auto& t : Faces{{3, 5, 4}, {3, 4, 6}, {4, 5, 6}, {3, 6, 5}}) pinched.push_back(t);
  const Defects d = FindDefects(pinched, p);
  EXPECT_EQ(d.non_manifold_vertices, 1) << d.Describe();
  EXPECT_EQ(d.open_edges + d.non_manifold_edges + d.misoriented_edges, 0) << d.Describe();

  Faces with_fin = tet;
  with_fin.push_back({0, 1, 4});  // a third face on edge 0-1
  EXPECT_GE(FindDefects(with_fin, p).non_manifold_edges, 1);

  std::vector<Eigen::Vector3d> flat = p;
  flat[3] = {0.5, 0.5, 0.0};  // the apex on the base's hypotenuse
  EXPECT_GE(FindDefects(tet, flat).degenerate_faces, 1);
}

}  // namespace
}  // namespace meshseg
