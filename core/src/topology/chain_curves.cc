#include "topology/chain_curves.h"

#include <algorithm>
#include <cassert>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace meshseg::topology_internal {
namespace {

using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// The label that goes on a curve's left for the pair {a, b}, a != b.
int CurveLeft(int a, int b) {
  if (a < 0) return b;
  if (b < 0) return a;
  return std::min(a, b);
}

// True if `h` is a boundary halfedge running in its curve's direction.
bool IsForward(const TriMesh& mesh, std::span<const int> labels, HalfedgeHandle h) {
  const int left = LeftLabel(mesh, labels, h);
  const int right = LeftLabel(mesh, labels, mesh.opposite_halfedge_handle(h));
  return left != right && left == CurveLeft(left, right);
}

// Corner test: three or more labels around v (the border counting as -1), or
// a boundary edge count other than 0 and 2.
bool IsCorner(const TriMesh& mesh, std::span<const int> labels, VertexHandle v) {
  int boundary_edges = 0;
  int seen[3];  // the first three distinct labels; a third one decides
  int seen_count = 0;
  for (HalfedgeHandle h : mesh.voh_range(v)) {
    const int l = LeftLabel(mesh, labels, h);
    if (std::find(seen, seen + seen_count, l) == seen + seen_count) {
      if (seen_count == 2) return true;
      seen[seen_count++] = l;
    }
    if (IsBoundaryHalfedge(mesh, labels, h)) ++boundary_edges;
  }
  return boundary_edges != 0 && boundary_edges != 2;
}

// The unassigned forward halfedge leaving v with the labels of `in`.
HalfedgeHandle ContinueFrom(const TriMesh& mesh, std::span<const int> labels,
                            const std::vector<int>& halfedge_curve, HalfedgeHandle in) {
  const int left = LeftLabel(mesh, labels, in);
  const int right = LeftLabel(mesh, labels, mesh.opposite_halfedge_handle(in));
  for (HalfedgeHandle h : mesh.voh_range(mesh.to_vertex_handle(in))) {
    if (halfedge_curve[h.idx()] >= 0 || !IsForward(mesh, labels, h)) continue;
    if (LeftLabel(mesh, labels, h) == left &&
        LeftLabel(mesh, labels, mesh.opposite_halfedge_handle(h)) == right) {
      return h;
    }
  }
  return HalfedgeHandle();
}

// True for an item that mesh.vertices() / mesh.halfedges() pass over (deleted
// or hidden, where the mesh keeps that status).
bool Skipped(const TriMesh& mesh, VertexHandle v) {
  return mesh.has_vertex_status() && (mesh.status(v).deleted() || mesh.status(v).hidden());
}
bool Skipped(const TriMesh& mesh, HalfedgeHandle h) {
  return mesh.has_halfedge_status() && (mesh.status(h).deleted() || mesh.status(h).hidden());
}

}  // namespace

int LeftLabel(const TriMesh& mesh, std::span<const int> face_labels, HalfedgeHandle h) {
  const OpenMesh::FaceHandle f = mesh.face_handle(h);
  return f.is_valid() ? face_labels[f.idx()] : -1;
}

bool IsBoundaryHalfedge(const TriMesh& mesh, std::span<const int> face_labels, HalfedgeHandle h) {
  return LeftLabel(mesh, face_labels, h) !=
         LeftLabel(mesh, face_labels, mesh.opposite_halfedge_handle(h));
}

CurveChains ChainCurves(const TriMesh& mesh, std::span<const int> face_labels) {
  CurveChains out;
  out.halfedge_curve.assign(mesh.n_halfedges(), -1);
  // Corners and forward halfedges depend only on the labels: found side by
  // side, then numbered and walked in index order.
  const int vertex_count = static_cast<int>(mesh.n_vertices());
  const int halfedge_count = static_cast<int>(mesh.n_halfedges());
  std::vector<int> corner_of_vertex(vertex_count, -1);
  std::vector<char> forward(halfedge_count, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, vertex_count, 4096),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int v = r.begin(); v < r.end(); ++v) {
                        const VertexHandle vh(v);
                        corner_of_vertex[v] =
                            !Skipped(mesh, vh) && IsCorner(mesh, face_labels, vh) ? 0 : -1;
                      }
                    });
  tbb::parallel_for(tbb::blocked_range<int>(0, halfedge_count, 8192),
                    [&](const tbb::blocked_range<int>& r) {
                      for (int h = r.begin(); h < r.end(); ++h) {
                        forward[h] = IsForward(mesh, face_labels, HalfedgeHandle(h));
                      }
                    });
  for (int v = 0; v < vertex_count; ++v) {
    if (corner_of_vertex[v] < 0) continue;
    corner_of_vertex[v] = static_cast<int>(out.corner_vertices.size());
    out.corner_vertices.push_back(v);
  }
  // Walks from `start` until a corner or back to `start`.
  auto trace = [&](HalfedgeHandle start) {
    BoundaryCurve curve;
    curve.id = static_cast<int>(out.curves.size());
    curve.left_region = LeftLabel(mesh, face_labels, start);
    curve.right_region = LeftLabel(mesh, face_labels, mesh.opposite_halfedge_handle(start));
    const VertexHandle first = mesh.from_vertex_handle(start);
    curve.start_corner = corner_of_vertex[first.idx()];
    curve.vertices.push_back(first.idx());
    HalfedgeHandle h = start;
    while (h.is_valid()) {
      out.halfedge_curve[h.idx()] = curve.id;
      const VertexHandle to = mesh.to_vertex_handle(h);
      curve.vertices.push_back(to.idx());
      if (corner_of_vertex[to.idx()] >= 0) {
        curve.end_corner = corner_of_vertex[to.idx()];
        break;
      }
      h = ContinueFrom(mesh, face_labels, out.halfedge_curve, h);
    }
    curve.closed = curve.vertices.front() == curve.vertices.back();
    assert((curve.end_corner >= 0 || curve.closed) && "a curve ends at a corner or closes");
    out.curves.push_back(std::move(curve));
  };
  // Open curves (and closed ones through a corner) start at corners.
  for (const int v : out.corner_vertices) {
    for (HalfedgeHandle h : mesh.voh_range(VertexHandle(v))) {
      if (out.halfedge_curve[h.idx()] < 0 && forward[h.idx()]) trace(h);
    }
  }
  // What is left are closed curves without corners.
  for (int h = 0; h < halfedge_count; ++h) {
    const HalfedgeHandle hh(h);
    if (out.halfedge_curve[h] < 0 && forward[h] && !Skipped(mesh, hh)) trace(hh);
  }
  return out;
}

}  // namespace meshseg::topology_internal
