// Small volumes with known surfaces for the voxel tests: a rotated box
// sampled as occupancy (binary) or as a grey ramp of signed distance.
#ifndef MESHSEG_TESTS_CORE_VOXEL_VOXEL_SHAPES_H_
#define MESHSEG_TESTS_CORE_VOXEL_VOXEL_SHAPES_H_

#include <algorithm>
#include <functional>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "meshseg/voxel.h"
#include "scratch_dir.h"

namespace meshseg::testing {

// Samples `sdf` (negative inside) on an n^3 grid of spacing h around the
// origin: binary = 1 inside, else a grey ramp 0..1000 over 2 h.
inline VolumeData SampleSdf(const std::function<double(const Eigen::Vector3d&)>& sdf, int n,
                            double h, bool binary) {
  VolumeData v;
  v.type = binary ? VoxelType::kUint8 : VoxelType::kUint16;
  v.geometry.dims = {n, n, n};
  v.geometry.origin =
      Eigen::Vector3d::Constant(-0.5 * (n - 1) * h) + Eigen::Vector3d(0.13, 0.29, 0.41) * h;
  for (int a = 0; a < 3; ++a) v.geometry.axes[a] = h * Eigen::Vector3d::Unit(a);
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const double f = sdf(v.geometry.Point(i, j, k));
        v.values.push_back(binary ? (f < 0.0) : 1000.0 * std::clamp(0.5 - f / (2.0 * h), 0.0, 1.0));
      }
    }
  }
  return v;
}

// A box of half extents `half`, turned by `degrees` about (1, 2, 3).
inline std::function<double(const Eigen::Vector3d&)> TurnedBox(const Eigen::Vector3d& half,
                                                               double degrees) {
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(degrees * 3.14159265358979 / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  return [=](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = (r.transpose() * p).cwiseAbs() - half;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
  };
}

inline std::function<double(const Eigen::Vector3d&)> Ball(double radius) {
  return [=](const Eigen::Vector3d& p) { return p.norm() - radius; };
}

// The surface ExtractSurface finds in `v`, written as NRRD under `name`.
inline VolumeSurface SurfaceOf(const VolumeData& v, const std::string& name) {
  const std::string path = testing_files::ScratchPath(name);
  EXPECT_TRUE(WriteNrrd(v, path).ok());
  absl::StatusOr<VolumeSurface> s = ExtractSurface(path);
  EXPECT_TRUE(s.ok()) << s.status();
  return *std::move(s);
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_VOXEL_VOXEL_SHAPES_H_
