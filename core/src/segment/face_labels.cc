#include "segment/face_labels.h"

#include <cmath>

#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::segment_internal {

std::vector<int> FaceLabels(const SegmentContext& c, const TriMesh& mesh,
                            const std::vector<int>& labels,
                            const std::vector<RegionState>& regions) {
  const int nf = static_cast<int>(mesh.n_faces());
  std::vector<int> out(nf, -1);
  tbb::parallel_for(tbb::blocked_range<int>(0, nf, 2048), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      int v[3];
      int k = 0;
      for (auto it = mesh.cfv_iter(TriMesh::FaceHandle(f)); it.is_valid() && k < 3; ++it) {
        v[k++] = it->idx();
      }
      if (k != 3) continue;
      const int l0 = labels[v[0]];
      if (l0 == labels[v[1]] && l0 == labels[v[2]]) {
        out[f] = l0;
        continue;
      }
      const Eigen::Vector3d& a = c.position(v[0]);
      const Eigen::Vector3d& b = c.position(v[1]);
      const Eigen::Vector3d& d = c.position(v[2]);
      const Eigen::Vector3d centroid = (a + b + d) / 3.0;
      Eigen::Vector3d normal = (b - a).cross(d - a);
      if (normal.norm() > 0.0) normal.normalize();
      double best = -1.0;
      for (const int vi : v) {
        const int id = labels[vi];
        if (id < 0 || id == out[f]) continue;
        const double agree =
            std::abs(Project(regions[id].surface, centroid, normal).normal.dot(normal));
        if (agree > best || (agree == best && id < out[f])) {
          best = agree;
          out[f] = id;
        }
      }
    }
  });
  return out;
}

}  // namespace meshseg::segment_internal
