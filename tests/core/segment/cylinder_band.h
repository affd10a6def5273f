// An exactly tessellated cylinder band for the tests of the exact-facet
// path: radius kBandRadius about the z axis, 0 <= z <= kBandHeight, in
// kBandAround quads between rulings, each split in two (facets 2k and
// 2k + 1 form quad k); corner 0 (on the bottom circle) pushed `push`
// outward.
#ifndef MESHSEG_TESTS_CORE_SEGMENT_CYLINDER_BAND_H_
#define MESHSEG_TESTS_CORE_SEGMENT_CYLINDER_BAND_H_

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "meshseg/mesh.h"

namespace meshseg::segment_internal::testing {

inline constexpr int kBandAround = 24;
inline constexpr double kBandRadius = 5.0;
inline constexpr double kBandHeight = 4.0;

inline Mesh CylinderBand(double push) {
  std::vector<Eigen::Vector3d> v;
  for (const double z : {0.0, kBandHeight}) {
    for (int k = 0; k < kBandAround; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kBandAround;
      v.emplace_back(kBandRadius * std::cos(a), kBandRadius * std::sin(a), z);
    }
  }
  v[0].x() += push;
  std::vector<std::array<int, 3>> f;
  for (int k = 0; k < kBandAround; ++k) {
    const int a = k, b = (k + 1) % kBandAround;
    f.push_back({a, b, b + kBandAround});
    f.push_back({a, b + kBandAround, a + kBandAround});
  }
  absl::StatusOr<Mesh> mesh = BuildMesh(std::move(v), f, "band");
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

} // namespace meshseg::segment_internal::testing

#endif // MESHSEG_TESTS_CORE_SEGMENT_CYLINDER_BAND_H_
