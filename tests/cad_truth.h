// Ground truth of labelled CAD meshes and the score of a segmentation
// against it (the measures of issue 31, as bench/cad/score_cad.py prints
// them): per-triangle B-rep face labels, each face's exact surface, faces
// whose surfaces coincide merged into one truth surface.
#ifndef MESHSEG_TESTS_CAD_TRUTH_H_
#define MESHSEG_TESTS_CAD_TRUTH_H_

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "meshseg/surface.h"

namespace meshseg::testing {

struct TruthFace {
  SurfaceType type = SurfaceType::kFreeform;  // a B-spline face: kFreeform
  Surface surface;
};

// Truth surfaces closer than this (relative to the diagonal; angles in
// radians) are one surface.
inline constexpr double kSameSurface = 1e-6;

// The text of `key: ` up to the end of its value in one `{...}` entry.
inline std::optional<std::string> FieldOf(const std::string& entry, const std::string& key) {
  std::size_t k = 0;
  while ((k = entry.find(key + ": ", k)) != std::string::npos) {
    if (k == 0 || entry[k - 1] == ' ' || entry[k - 1] == '{' || entry[k - 1] == ',') break;
    ++k;
  }
  if (k == std::string::npos) return std::nullopt;
  std::size_t start = k + key.size() + 2;
  if (entry[start] == '[') return entry.substr(start + 1, entry.find(']', start) - start - 1);
  return entry.substr(start, entry.find_first_of(",}", start) - start);
}

inline std::vector<double> Numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

// The faces of an ABC-style features YAML (flow style `surfaces: [{...}]`),
// and, if `labels` is given, each entry's face_indices as labels per
// triangle (-1 where none).
inline std::vector<TruthFace> ReadTruthFaces(const std::string& path,
                                             std::vector<int>* labels = nullptr) {
  std::ifstream file(path);
  std::stringstream buf;
  buf << file.rdbuf();
  std::string s = buf.str();
  for (char& c : s) {
    if (c == '\n') c = ' ';
  }
  std::string collapsed;
  for (const char c : s) {
    if (c == ' ' && !collapsed.empty() && collapsed.back() == ' ') continue;
    collapsed.push_back(c);
  }
  s = collapsed;
  std::vector<TruthFace> faces;
  std::size_t pos = s.find("surfaces: [");
  int index = 0;
  while (pos != std::string::npos && (pos = s.find("{", pos)) != std::string::npos) {
    int depth = 0;
    std::size_t end = pos;
    for (; end < s.size(); ++end) {
      if (s[end] == '{') ++depth;
      if (s[end] == '}' && --depth == 0) break;
    }
    const std::string e = s.substr(pos, end - pos + 1);
    pos = end + 1;
    TruthFace face;
    const std::string type = FieldOf(e, "type").value_or("");
    auto vec = [&](const char* key) {
      const std::vector<double> v = Numbers(FieldOf(e, key).value_or("0,0,0"));
      return Eigen::Vector3d(v[0], v[1], v[2]);
    };
    auto num = [&](const char* key) { return std::stod(FieldOf(e, key).value_or("0")); };
    if (type == "Plane") {
      face = {SurfaceType::kPlane, Plane{vec("location"), vec("z_axis").normalized()}};
    } else if (type == "Cylinder") {
      face = {SurfaceType::kCylinder,
              Cylinder{vec("location"), vec("z_axis").normalized(), num("radius")}};
    } else if (type == "Cone") {
      face = {SurfaceType::kCone, Cone{vec("apex"), vec("z_axis").normalized(), num("angle")}};
    } else if (type == "Sphere") {
      face = {SurfaceType::kSphere, Sphere{vec("location"), num("radius")}};
    } else if (type == "Torus") {
      face = {SurfaceType::kTorus, Torus{vec("location"), vec("z_axis").normalized(),
                                         num("max_radius"), num("min_radius")}};
    }
    if (labels) {
      if (const auto indices = FieldOf(e, "face_indices")) {
        for (const double i : Numbers(*indices)) {
          if (static_cast<std::size_t>(i) >= labels->size()) labels->resize(i + 1, -1);
          (*labels)[static_cast<std::size_t>(i)] = index;
        }
      }
    }
    faces.push_back(face);
    ++index;
  }
  return faces;
}

// One integer per line (lines starting with '#' skipped).
inline std::vector<int> ReadLabels(const std::string& path) {
  std::ifstream in(path);
  std::vector<int> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    out.push_back(std::stoi(line));
  }
  return out;
}

inline double AxisAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.normalized().cross(b.normalized()).norm(),
                    std::abs(a.normalized().dot(b.normalized())));
}

