// Tiny files for the mesh-stage tests, written at test time.
#ifndef MESHSEG_TESTS_CORE_MESH_TEMP_FILE_H_
#define MESHSEG_TESTS_CORE_MESH_TEMP_FILE_H_

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "absl/status/status.h"
#include "scratch_dir.h"

namespace meshseg::testing_files {

// The message of `status` as a std::string (Debian's absl::string_view is not
// std::string_view, and gMock prints it character by character).
inline std::string Message(const absl::Status& status) { return std::string(status.message()); }

// Returns the path of `name` in a directory of its own for the running test,
// after writing `content` to it.
inline std::string WriteTemp(const std::string& name, std::string_view content) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string leaf = std::string(info->test_suite_name()) + "_" + info->name();
  for (char& c : leaf) {
    if (c == '/') c = '_';
  }
  const std::string dir = testing_files::ScratchPath(leaf);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  FILE* file = std::fopen(path.c_str(), "wb");
  EXPECT_NE(file, nullptr) << path;
  if (file != nullptr) {
    std::fwrite(content.data(), 1, content.size(), file);
    std::fclose(file);
  }
  return path;
}

template <typename T>
void AppendRaw(std::string& out, T value, bool big_endian = false) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian) {
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  }
  out.append(raw, sizeof(T));
}

using Tri = std::array<std::array<float, 3>, 3>;

// Binary STL bytes of `triangles`; `declared` overrides the count field.
inline std::string BinaryStl(const std::vector<Tri>& triangles, int64_t declared = -1,
                             std::string_view header = "binary stl written by a test") {
  std::string out(header.substr(0, 80));  // the 80-byte header, space-padded
  out.resize(80, ' ');
  AppendRaw<uint32_t>(out, static_cast<uint32_t>(declared >= 0 ? declared : triangles.size()));
  for (const Tri& t : triangles) {
    for (int i = 0; i < 3; ++i) AppendRaw<float>(out, 0.0f);
    for (const auto& v : t) {
      for (float c : v) AppendRaw<float>(out, c);
    }
    AppendRaw<uint16_t>(out, 0);
  }
  return out;
}

// The 12 triangles of the unit cube [0,1]^3, outward oriented.
inline std::vector<Tri> CubeTriangles() {
  const float p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<Tri> out;
  for (const auto& t : f) {
    Tri tri;
    for (int k = 0; k < 3; ++k) tri[k] = {p[t[k]][0], p[t[k]][1], p[t[k]][2]};
    out.push_back(tri);
  }
  return out;
}

// The unit cube as OFF text (8 vertices, 12 triangles).
inline std::string CubeOff() {
  return "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
         "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
         "3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
}

}  // namespace meshseg::testing_files

#endif  // MESHSEG_TESTS_CORE_MESH_TEMP_FILE_H_
