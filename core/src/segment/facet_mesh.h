// The mesh as the exact-facet path reads it: corner positions relative to
// the centre of the bounding box (so a part far from the origin is fitted
// on small numbers), the three neighbours of each facet across its edges,
// unit facet normals and areas.
#ifndef MESHSEG_SRC_SEGMENT_FACET_MESH_H_
#define MESHSEG_SRC_SEGMENT_FACET_MESH_H_

#include <Eigen/Core>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
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
  // Found for every vertex by BuildFacetMesh, or, with
  // ChordVertices::kOnFirstUse, for each vertex the first time OnChord or
  // ChordEnds reads it (a test that looks at a few thousand vertices need
  // not find them for all). Either way a vertex's entries are the same
  // function of its ring, so readers see the same values.
  mutable std::vector<std::array<int, 2>> chord_ends;
  mutable std::vector<double> chord_offset;

  // The mesh the chord vertices are found on when first read; null when
  // all were found up front.
  const TriMesh* chord_source = nullptr;
  // Per vertex with chord_source: 0 not found, 1 being found (by one
  // thread; others wait), 2 found.
  mutable std::unique_ptr<std::atomic<uint8_t>[]> chord_state;

  // Finds vertex v's chord entries if they are found on first use and not
  // yet found (safe from several threads at once).
  void EnsureChord(int v) const {
    if (chord_source != nullptr) FindChordOnFirstUse(v);
  }
  const std::array<int, 2>& ChordEnds(int v) const {
    EnsureChord(v);
    return chord_ends[v];
  }

  int facet_count() const { return static_cast<int>(corners.size()); }
  Eigen::Vector3d Centroid(int f) const {
    return (points[corners[f][0]] + points[corners[f][1]] + points[corners[f][2]]) / 3.0;
  }

  // EnsureChord's work once chord_source is set.
  void FindChordOnFirstUse(int v) const;
};

// True if vertex v lies within `tau` of the chord between its chord_ends.
inline bool OnChord(const FacetMesh& fm, int v, double tau) {
  fm.EnsureChord(v);
  return fm.chord_ends[v][0] >= 0 && fm.chord_offset[v] <= tau;
}

// Returns the distinct corners of `facets`, sorted.
std::vector<int> CornersOf(const FacetMesh& fm, const std::vector<int>& facets);

// When FacetMesh::chord_ends and chord_offset are found.
enum class ChordVertices { kUpFront, kOnFirstUse };

// Returns `mesh` as a FacetMesh. With kOnFirstUse the chord entries are
// found as read, on `mesh`, which must then outlive the FacetMesh.
FacetMesh BuildFacetMesh(const TriMesh& mesh, ChordVertices chords = ChordVertices::kUpFront);

// Returns `surface` moved by `shift` (a FacetMesh surface back into the
// input's frame: shift = origin).
Surface Translated(const Surface& surface, const Eigen::Vector3d& shift);

}  // namespace meshseg::segment_internal

#endif  // MESHSEG_SRC_SEGMENT_FACET_MESH_H_
