// The ground-truth segmentation of a generated part: one region per
// primitive, labels from face_primitive, and each region's surface refitted
// by the fit stage to the vertices of its faces away from primitive
// boundaries (the truth surface where the fit fails), so curve and feature
// accuracy is measured through real fits.
#ifndef MESHSEG_TESTS_CORE_TOPOLOGY_GROUND_TRUTH_REGIONS_H_
#define MESHSEG_TESTS_CORE_TOPOLOGY_GROUND_TRUTH_REGIONS_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "meshseg/fit.h"
#include "meshseg/generate.h"
#include "meshseg/segment.h"

namespace meshseg::testing {

struct TruthSegmentation {
  std::vector<int> face_labels;
  std::vector<Region> regions;
};

inline FitResult FitLike(const Surface& truth, const FitInput& input) {
  switch (TypeOf(truth)) {
    case SurfaceType::kPlane: return FitPlane(input);
    case SurfaceType::kCylinder: return FitCylinder(input);
    case SurfaceType::kCone: return FitCone(input);
    case SurfaceType::kSphere: return FitSphere(input);
    case SurfaceType::kTorus: return FitTorus(input);
    default: return FitQuadric(input);
  }
}

inline TruthSegmentation TruthOf(const GeneratedPart& part, bool refit = true) {
  TruthSegmentation out;
  out.face_labels = part.face_primitive;
  const TriMesh& tri = part.mesh.tri;
  for (const PrimitiveTruth& p : part.primitives) {
    Region r;
    r.id = p.id;
    r.type = TypeOf(p.surface);
    r.surface = p.surface;
    out.regions.push_back(r);
  }
  std::vector<std::vector<int>> vertex_lists(part.primitives.size());
  std::vector<std::vector<char>> taken(part.primitives.size(),
                                       std::vector<char>(tri.n_vertices(), 0));
  for (auto f : tri.faces()) {
    const int label = part.face_primitive[f.idx()];
    if (label < 0) continue;
    Region& r = out.regions[label];
    ++r.face_count;
    r.area += tri.calc_face_area(f);
    if (part.face_near_boundary[f.idx()]) continue;
    for (auto v : tri.fv_range(f)) {
      if (!taken[label][v.idx()]) {
        taken[label][v.idx()] = 1;
        vertex_lists[label].push_back(v.idx());
      }
    }
  }
  if (!refit) return out;
  for (Region& r : out.regions) {
    const std::vector<int>& list = vertex_lists[r.id];
    if (list.size() < 12) continue;
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> normals;
    for (const int v : list) {
      points.push_back(ToEigen(tri.point(OpenMesh::VertexHandle(v))));
      normals.push_back(ToEigen(tri.normal(OpenMesh::VertexHandle(v))));
    }
    const FitResult fit = FitLike(r.surface, FitInput{points, normals, {}});
    if (fit.ok() && TypeOf(fit.surface) == r.type) {
      r.surface = fit.surface;
      r.rms_distance = fit.rms_distance;
      r.max_distance = fit.max_distance;
    }
  }
  return out;
}

// The id of the primitive called `name`, or -1.
inline int PrimitiveId(const GeneratedPart& part, const std::string& name) {
  for (const PrimitiveTruth& p : part.primitives) {
    if (p.name == name) return p.id;
  }
  return -1;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_TOPOLOGY_GROUND_TRUTH_REGIONS_H_
