// Scores a Segmentation of a generated part against its ground truth.
#ifndef MESHSEG_TESTS_CORE_SEGMENT_SEGMENT_EVAL_H_
#define MESHSEG_TESTS_CORE_SEGMENT_SEGMENT_EVAL_H_

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "meshseg/generate.h"
#include "meshseg/segment.h"

namespace meshseg::testing {

struct PrimitiveScore {
  int primitive = 0;
  std::string name;
  SurfaceType true_type = SurfaceType::kPlane;
  int64_t faces = 0;         // faces of the primitive
  int region = -1;           // region covering most of its area
  double covered = 0.0;      // share of its (non-boundary) area in regions
                             // whose majority primitive it is
  std::vector<int> regions;  // those regions
  double angular_span = 1.0; // cylinders: fraction of the full turn present
  double amount = 0.0;       // its scored weight (area of faces, or points)
};

struct Evaluation {
  double area_fraction = 0.0;  // area labelled with the true primitive
  int true_count = 0;          // face-connected pieces of primitives (>= 10 faces)
  int true_extra_pieces = 0;   // of those, beyond one per primitive
  int region_count = 0;
  int region_extra_pieces = 0; // face-connected pieces of regions (any size) beyond one each
  std::vector<PrimitiveScore> primitives;
  std::vector<int> region_primitive;  // per region: the primitive of most of its weight, or -1
};

inline double AngularSpan(const GeneratedPart& part, int primitive, const Cylinder& cyl) {
  std::vector<bool> bins(72, false);
  Eigen::Vector3d u = cyl.axis_direction.unitOrthogonal();
  Eigen::Vector3d w = cyl.axis_direction.cross(u);
  for (std::size_t f = 0; f < part.face_primitive.size(); ++f) {
    if (part.face_primitive[f] != primitive) continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto it = part.mesh.tri.cfv_iter(TriMesh::FaceHandle(int(f))); it.is_valid(); ++it) {
      c += ToEigen(part.mesh.tri.point(*it)) / 3.0;
    }
    const Eigen::Vector3d d = c - cyl.axis_origin;
    const double a = std::atan2(d.dot(w), d.dot(u)) + std::numbers::pi;
    bins[std::min(71, int(a / (2 * std::numbers::pi) * 72))] = true;
  }
  return std::count(bins.begin(), bins.end(), true) / 72.0;
}

// Face-connected pieces of equally labelled faces (labels >= 0) with at
// least `min_faces` faces, per label.
inline std::map<int, int> PiecesPerLabel(const TriMesh& tri, std::span<const int> labels,
                                         int min_faces) {
  std::vector<int> seen(tri.n_faces(), 0);
  std::map<int, int> count;
  for (std::size_t s = 0; s < tri.n_faces(); ++s) {
    if (seen[s] || labels[s] < 0) continue;
    std::vector<int> stack = {int(s)};
    seen[s] = 1;
    int size = 0;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      ++size;
      for (auto it = tri.cff_iter(TriMesh::FaceHandle(f)); it.is_valid(); ++it) {
        const int g = it->idx();
        if (seen[g] || labels[g] != labels[s]) continue;
        seen[g] = 1;
        stack.push_back(g);
      }
    }
    if (size >= min_faces) ++count[labels[s]];
  }
  return count;
}

// Pieces beyond one per label.
inline int ExtraPieces(const std::map<int, int>& pieces) {
  int extra = 0;
  for (const auto& [label, n] : pieces) extra += n - 1;
  return extra;
}

