// Builds the TriMesh from polygons: fan triangulation, dropping of degenerate,
// duplicate and non-manifold triangles, and the input-face map.
#include <cmath>
#include <mutex>

#include <Eigen/Geometry>
#include <OpenMesh/Core/System/omstream.hh>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/input_size.h"
#include "meshseg/mesh.h"
#include "meshseg/status_macros.h"
#include "mesh/input_topology.h"
#include "mesh/manifold_build.h"
#include "mesh/normals.h"
#include "mesh/raw_mesh.h"

namespace meshseg {
namespace mesh_internal {
namespace {

// Zero area, relative to the longest edge: |cross| <= kFlat * l_max^2.
constexpr double kFlat = 1e-12;

// OpenMesh reports refused faces on its global omerr(); core never prints.
void SilenceOpenMesh() {
  static std::once_flag once;
  std::call_once(once, [] {
    omerr().disable();
    omlog().disable();
    omout().disable();
  });
}

bool IsDegenerate(const std::array<int, 3>& t, const LargeVector<Eigen::Vector3d>& v) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  const Eigen::Vector3d e0 = v[t[1]] - v[t[0]];
  const Eigen::Vector3d e1 = v[t[2]] - v[t[0]];
  const Eigen::Vector3d e2 = v[t[2]] - v[t[1]];
  const double l_max_sq = std::max({e0.squaredNorm(), e1.squaredNorm(), e2.squaredNorm()});
  return e0.cross(e1).norm() <= kFlat * l_max_sq;
}

}  // namespace

absl::Status CheckFinite(const Source& src, const std::vector<Eigen::Vector3d>& vertices) {
  for (size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite()) {
      return BadInput(src, absl::StrCat("vertex ", i, " has a non-finite coordinate (",
                                        vertices[i].x(), ", ", vertices[i].y(), ", ",
                                        vertices[i].z(), ")"));
    }
  }
  return absl::OkStatus();
}

