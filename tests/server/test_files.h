// Small meshes written in every supported format, for the service and CLI
// tests. A box with each side split n x n (12 n^2 triangles, closed).
#ifndef MESHSEG_TESTS_SERVER_TEST_FILES_H_
#define MESHSEG_TESTS_SERVER_TEST_FILES_H_

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

namespace meshseg::testing_files {

struct TestMesh {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<int, 3>> f;
};

inline TestMesh SplitBox(int n, const Eigen::Vector3d& size) {
  TestMesh m;
  // Six sides (fixed axis, low/high); sides share vertices through their
  // integer grid position, so the box is closed and manifold.
  std::vector<int> index((n + 1) * (n + 1) * (n + 1), -1);
  auto vertex = [&](int i, int j, int k) {
    int& id = index[(i * (n + 1) + j) * (n + 1) + k];
    if (id < 0) {
      id = static_cast<int>(m.v.size());
      m.v.emplace_back(size.x() * i / n, size.y() * j / n, size.z() * k / n);
    }
    return id;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) {
          auto at = [&](int da, int db) {
            std::array<int, 3> g{};
            g[axis] = side * n;
            g[(axis + 1) % 3] = a + da;
            g[(axis + 2) % 3] = b + db;
            return vertex(g[0], g[1], g[2]);
          };
          const int p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (side == 1) {
            m.f.push_back({p00, p10, p11});
            m.f.push_back({p00, p11, p01});
          } else {
            m.f.push_back({p00, p11, p10});
            m.f.push_back({p00, p01, p11});
          }
        }
      }
    }
  }
  return m;
}

inline void WriteObj(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  for (const auto& p : m.v) o << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : m.f) o << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

inline void WriteOff(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  o << "OFF\n" << m.v.size() << " " << m.f.size() << " 0\n";
  for (const auto& p : m.v) o << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : m.f) o << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

inline void WritePlyAscii(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  o << "ply\nformat ascii 1.0\nelement vertex " << m.v.size()
    << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.f.size()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.v) o << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& t : m.f) o << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

inline void WritePlyBinary(const TestMesh& m, const std::string& path) {
  std::ofstream o(path, std::ios::binary);
  o << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.v.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.f.size()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.v) {
    const float xyz[3] = {float(p.x()), float(p.y()), float(p.z())};
    o.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  for (const auto& t : m.f) {
    const unsigned char three = 3;
    o.write(reinterpret_cast<const char*>(&three), 1);
    o.write(reinterpret_cast<const char*>(t.data()), 12);
  }
}

// Writes `value` most significant byte first.
template <typename T>
void WriteBigEndian(std::ostream& o, T value) {
  static_assert(std::endian::native == std::endian::little,
                "the swap assumes a little-endian host");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  std::reverse(bytes, bytes + sizeof(T));
  o.write(bytes, sizeof(T));
}

// Binary big-endian PLY with double positions (the same values as the ASCII
// PLY at 17 digits, so both read back identical) and int indices.
inline void WritePlyBinaryBigEndian(const TestMesh& m, const std::string& path) {
  std::ofstream o(path, std::ios::binary);
  o << "ply\nformat binary_big_endian 1.0\nelement vertex " << m.v.size()
    << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.f.size()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.v) {
    for (int k = 0; k < 3; ++k) WriteBigEndian(o, p[k]);
  }
  for (const auto& t : m.f) {
    o.put(3);
    for (int c : t) WriteBigEndian(o, static_cast<int32_t>(c));
  }
}

inline Eigen::Vector3d Normal(const TestMesh& m, const std::array<int, 3>& t) {
  return (m.v[t[1]] - m.v[t[0]]).cross(m.v[t[2]] - m.v[t[0]]).normalized();
}

inline void WriteStlAscii(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  o << "solid box\n";
  for (const auto& t : m.f) {
    const Eigen::Vector3d n = Normal(m, t);
    o << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
    for (int c : t) o << "   vertex " << m.v[c].x() << " " << m.v[c].y() << " " << m.v[c].z() << "\n";
    o << "  endloop\n endfacet\n";
  }
  o << "endsolid box\n";
}

inline void WriteStlBinary(const TestMesh& m, const std::string& path) {
  std::ofstream o(path, std::ios::binary);
  const std::string header(80, ' ');
  o.write(header.data(), 80);
  const uint32_t count = static_cast<uint32_t>(m.f.size());
  o.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : m.f) {
    const Eigen::Vector3d n = Normal(m, t);
    float data[12] = {float(n.x()), float(n.y()), float(n.z())};
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) data[3 + 3 * c + k] = float(m.v[t[c]][k]);
    }
    o.write(reinterpret_cast<const char*>(data), sizeof data);
    const uint16_t attr = 0;
    o.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

// Point clouds: the vertices of a SplitBox (a regular grid on its sides),
// with outward normals (axis directions; averaged on edges and corners).
inline std::vector<Eigen::Vector3d> BoxNormals(const TestMesh& m) {
  Eigen::Vector3d lo = m.v.front(), hi = m.v.front();
  for (const auto& p : m.v) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  std::vector<Eigen::Vector3d> normals;
  for (const auto& p : m.v) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) n[k] = (p[k] == hi[k]) - (p[k] == lo[k]);
    normals.push_back(n.normalized());
  }
  return normals;
}

inline void WriteXyz(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  for (const auto& p : m.v) o << p.x() << " " << p.y() << " " << p.z() << "\n";
}

inline void WriteXyzNormals(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  const std::vector<Eigen::Vector3d> n = BoxNormals(m);
  for (std::size_t i = 0; i < m.v.size(); ++i) {
    o << m.v[i].x() << " " << m.v[i].y() << " " << m.v[i].z() << " " << n[i].x() << " "
      << n[i].y() << " " << n[i].z() << "\n";
  }
}

inline void WritePwn(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  o << m.v.size() << "\n";
  for (const auto& p : m.v) o << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& n : BoxNormals(m)) o << n.x() << " " << n.y() << " " << n.z() << "\n";
}

// A PLY with a vertex element only (ASCII, positions).
inline void WritePlyPointsAscii(const TestMesh& m, const std::string& path) {
  std::ofstream o(path);
  o.precision(17);
  o << "ply\nformat ascii 1.0\nelement vertex " << m.v.size()
    << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  for (const auto& p : m.v) o << p.x() << " " << p.y() << " " << p.z() << "\n";
}

// A PLY with a vertex element only (binary, float positions and normals).
inline void WritePlyPointsBinary(const TestMesh& m, const std::string& path) {
  std::ofstream o(path, std::ios::binary);
  o << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.v.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
       "property float ny\nproperty float nz\nend_header\n";
  const std::vector<Eigen::Vector3d> n = BoxNormals(m);
  for (std::size_t i = 0; i < m.v.size(); ++i) {
    const float data[6] = {float(m.v[i].x()), float(m.v[i].y()), float(m.v[i].z()),
                           float(n[i].x()),   float(n[i].y()),   float(n[i].z())};
    o.write(reinterpret_cast<const char*>(data), sizeof data);
  }
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream o(path, std::ios::binary);
  o << text;
}

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace meshseg::testing_files

#endif  // MESHSEG_TESTS_SERVER_TEST_FILES_H_
