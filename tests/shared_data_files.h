// The meshes of ../shared/data (SOURCES.md), for tests that run a stage on
// every one of them.
#ifndef MESHSEG_TESTS_SHARED_DATA_FILES_H_
#define MESHSEG_TESTS_SHARED_DATA_FILES_H_

#include <cctype>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace meshseg::testing {

inline std::string SharedData(const std::string& name) {
  return (std::filesystem::path(MESHSEG_SHARED_DATA_DIR) / name).string();
}

// Every mesh file (not the point clouds) of shared/data.
inline auto SharedMeshFiles() {
  return ::testing::Values("fandisk.off", "fandisk_noisy0.1.off", "abc_00007974_5.obj",
                           "plate_holes.stl", "torus.stl", "tray_bottom_1002.stl",
                           "bunny_zipper_res2.ply", "broken_bullet_gt.obj", "abc_00016513_gt.ply");
}

// A test name from a file name: non-alphanumerics become '_'.
inline std::string FileTestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& ch : n) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return n;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_SHARED_DATA_FILES_H_
