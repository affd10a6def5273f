// The mesh as the exact-facet path reads it: corner positions relative to
// the centre of the bounding box (so a part far from the origin is fitted
// on small numbers), the three neighbours of each facet across its edges,
// unit facet normals and areas.
#ifndef MESHSEG_SRC_SEGMENT_FACET_MESH_H_
#define MESHSEG_SRC_SEGMENT_FACET_MESH_H_

#include <Eigen/Core>
#include <array>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/surface.h"

namespace meshseg::segment_internal {

struct FacetMesh {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // subtracted from every position
  std::vector<Eigen::Vector3d> points;               // per vertex, minus origin
  std::vector<std::array<int, 3>> corners;           // per facet
  // Per facet, the facet across the edge from corner k to corner k+1; -1 at
  // a border.
  std::vector<std::array<int, 3>> across;
  std::vector<Eigen::Vector3d> normal;  // unit; zero for a degenerate facet
  std::vector<double> area;
  double diagonal = 0.0;  // of the bounding box
  // Per vertex, the two edge neighbours whose segment passes nearest it
  // with the vertex between them ({-1, -1} if none), and that distance: a
  // vertex a tessellator put on an edge of a flat facet to meet the next
  // face (a T-junction made conforming) lies on that edge's chord, under a
  // curved surface by its sag, and is judged by the chord's ends
  // (facet_on_surface.h).
  std::vector<std::array<int, 2>> chord_ends;
  std::vector<double> chord_offset;

  int facet_count() const { return static_cast<int>(corners.size()); }
  Eigen::Vector3d Centroid(int f) const {
    return (points[corners[f][0]] + points[corners[f][1]] + points[corners[f][2]]) / 3.0;
  }
};

// True if vertex v lies within `tau` of the chord between its chord_ends.
inline bool OnChord(const FacetMesh& fm, int v, double tau) {
  return fm.chord_ends[v][0] >= 0 && fm.chord_offset[v] <= tau;
}

// Returns the distinct corners of `facets`, sorted.
std::vector<int> CornersOf(const FacetMesh& fm, const std::vector<int>& facets);

// Returns `mesh` as a FacetMesh.
FacetMesh BuildFacetMesh(const TriMesh& mesh);

// Returns `surface` moved by `shift` (a FacetMesh surface back into the
// input's frame: shift = origin).
Surface Translated(const Surface& surface, const Eigen::Vector3d& shift);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FACET_MESH_H_