// Majority matching of labelled elements (faces weighted by area, scan
// points by count) against their true primitives: each region stands for
// the primitive holding most of its weight; an element is right when its
// region stands for its own primitive. `truth` and `labels` have one entry
// per element (-1 = none), `weight` one per element; elements with
// `scored[i] == 0` (faces near a boundary between primitives) vote for their
// region's primitive but are not scored. Fills e.area_fraction (the scored
// weight labelled right) and per primitive with scored elements: region,
// covered, regions, amount. Faces and points share this one measure.
inline void MatchMajority(const std::vector<PrimitiveTruth>& primitives, int region_count,
                          std::span<const int> truth, std::span<const int> labels,
                          std::span<const double> weight, std::span<const uint8_t> scored,
                          Evaluation* e) {
  const int np = static_cast<int>(primitives.size());
  const int nr = region_count;
  // weight[region][primitive] over all elements; clean[..] scored ones only.
  std::vector<std::map<int, double>> all(nr), clean(np);
  std::vector<int64_t> count(np, 0);
  double total = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const int p = truth[i];
    const int r = labels[i];
    if (p >= 0) ++count[p];
    if (r >= 0 && p >= 0) all[r][p] += weight[i];
    if (p >= 0 && scored[i]) {
      clean[p][r] += weight[i];
      total += weight[i];
    }
  }
  std::vector<int> region_primitive(nr, -1);
  for (int r = 0; r < nr; ++r) {
    double best = 0.0;
    for (const auto& [p, a] : all[r]) {
      if (a > best) best = a, region_primitive[r] = p;
    }
  }
  e->region_count = nr;
  e->region_primitive = region_primitive;
  double correct = 0.0;
  for (int p = 0; p < np; ++p) {
    if (count[p] == 0) continue;
    PrimitiveScore s;
    s.primitive = p;
    s.name = primitives[p].name;
    s.true_type = TypeOf(primitives[p].surface);
    s.faces = count[p];
    double sum = 0.0, best = 0.0, mine = 0.0;
    for (const auto& [r, a] : clean[p]) {
      sum += a;
      if (r >= 0 && region_primitive[r] == p) {
        mine += a;
        s.regions.push_back(r);
      }
      if (r >= 0 && a > best) best = a, s.region = r;
    }
    correct += mine;
    s.amount = sum;
    s.covered = sum > 0.0 ? mine / sum : 0.0;
    e->primitives.push_back(s);
  }
  e->area_fraction = total > 0.0 ? correct / total : 0.0;
}

inline Evaluation Evaluate(const GeneratedPart& part, const Segmentation& seg) {
  const TriMesh& tri = part.mesh.tri;
  std::vector<double> area(tri.n_faces());
  std::vector<uint8_t> scored(tri.n_faces());
  for (std::size_t f = 0; f < tri.n_faces(); ++f) {
    area[f] = tri.calc_face_area(TriMesh::FaceHandle(int(f)));
    scored[f] = !part.face_near_boundary[f];
  }
  Evaluation e;
  MatchMajority(part.primitives, static_cast<int>(seg.regions.size()), part.face_primitive,
                seg.face_labels, area, scored, &e);
  const std::map<int, int> true_pieces =
      PiecesPerLabel(tri, part.face_primitive, /*min_faces=*/10);
  for (const auto& [p, n] : true_pieces) e.true_count += n;
  e.true_extra_pieces = ExtraPieces(true_pieces);
  e.region_extra_pieces = ExtraPieces(PiecesPerLabel(tri, seg.face_labels, /*min_faces=*/1));
  for (PrimitiveScore& s : e.primitives) {
    if (const auto* cyl = std::get_if<Cylinder>(&part.primitives[s.primitive].surface)) {
      s.angular_span = AngularSpan(part, s.primitive, *cyl);
    }
  }
  return e;
}

// The same measure on the points of a scan (ScanPart): every genuine point
// (not an outlier, drawn from a primitive) weighs 1 and is scored, also the
// ones the pipeline discarded (label -1 counts as wrong); outliers are left
// out. area_fraction is then the fraction of genuine points labelled with
// their true surface, `faces` and `amount` count points. `point_labels` has
// one entry per scan point, `region_count` is the result's.
inline Evaluation EvaluatePoints(const ScannedPart& scan, std::span<const int> point_labels,
                                 int region_count) {
  const std::vector<double> one(scan.point_primitive.size(), 1.0);
  std::vector<uint8_t> scored(scan.point_primitive.size());
  for (std::size_t i = 0; i < scored.size(); ++i) scored[i] = !scan.is_outlier[i];
  Evaluation e;
  MatchMajority(scan.part.primitives, region_count, scan.point_primitive, point_labels, one,
                scored, &e);
  return e;
}

inline std::ostream& operator<<(std::ostream& os, const Evaluation& e) {
  os << "area_fraction " << e.area_fraction << ", regions " << e.region_count << " / true "
     << e.true_count << ", extra pieces " << e.region_extra_pieces << " / true "
     << e.true_extra_pieces << "\n";
  for (const auto& s : e.primitives) {
    os << "  " << s.name << " (" << SurfaceTypeName(s.true_type) << ", " << s.faces
       << " faces): region " << s.region << ", covered " << s.covered << " by";
    for (const int r : s.regions) os << " " << r;
    os << "\n";
  }
  return os;
}

// Angle in degrees between two axes (either orientation).
inline double AxisAngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 /
         std::numbers::pi;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_SEGMENT_SEGMENT_EVAL_H_
