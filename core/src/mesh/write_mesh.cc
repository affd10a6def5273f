// Writers: binary little-endian PLY (optionally with face colours), OFF, OBJ,
// binary STL, and points with colours as PLY.
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include <Eigen/Geometry>

#include "absl/strings/str_cat.h"
#include "meshseg/label_color.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "mesh/source.h"

namespace meshseg {
namespace {

static_assert(std::endian::native == std::endian::little, "PLY writer assumes little endian");

std::string Extension(const std::string& path) {
  const std::string name = mesh_internal::FileName(path);
  const size_t dot = name.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

absl::Status WriteBytes(const std::string& path, const std::string& bytes) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (file == nullptr || std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size() ||
      std::fflush(file.get()) != 0) {
    return absl::InternalError(absl::StrCat("write_mesh: \"", mesh_internal::FileName(path),
                                            "\": cannot write ", bytes.size(), " bytes"));
  }
  return absl::OkStatus();
}

template <typename T>
void Append(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

}  // namespace

// Distinct colours for labels 0, 1, 2, ...: hues spaced by the golden angle,
// three brightness levels; grey for -1.
std::array<uint8_t, 3> LabelColor(int label) {
  if (label < 0) return {128, 128, 128};
  const double hue = std::fmod(label * 0.618033988749895, 1.0) * 6.0;
  const double value = 1.0 - 0.25 * ((label / 7) % 3);
  const int sector = static_cast<int>(hue);
  const double f = hue - sector;
  const double rgb[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f},
                            {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  std::array<uint8_t, 3> color;
  for (int c = 0; c < 3; ++c) {
    color[c] = static_cast<uint8_t>(std::lround(255.0 * value * (0.15 + 0.85 * rgb[sector][c])));
  }
  return color;
}

namespace {

std::string PlyBytes(const TriMesh& mesh, const std::vector<int>* labels) {
  std::string out = absl::StrCat(
      "ply\nformat binary_little_endian 1.0\ncomment written by meshseg\nelement vertex ",
      mesh.n_vertices(), "\nproperty double x\nproperty double y\nproperty double z\n",
      "element face ", mesh.n_faces(), "\nproperty list uchar int vertex_indices\n");
  if (labels != nullptr) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "end_header\n";
  out.reserve(out.size() + mesh.n_vertices() * 24 + mesh.n_faces() * 16);
  for (const auto v : mesh.vertices()) {
    const TriMesh::Point& p = mesh.point(v);
    for (int c = 0; c < 3; ++c) Append<double>(out, p[c]);
  }
  for (const auto f : mesh.faces()) {
    Append<uint8_t>(out, 3);
    for (const auto v : mesh.fv_range(f)) Append<int32_t>(out, v.idx());
    if (labels != nullptr) {
      for (uint8_t c : LabelColor((*labels)[f.idx()])) Append<uint8_t>(out, c);
    }
  }
  return out;
}

std::string OffBytes(const TriMesh& mesh) {
  std::string out = absl::StrCat("OFF\n", mesh.n_vertices(), " ", mesh.n_faces(), " 0\n");
  for (const auto v : mesh.vertices()) {
    const TriMesh::Point& p = mesh.point(v);
    // %.17g keeps every double exactly.
    char line[96];
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out += line;
  }
  for (const auto f : mesh.faces()) {
    out += "3";
    for (const auto v : mesh.fv_range(f)) absl::StrAppend(&out, " ", v.idx());
    out += "\n";
  }
  return out;
}

// Binary STL as CAD systems export it: float32 coordinates, one unit normal
// per facet (from its corners), no shared vertices.
std::string StlBytes(const TriMesh& mesh) {
  std::string out(80, '\0');
  out.replace(0, 22, "binary STL by meshseg ");
  Append<uint32_t>(out, static_cast<uint32_t>(mesh.n_faces()));
  out.reserve(out.size() + mesh.n_faces() * 50);
  for (const auto f : mesh.faces()) {
    std::array<Eigen::Vector3d, 3> c;
    int k = 0;
    for (const auto v : mesh.fv_range(f)) c[k++] = ToEigen(mesh.point(v));
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]).normalized();
    for (int i = 0; i < 3; ++i) Append<float>(out, static_cast<float>(n[i]));
    for (const Eigen::Vector3d& p : c) {
      for (int i = 0; i < 3; ++i) Append<float>(out, static_cast<float>(p[i]));
    }
    Append<uint16_t>(out, 0);
  }
  return out;
}

// Wavefront OBJ, 17 significant digits (reads back bit-identical).
std::string ObjBytes(const TriMesh& mesh) {
  std::string out = "# written by meshseg\n";
  for (const auto v : mesh.vertices()) {
    const TriMesh::Point& p = mesh.point(v);
    char line[100];
    std::snprintf(line, sizeof(line), "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out += line;
  }
  for (const auto f : mesh.faces()) {
    out += "f";
    for (const auto v : mesh.fv_range(f)) absl::StrAppend(&out, " ", v.idx() + 1);
    out += "\n";
  }
  return out;
}

}  // namespace

absl::Status WriteMesh(const TriMesh& mesh, const std::string& path) {
  const std::string ext = Extension(path);
  if (ext == "ply") return WriteBytes(path, PlyBytes(mesh, nullptr));
  if (ext == "off") return WriteBytes(path, OffBytes(mesh));
  if (ext == "obj") return WriteBytes(path, ObjBytes(mesh));
  if (ext == "stl") return WriteBytes(path, StlBytes(mesh));
  return absl::InvalidArgumentError(absl::StrCat("write_mesh: \"", mesh_internal::FileName(path),
                                                 "\": unsupported extension \"", ext,
                                                 "\" (ply, off, obj, stl)"));
}

absl::Status WriteColoredPly(const TriMesh& mesh, const std::vector<int>& face_labels,
                             const std::string& path) {
  if (face_labels.size() != mesh.n_faces()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "write_colored_ply: \"", mesh_internal::FileName(path), "\": ", face_labels.size(),
        " face labels for ", mesh.n_faces(), " faces"));
  }
  return WriteBytes(path, PlyBytes(mesh, &face_labels));
}

absl::Status WriteColoredPointPly(const PointCloud& cloud, const std::vector<int>& point_labels,
                                  const std::string& path) {
  if (point_labels.size() != cloud.points.size()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "write_colored_ply: \"", mesh_internal::FileName(path), "\": ", point_labels.size(),
        " point labels for ", cloud.points.size(), " points"));
  }
  std::string out = absl::StrCat(
      "ply\nformat binary_little_endian 1.0\ncomment written by meshseg\nelement vertex ",
      cloud.points.size(), "\nproperty double x\nproperty double y\nproperty double z\n",
      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n");
  out.reserve(out.size() + cloud.points.size() * 27);
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    for (int c = 0; c < 3; ++c) Append<double>(out, cloud.points[i][c]);
    for (uint8_t c : LabelColor(point_labels[i])) Append<uint8_t>(out, c);
  }
  return WriteBytes(path, out);
}

}  // namespace meshseg
