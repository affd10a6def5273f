#include "pipeline/refit_regions.h"

#include <algorithm>
#include <cmath>

#include "meshseg/fit.h"

namespace meshseg::pipeline_internal {
namespace {

struct Distances {
  double rms = 0.0;
  double max = 0.0;
};

Distances DistancesTo(const Surface& surface, std::span<const Eigen::Vector3d> points) {
  Distances d;
  for (const Eigen::Vector3d& p : points) {
    const double e = std::abs(SignedDistance(surface, p));
    d.rms += e * e;
    d.max = std::max(d.max, e);
  }
  d.rms = points.empty() ? 0.0 : std::sqrt(d.rms / static_cast<double>(points.size()));
  return d;
}

}  // namespace

void RefitOnInputVertices(const TriMesh& mesh, std::span<const int> face_labels,
                          std::vector<Region>* regions) {
  // Vertex lists per region: the corners of its faces, each once.
  std::vector<std::vector<int>> members(regions->size());
  std::vector<int> last_region(mesh.n_vertices(), -1);
  for (const auto f : mesh.faces()) {
    const int r = face_labels[f.idx()];
    if (r < 0) continue;
    for (const auto v : mesh.fv_range(f)) {
      // Faces of one region mostly come in runs; a vertex may still be
      // listed twice when they do not, which only weights it double.
      if (last_region[v.idx()] == r) continue;
      last_region[v.idx()] = r;
      members[r].push_back(v.idx());
    }
  }
  std::vector<Eigen::Vector3d> points, normals;
  for (Region& region : *regions) {
    std::vector<int>& ids = members[region.id];
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    points.clear();
    normals.clear();
    for (const int v : ids) {
      const Eigen::Vector3d p = ToEigen(mesh.point(TriMesh::VertexHandle(v)));
      points.push_back(p);
      normals.push_back(Project(region.surface, p, Eigen::Vector3d::Zero()).normal);
    }
    const Distances before = DistancesTo(region.surface, points);
    const FitResult refit =
        FitOfType(region.type, {.points = points, .normals = normals, .weights = {}});
    if (refit.ok() && refit.rms_distance < before.rms) {
      region.surface = refit.surface;
      region.rms_distance = refit.rms_distance;
      region.max_distance = refit.max_distance;
    } else {
      region.rms_distance = before.rms;
      region.max_distance = before.max;
    }
  }
}

}  // namespace meshseg::pipeline_internal
