#include "segment/facet_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <thread>
#include <type_traits>
#include <variant>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::segment_internal {

namespace {

// A vertex strictly inside a segment between two of its neighbours, not at
// its ends' tenth of it (a vertex put on an edge, not a corner of a fan).
constexpr double kChordInside = 0.1;

// fm.chord_ends and chord_offset of vertex v, from their initial {-1, -1}
// and infinity (`ring`: scratch).
void FindChordVertex(const TriMesh& mesh, TriMesh::VertexHandle v, const FacetMesh& fm,
                     std::vector<int>* ring) {
  ring->clear();
  for (const auto w : mesh.vv_range(v)) ring->push_back(w.idx());
  const Eigen::Vector3d& p = fm.points[v.idx()];
  for (std::size_t i = 0; i < ring->size(); ++i) {
    for (std::size_t j = i + 1; j < ring->size(); ++j) {
      const Eigen::Vector3d& a = fm.points[(*ring)[i]];
      const Eigen::Vector3d ab = fm.points[(*ring)[j]] - a;
      const double length2 = ab.squaredNorm();
      if (!(length2 > 0.0)) continue;
      const double t = (p - a).dot(ab) / length2;
      if (t < kChordInside || t > 1.0 - kChordInside) continue;
      const double offset = (a + t * ab - p).norm();
      if (offset < fm.chord_offset[v.idx()]) {
        fm.chord_offset[v.idx()] = offset;
        fm.chord_ends[v.idx()] = {(*ring)[i], (*ring)[j]};
      }
    }
  }
}

// fm->chord_ends and chord_offset (facet_mesh.h): up front, each vertex on
// its own (independent; the mesh is only read), or left to be found on
// first use.
void FindChordVertices(const TriMesh& mesh, ChordVertices when, FacetMesh* fm) {
  const int n = static_cast<int>(fm->points.size());
  fm->chord_ends.assign(n, {-1, -1});
  fm->chord_offset.assign(n, std::numeric_limits<double>::infinity());
  if (when == ChordVertices::kOnFirstUse) {
    fm->chord_source = &mesh;
    fm->chord_state = std::make_unique<std::atomic<uint8_t>[]>(n);  // all 0: not found
    return;
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 4096), [&](const tbb::blocked_range<int>& range) {
    std::vector<int> ring;
    for (int index = range.begin(); index < range.end(); ++index) {
      const TriMesh::VertexHandle v(index);
      if (mesh.has_vertex_status() && mesh.status(v).deleted()) continue;
      FindChordVertex(mesh, v, *fm, &ring);
    }
  });
}

}  // namespace

void FacetMesh::FindChordOnFirstUse(int v) const {
  std::atomic<uint8_t>& state = chord_state[v];
  if (state.load(std::memory_order_acquire) == 2) return;
  uint8_t expected = 0;
  if (state.compare_exchange_strong(expected, 1, std::memory_order_acquire)) {
    const TriMesh::VertexHandle vh(v);
    if (!(chord_source->has_vertex_status() && chord_source->status(vh).deleted())) {
      thread_local std::vector<int> ring;
      FindChordVertex(*chord_source, vh, *this, &ring);
    }
    state.store(2, std::memory_order_release);
    return;
  }
  // Another thread is finding them: wait for its entries.
  while (state.load(std::memory_order_acquire) != 2) std::this_thread::yield();
}

FacetMesh BuildFacetMesh(const TriMesh& mesh, ChordVertices chords) {
  FacetMesh fm;
  const int n_vertices = static_cast<int>(mesh.n_vertices());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto v : mesh.vertices()) {
    const Eigen::Vector3d p = ToEigen(mesh.point(v));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (n_vertices > 0) {
    fm.origin = 0.5 * (lo + hi);
    fm.diagonal = (hi - lo).norm();
  }
  fm.points.resize(n_vertices);
  for (const auto v : mesh.vertices()) fm.points[v.idx()] = ToEigen(mesh.point(v)) - fm.origin;
  const int n_faces = static_cast<int>(mesh.n_faces());
  fm.corners.resize(n_faces);
  fm.across.resize(n_faces);
  fm.normal.resize(n_faces);
  fm.area.resize(n_faces);
  // Each facet on its own (independent; the mesh is only read).
  tbb::parallel_for(
      tbb::blocked_range<int>(0, n_faces, 4096), [&](const tbb::blocked_range<int>& range) {
        for (int index = range.begin(); index < range.end(); ++index) {
          const TriMesh::FaceHandle f(index);
          if (mesh.has_face_status() && mesh.status(f).deleted()) continue;
          int k = 0;
          for (const auto h : mesh.fh_range(f)) {
            if (k == 3) break;
            fm.corners[index][k] = mesh.from_vertex_handle(h).idx();
            const auto g = mesh.opposite_face_handle(h);
            fm.across[index][k] = g.is_valid() ? g.idx() : -1;
            ++k;
          }
          const std::array<int, 3>& c = fm.corners[index];
          const Eigen::Vector3d cross =
              (fm.points[c[1]] - fm.points[c[0]]).cross(fm.points[c[2]] - fm.points[c[0]]);
          const double norm = cross.norm();
          fm.area[index] = 0.5 * norm;
          fm.normal[index] = norm > 0.0 ? Eigen::Vector3d(cross / norm) : Eigen::Vector3d::Zero();
        }
      });
  FindChordVertices(mesh, chords, &fm);
  return fm;
}

std::vector<int> CornersOf(const FacetMesh& fm, const std::vector<int>& facets) {
  std::vector<int> v;
  v.reserve(3 * facets.size());
  for (const int f : facets) v.insert(v.end(), fm.corners[f].begin(), fm.corners[f].end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

Surface Translated(const Surface& surface, const Eigen::Vector3d& shift) {
  return std::visit(
      [&](auto s) -> Surface {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Plane>) {
          s.point += shift;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          s.axis_origin += shift;
        } else if constexpr (std::is_same_v<T, Cone>) {
          s.apex += shift;
        } else if constexpr (std::is_same_v<T, Sphere> || std::is_same_v<T, Torus>) {
          s.center += shift;
        } else {
          // f(x - shift): expand the linear and constant terms.
          const auto& c = s.c;
          const double x = shift.x(), y = shift.y(), z = shift.z();
          Quadric q = s;
          q.c[6] = c[6] - 2 * c[0] * x - c[3] * y - c[5] * z;
          q.c[7] = c[7] - 2 * c[1] * y - c[3] * x - c[4] * z;
          q.c[8] = c[8] - 2 * c[2] * z - c[4] * y - c[5] * x;
          q.c[9] = c[9] + c[0] * x * x + c[1] * y * y + c[2] * z * z + c[3] * x * y + c[4] * y * z +
                   c[5] * z * x - c[6] * x - c[7] * y - c[8] * z;
          return q;
        }
        return s;
      },
      surface);
}

}  // namespace meshseg::segment_internal
