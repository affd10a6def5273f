// Short non-separating loops of a surface mesh: the handles too thin for the
// points to resolve (issue 38 item 1, "no handle that the points do not
// support"; our addition to the reconstruction of ALGORITHMS.md S3).
//
// Principle (Guskov & Wood 2001, "Topological noise removal"): a handle whose
// shortest cycle is only a few sample spacings long is below the resolution
// of the sampling, so the points cannot tell it from a surface without it;
// the reconstruction's implicit function closes it across near-contact gaps
// (two sheets within a spacing or two, a slot narrower than the noise). Each
// seed v grows a geodesic ball (Dijkstra over the mesh edges) of radius
// max_loop(v) / 2 (widened by one edge, below), which holds every loop
// through v of length max_loop(v). A ball of Euler characteristic 1 is a
// disc and holds none that is not contractible; otherwise such loops come
// from a tree-cotree decomposition of the ball (the shortest-path tree from
// v, a spanning tree of the dual graph with the ball's border as one node,
// taken greedily longest loop first; Erickson & Whittlesey 2005): the
// shortest leftover edge closes the shortest such loop through v, and its
// tail to v is dropped. Whether a loop is a handle is handle_strips.h's test.
// Seeds whose ball lies inside a larger ball that is a disc (connected,
// Euler characteristic 1) are not searched: every loop there separates the
// surface, so none of them could be cut (the covering, in ShortLoops).
#ifndef MESHSEG_RECONSTRUCT_HANDLE_LOOPS_H_
#define MESHSEG_RECONSTRUCT_HANDLE_LOOPS_H_

#include <array>
#include <cstdint>
#include <vector>

#include "meshseg/mesh.h"

namespace meshseg::reconstruct_internal {

// The mesh as flat arrays: vertex rings, faces and the faces of each edge.
struct MeshGraph {
  std::vector<int> ring_begin;  // per vertex, into to/edge/length; one more at the end
  std::vector<int> to, edge;
  std::vector<double> length;
  std::vector<int> faces_begin, faces;  // faces around each vertex
  std::vector<std::array<int, 3>> face_vertices, face_edges;
  std::vector<std::array<int, 2>> edge_faces;  // -1 on a border
  std::vector<double> edge_length;
};

MeshGraph MakeMeshGraph(const TriMesh& tri);

// A simple closed path of mesh vertices and its length (model units).
struct HandleLoop {
  double length = 0.0;
  std::vector<int> vertices;
};

// Loops of `g` not contractible in the geodesic ball they were found in, at
// most max_loop[v] long (model units) for the seed v they were found from,
// shortest first (several seeds may find the same loop). Every vertex is a
// seed or next to one (a maximal independent set), so a loop passes within
// one edge of a seed and lies in its ball of radius max_loop / 2 widened by
// the seed's longest edge. Loops inside a disc of the surface (they separate
// it) are not all returned: seeds whose balls lie in a covering disc are
// skipped. With `near` (one per vertex) not empty, only seeds within
// max_loop of a flagged vertex are used.
std::vector<HandleLoop> ShortLoops(const MeshGraph& g, const std::vector<double>& max_loop,
                                   const std::vector<uint8_t>& near = {});

}  // namespace meshseg::reconstruct_internal

#endif  // MESHSEG_RECONSTRUCT_HANDLE_LOOPS_H_
