// CreaseEdges(): an edge is a crease when the surface turns across it by
// more than the limit, measured at the scale of the one-ring rather than of
// single faces. Scan and marching-cubes meshes hold slivers whose normals
// the noise swings by tens of degrees (a face's normal error grows as the
// noise over its height), so each side's normal is the area-weighted mean of
// the edge's face and that face's two other edge neighbours: slivers weigh
// little, and on a smooth surface the three faces agree to within the
// curvature over two edge lengths.
#include <cmath>
#include <numbers>

#include "voxel/edge_collapse.h"

namespace meshseg::voxel_internal {

std::vector<uint8_t> CreaseEdges(const TriMesh& mesh, double min_deg) {
  // Area-weighted face normals (the cross product's length is twice the area).
  std::vector<Eigen::Vector3d> weighted(mesh.n_faces(), Eigen::Vector3d::Zero());
  for (auto f : mesh.faces()) {
    auto it = mesh.cfv_iter(f);
    const Eigen::Vector3d p0 = ToEigen(mesh.point(*it++)), p1 = ToEigen(mesh.point(*it++)),
                          p2 = ToEigen(mesh.point(*it));
    weighted[f.idx()] = (p1 - p0).cross(p2 - p0);
  }
  // The mean normal of the face left of halfedge h and its neighbours across
  // the face's two other edges.
  const auto side = [&](TriMesh::HalfedgeHandle h) {
    const auto f = mesh.face_handle(h);
    Eigen::Vector3d n = weighted[f.idx()];
    for (auto g : {mesh.face_handle(mesh.opposite_halfedge_handle(mesh.next_halfedge_handle(h))),
                   mesh.face_handle(mesh.opposite_halfedge_handle(mesh.prev_halfedge_handle(h)))}) {
      if (g.is_valid()) n += weighted[g.idx()];
    }
    return n;
  };
  const double min_cos = std::cos(min_deg * std::numbers::pi / 180.0);
  std::vector<uint8_t> crease(mesh.n_edges(), 0);
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) {
      crease[e.idx()] = 1;  // an open border is a feature line too
      continue;
    }
    const Eigen::Vector3d a = side(mesh.halfedge_handle(e, 0));
    const Eigen::Vector3d b = side(mesh.halfedge_handle(e, 1));
    const double la = a.norm(), lb = b.norm();
    if (la == 0.0 || lb == 0.0) continue;
    crease[e.idx()] = a.dot(b) < min_cos * la * lb;
  }
  return crease;
}

}  // namespace meshseg::voxel_internal
