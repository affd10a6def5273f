#include "mesh/normals.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::mesh_internal {

void SetNormals(TriMesh* mesh) {
  TriMesh& m = *mesh;
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(m.n_faces()), 8192),
                    [&m](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      const TriMesh::FaceHandle fh(f);
      const TriMesh::HalfedgeHandle h0 = m.halfedge_handle(fh);
      const TriMesh::HalfedgeHandle h1 = m.next_halfedge_handle(h0);
      const TriMesh::Point& p0 = m.point(m.from_vertex_handle(h0));
      const TriMesh::Point& p1 = m.point(m.to_vertex_handle(h0));
      const TriMesh::Point& p2 = m.point(m.to_vertex_handle(h1));
      TriMesh::Normal n = OpenMesh::cross(p1 - p0, p2 - p0);
      const double length = n.norm();
      if (length > 0.0) n /= length;
      m.set_normal(fh, n);
    }
  });
  tbb::parallel_for(tbb::blocked_range<int>(0, static_cast<int>(m.n_vertices()), 8192),
                    [&m](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      const TriMesh::VertexHandle vh(v);
      TriMesh::Normal n(0.0, 0.0, 0.0);
      for (const TriMesh::FaceHandle fh : m.vf_range(vh)) n += m.normal(fh);
      const double length = n.norm();
      if (length > 0.0) n /= length;
      m.set_normal(vh, n);
    }
  });
}

}  // namespace meshseg::mesh_internal