// The worst difference between two surfaces of one type, relative to the
// diagonal (angles in radians); +inf for different types.
inline double SurfaceError(const Surface& a, const Surface& b, double diagonal) {
  if (a.index() != b.index()) return std::numeric_limits<double>::infinity();
  auto line = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& d) {
    const Eigen::Vector3d w = p - q;
    return (w - w.dot(d.normalized()) * d.normalized()).norm();
  };
  const double d = diagonal;
  if (const auto* x = std::get_if<Plane>(&a)) {
    const auto& y = std::get<Plane>(b);
    return std::max(AxisAngle(x->normal, y.normal),
                    std::abs((y.point - x->point).dot(x->normal)) / d);
  }
  if (const auto* x = std::get_if<Cylinder>(&a)) {
    const auto& y = std::get<Cylinder>(b);
    return std::max({AxisAngle(x->axis_direction, y.axis_direction),
                     line(y.axis_origin, x->axis_origin, x->axis_direction) / d,
                     std::abs(x->radius - y.radius) / d});
  }
  if (const auto* x = std::get_if<Cone>(&a)) {
    const auto& y = std::get<Cone>(b);
    return std::max({AxisAngle(x->axis_direction, y.axis_direction), (x->apex - y.apex).norm() / d,
                     std::abs(x->half_angle - y.half_angle)});
  }
  if (const auto* x = std::get_if<Sphere>(&a)) {
    const auto& y = std::get<Sphere>(b);
    return std::max((x->center - y.center).norm() / d, std::abs(x->radius - y.radius) / d);
  }
  if (const auto* x = std::get_if<Torus>(&a)) {
    const auto& y = std::get<Torus>(b);
    return std::max({AxisAngle(x->axis_direction, y.axis_direction),
                     (x->center - y.center).norm() / d,
                     std::abs(x->major_radius - y.major_radius) / d,
                     std::abs(x->minor_radius - y.minor_radius) / d});
  }
  return std::numeric_limits<double>::infinity();
}

struct CadScore {
  double area_right = 0.0;  // share of the labelled area in its region's majority surface
  int regions = 0;
  int faces = 0;             // truth faces
  int big_faces = 0;         // of >= kBigFace triangles
  int found = 0;             // big faces whose main region has their type
  double worst_error = 0.0;  // over the found faces' main regions (SurfaceError)
  int shared = 0;            // truth surfaces of >= 2 faces spread over >= 2 regions
  int shared_once = 0;       // ... whose regions share one surface_id
  std::vector<std::string> misses;
};
inline constexpr int kBigFace = 20;

// Scores `face_labels` / `regions` (per mesh face of `mesh`) against
// `labels` (per mesh face, B-rep face index, -1 = none) and `truth`.
// Faces of fewer than `min_triangles` triangles are not asked to be found
// (big_faces counts the others).
inline CadScore ScoreCad(const Mesh& mesh, const std::vector<int>& face_labels,
                         const std::vector<Region>& regions, const std::vector<int>& labels,
                         const std::vector<TruthFace>& truth, int min_triangles = kBigFace) {
  CadScore score;
  const TriMesh& tri = mesh.tri;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto v : tri.vertices()) {
    lo = lo.cwiseMin(ToEigen(tri.point(v)));
    hi = hi.cwiseMax(ToEigen(tri.point(v)));
  }
  const double diagonal = (hi - lo).norm();
  const int n_truth = static_cast<int>(truth.size());
  std::vector<int> group(n_truth);
  for (int i = 0; i < n_truth; ++i) {
    group[i] = i;
    if (truth[i].type == SurfaceType::kFreeform) continue;
    for (int j = 0; j < i; ++j) {
      if (group[j] == j &&
          SurfaceError(truth[i].surface, truth[j].surface, diagonal) < kSameSurface) {
        group[i] = j;
        break;
      }
    }
  }
  const int n = static_cast<int>(tri.n_faces());
  std::vector<double> area(n);
  for (int f = 0; f < n; ++f) area[f] = tri.calc_face_area(TriMesh::FaceHandle(f));
  std::map<std::pair<int, int>, double> votes;
  for (int f = 0; f < n; ++f) {
    if (labels[f] >= 0) votes[{face_labels[f], group[labels[f]]}] += area[f];
  }
  std::map<int, std::pair<int, double>> majority;
  for (const auto& [key, a] : votes) {
    auto& m = majority[key.first];
    if (a > m.second) m = {key.second, a};
  }
  double right = 0.0, total = 0.0;
  for (int f = 0; f < n; ++f) {
    if (labels[f] < 0) continue;
    total += area[f];
    if (majority[face_labels[f]].first == group[labels[f]]) right += area[f];
  }
  score.area_right = total > 0.0 ? right / total : 0.0;
  score.regions = static_cast<int>(regions.size());
  score.faces = n_truth;
  for (int k = 0; k < n_truth; ++k) {
    std::map<int, double> share;
    int triangles = 0;
    for (int f = 0; f < n; ++f) {
      if (labels[f] == k) share[face_labels[f]] += area[f], ++triangles;
    }
    if (triangles < min_triangles) continue;
    ++score.big_faces;
    const int r = std::max_element(share.begin(), share.end(), [](auto& a, auto& b) {
                    return a.second < b.second;
                  })->first;
    if (r < 0 || regions[r].type != truth[k].type) {
      score.misses.push_back("face " + std::to_string(k) + " " + SurfaceTypeName(truth[k].type) +
                             " -> " + (r < 0 ? "none" : SurfaceTypeName(regions[r].type)));
      continue;
    }
    ++score.found;
    if (truth[k].type != SurfaceType::kFreeform) {
      score.worst_error =
          std::max(score.worst_error, SurfaceError(truth[k].surface, regions[r].surface, diagonal));
    }
  }
  std::map<int, std::set<int>> regions_of_group;
  std::map<int, int> faces_of_group;
  for (int k = 0; k < n_truth; ++k) ++faces_of_group[group[k]];
  for (int f = 0; f < n; ++f) {
    if (labels[f] >= 0) regions_of_group[group[labels[f]]].insert(face_labels[f]);
  }
  for (const auto& [g, members] : regions_of_group) {
    if (faces_of_group[g] < 2 || members.size() < 2) continue;
    ++score.shared;
    std::set<int> ids;
    for (const int r : members) ids.insert(r < 0 ? -1 : regions[r].surface_id);
    score.shared_once += ids.size() == 1;
  }
  return score;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CAD_TRUTH_H_
