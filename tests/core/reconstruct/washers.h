// Washers (rings of rectangular section) with parts of their surface unseen,
// for the tests of the tube between an unseen annulus's rims (close_tube.h)
// and of the split at the cap (split_at_cap.h); and the check that a closed
// surface is one manifold of a given genus.
#ifndef MESHSEG_TESTS_CORE_RECONSTRUCT_WASHERS_H_
#define MESHSEG_TESTS_CORE_RECONSTRUCT_WASHERS_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "clouds.h"
#include "reconstruct/close_unsupported.h"
#include "reconstruct/surface_mesh.h"

namespace meshseg::reconstruct_internal::test_washers {

// `tri` is one closed manifold of genus `genus`.
inline void ExpectOneClosedManifoldOfGenus(const TriMesh& tri, int genus) {
  EXPECT_EQ(test::BoundaryEdgeCount(tri), 0);
  EXPECT_EQ(test::NonManifoldVertexCount(tri), 0);
  EXPECT_EQ(test::ComponentCount(tri), 1);
  EXPECT_EQ(Genus(tri), genus);
}

// A washer: the ring of rectangular section ρ in [kInner, kOuter], z in
// [0, height] round the z axis, kNu cells round it and cells kStep square
// on the section, which runs anticlockwise in (ρ, z) from the outer wall's
// foot (so the faces face outwards). Face 2 (i cells + j) + k lies in cell
// (i, j); `section` gets the section's vertices. The walls are tall enough
// that the rings the rims' normals come from (close_tube.cc, up to 9 edges
// in) stay on them.
constexpr int kNu = 96;  // cells round the axis
constexpr double kInner = 10.0, kOuter = 15.0, kHeight = 10.0, kStep = 0.5;

inline Mesh Washer(double height, std::vector<Eigen::Vector2d>* section) {
  const int across = static_cast<int>(std::lround((kOuter - kInner) / kStep));
  const int up = static_cast<int>(std::lround(height / kStep));
  for (int k = 0; k < up; ++k) section->emplace_back(kOuter, k * kStep);
  for (int k = 0; k < across; ++k) section->emplace_back(kOuter - k * kStep, height);
  for (int k = 0; k < up; ++k) section->emplace_back(kInner, height - k * kStep);
  for (int k = 0; k < across; ++k) section->emplace_back(kInner + k * kStep, 0.0);
  const int nv = static_cast<int>(section->size());
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i < kNu; ++i) {
    const double u = 2 * M_PI * i / kNu;
    for (const Eigen::Vector2d& q : *section) {
      vertices.emplace_back(q.x() * std::cos(u), q.x() * std::sin(u), q.y());
    }
  }
  const auto id = [&](int i, int j) { return (i % kNu) * nv + j % nv; };
  for (int i = 0; i < kNu; ++i) {
    for (int j = 0; j < nv; ++j) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return *SurfaceMesh(vertices, triangles, "washer");
}

// The washer's faces whose section edge (p, q) is `seen`.
inline std::vector<uint8_t> SeenWhere(const Mesh& washer, const std::vector<Eigen::Vector2d>& section,
                                      bool (*seen)(const Eigen::Vector2d& p, const Eigen::Vector2d& q)) {
  const int nv = static_cast<int>(section.size());
  std::vector<uint8_t> supported(washer.tri.n_faces());
  for (size_t f = 0; f < supported.size(); ++f) {
    const int j = static_cast<int>(f) / 2 % nv;
    supported[f] = seen(section[j], section[(j + 1) % nv]);
  }
  return supported;
}

// Distance of `p` from the exact washer of `height`: from its section, the
// rectangle [kInner, kOuter] × [0, height] in (ρ, z).
inline double WasherDistance(const Eigen::Vector3d& p, double height) {
  const double rho = std::hypot(p.x(), p.y());
  const double inside = std::min({rho - kInner, kOuter - rho, p.z(), height - p.z()});
  if (inside >= 0) return inside;
  const double dr = std::max({kInner - rho, rho - kOuter, 0.0});
  const double dz = std::max({-p.z(), p.z() - height, 0.0});
  return std::hypot(dr, dz);
}

// The largest distance of a patch vertex from the exact washer of `height`.
inline double WorstWasherDistance(const ClosedSurface& closed, double height) {
  double worst = 0.0;
  for (const auto f : closed.mesh.tri.faces()) {
    if (!closed.filled[f.idx()]) continue;
    for (const auto v : closed.mesh.tri.fv_range(f)) {
      worst = std::max(worst, WasherDistance(ToEigen(closed.mesh.tri.point(v)), height));
    }
  }
  return worst;
}

}  // namespace meshseg::reconstruct_internal::test_washers

#endif  // MESHSEG_TESTS_CORE_RECONSTRUCT_WASHERS_H_