namespace {

// Fills *out (a default Mesh) from `raw`; see BuildFromRaw.
absl::Status Fill(RawMesh raw, const Source& src, Mesh* out) {
  const int64_t nv = static_cast<int64_t>(raw.vertices.size());
  const int64_t nf = raw.face_count();
  if (nv == 0) return BadInput(src, "no vertices");
  if (nf <= 0) return BadInput(src, "no faces");
  if (nv > std::numeric_limits<int>::max()) {
    return BadInput(src, absl::StrCat(nv, " vertices, over the limit of ",
                                      std::numeric_limits<int>::max()));
  }
  for (int64_t i = 0; i < nv; ++i) {
    const double m = raw.vertices[i].cwiseAbs().maxCoeff();
    if (m > kMaxCoordinate) {  // beyond it, areas here and fits downstream overflow
      return BadInput(src, absl::StrCat("vertex ", i, " has coordinate ", m, ", beyond the +-",
                                        kMaxCoordinate,
                                        " whose fourth powers the surface fits can sum without "
                                        "overflow; rescale the part"));
    }
  }
  // Fan triangulation; tri_face[t] is the input face of triangle t.
  Triangles tris;
  LargeVector<int> tri_face;
  tris.reserve(raw.corners.size() >= 2 * static_cast<size_t>(nf)
                   ? raw.corners.size() - 2 * nf : 0);
  tri_face.reserve(tris.capacity());
  for (int64_t f = 0; f < nf; ++f) {
    const int64_t begin = raw.face_start[f];
    const int64_t end = raw.face_start[f + 1];
    if (end - begin < 3) {
      return BadInput(src, absl::StrCat("face ", f, " has ", end - begin, " corners"));
    }
    for (int64_t c = begin; c < end; ++c) {
      if (raw.corners[c] < 0 || raw.corners[c] >= nv) {
        return BadInput(src, absl::StrCat("face ", f, ": vertex index ", raw.corners[c],
                                          " out of range [0, ", nv, ")"));
      }
    }
    for (int64_t c = begin + 1; c + 1 < end; ++c) {
      tris.push_back({raw.corners[begin], raw.corners[c], raw.corners[c + 1]});
      tri_face.push_back(static_cast<int>(f));
    }
  }
  Mesh& mesh = *out;
  mesh.name = src.name;
  mesh.input_vertex_count = raw.input_vertex_count > 0 ? raw.input_vertex_count : nv;
  InputTopology& topo = mesh.input_topology;
  LargeVector<uint8_t> keep(tris.size(), 1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tris.size(), 8192),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t t = range.begin(); t < range.end(); ++t) {
                        if (IsDegenerate(tris[t], raw.vertices)) keep[t] = 0;
                      }
                    });
  // Degenerate input faces: those whose triangles are all degenerate.
  for (int64_t f = 0, t = 0; f < nf; ++f) {
    bool any = false;
    for (; t < static_cast<int64_t>(tris.size()) && tri_face[t] == f; ++t) any |= keep[t];
    topo.degenerate_face_count += !any;
  }
  const TopologyCounts counts = AnalyzeInputTopology(static_cast<int>(nv), tris, &keep);
  topo.duplicate_face_count = counts.duplicate_face_count;
  topo.non_manifold_edge_count = counts.non_manifold_edge_count;
  topo.non_manifold_vertex_count = counts.non_manifold_vertex_count;

  SilenceOpenMesh();
  TriMesh& tri = mesh.tri;
  tri.reserve(nv, 3 * tris.size() / 2 + 3, tris.size());
  // All vertices at once: add_vertex() would grow every vertex property
  // one element at a time.
  tri.resize(nv, 0, 0);
  for (int64_t i = 0; i < nv; ++i) {
    const Eigen::Vector3d& p = raw.vertices[i];
    tri.set_point(TriMesh::VertexHandle(static_cast<int>(i)),
                  TriMesh::Point(p.x(), p.y(), p.z()));
  }
  mesh.face_of_input.assign(nf, -1);
  // Kept triangles move to the front, in order; tri_face follows.
  size_t kept_count = 0;
  for (size_t t = 0; t < tris.size(); ++t) {
    if (keep[t]) {
      tris[kept_count] = tris[t];
      tri_face[kept_count++] = tri_face[t];
    }
  }
  tris.resize(kept_count);
  Triangles& kept = tris;
  const LargeVector<int>& kept_face = tri_face;
  const bool manifold = counts.non_manifold_edge_count == 0 &&
                        counts.non_manifold_vertex_count == 0 && BuildManifold(kept, &tri);
  for (size_t t = 0; t < kept.size(); ++t) {
    int face = static_cast<int>(t);
    if (!manifold) {
      face = tri.add_face(TriMesh::VertexHandle(kept[t][0]), TriMesh::VertexHandle(kept[t][1]),
                          TriMesh::VertexHandle(kept[t][2]))
                 .idx();
      if (face < 0) {
        ++topo.refused_face_count;
        continue;
      }
    }
    int& entry = mesh.face_of_input[kept_face[t]];
    if (entry < 0) entry = face;
  }
  if (tri.n_faces() == 0) {
    return BadInput(src, absl::StrCat("all ", nf, " faces dropped (", topo.degenerate_face_count,
                                      " degenerate, ", topo.duplicate_face_count, " duplicate, ",
                                      topo.refused_face_count, " non-manifold)"));
  }
  SetNormals(&tri);
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<Mesh> BuildFromRaw(RawMesh raw, const Source& src) {
  // Built in place: OpenMesh 9 meshes have no move constructor, so returning
  // a local Mesh would copy it.
  absl::StatusOr<Mesh> result(absl::in_place);
  const absl::Status status = Fill(std::move(raw), src, &*result);
  if (!status.ok()) result = status;
  return result;
}

}  // namespace mesh_internal

absl::StatusOr<Mesh> BuildMesh(std::vector<Eigen::Vector3d> vertices,
                               const std::vector<std::array<int, 3>>& triangles,
                               std::string name) {
  const mesh_internal::Source src{"build_mesh", std::move(name)};
  MESHSEG_RETURN_IF_ERROR(mesh_internal::CheckFinite(src, vertices));
  mesh_internal::RawMesh raw;
  raw.input_vertex_count = static_cast<int64_t>(vertices.size());
  raw.vertices.assign(vertices.begin(), vertices.end());
  raw.corners.reserve(3 * triangles.size());
  raw.face_start.reserve(triangles.size() + 1);
  for (size_t t = 0; t < triangles.size(); ++t) {
    raw.corners.insert(raw.corners.end(), triangles[t].begin(), triangles[t].end());
    raw.face_start.push_back(static_cast<int64_t>(raw.corners.size()));
  }
  return mesh_internal::BuildFromRaw(std::move(raw), src);
}

}  // namespace meshseg
