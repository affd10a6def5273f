// Invariants every Topology must satisfy, checked with GoogleTest
// expectations: each boundary edge on exactly one curve, curves bounding two
// regions (or one at a border), closed loops, and Euler's formula.
#ifndef MESHSEG_TESTS_CORE_TOPOLOGY_TOPOLOGY_CHECKS_H_
#define MESHSEG_TESTS_CORE_TOPOLOGY_TOPOLOGY_CHECKS_H_

#include <algorithm>
#include <set>
#include <span>
#include <utility>

#include <gtest/gtest.h>

#include "meshseg/mesh.h"
#include "meshseg/topology.h"

namespace meshseg::testing {

inline int SideLabel(const TriMesh& mesh, std::span<const int> labels,
                     OpenMesh::HalfedgeHandle h) {
  const OpenMesh::FaceHandle f = mesh.face_handle(h);
  return f.is_valid() ? labels[f.idx()] : -1;
}

// Euler characteristic of the B-rep complex, chi = V - E + 2F - L, with
// V = corners + closed curves without a corner (each given one vertex),
// E = curves, F = region patches, L = loops. For genus-0 patches this is
// V - E + F - (L - F), the Euler–Poincaré count with L - F ring loops, and
// equals V - E + F of the labelled part of the mesh.
inline int BrepEulerCharacteristic(const Topology& topo) {
  int vertices = static_cast<int>(topo.corners.size());
  for (const BoundaryCurve& c : topo.curves) {
    if (c.start_corner < 0) ++vertices;
  }
  int faces = 0;
  for (const RegionTopology& r : topo.regions) faces += r.patch_count;
  return vertices - static_cast<int>(topo.curves.size()) + 2 * faces -
         static_cast<int>(topo.loops.size());
}

// V - E + F of the labelled faces (label >= 0) with their edges and vertices.
inline int LabelledEulerCharacteristic(const TriMesh& mesh, std::span<const int> labels) {
  std::set<int> vertices;
  std::set<int> edges;
  int faces = 0;
  for (auto f : mesh.faces()) {
    if (labels[f.idx()] < 0) continue;
    ++faces;
    for (auto h : mesh.fh_range(f)) {
      edges.insert(mesh.edge_handle(h).idx());
      vertices.insert(mesh.to_vertex_handle(h).idx());
    }
  }
  return static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) + faces;
}

// First and last vertex of a curve use in loop order.
inline std::pair<int, int> UseEnds(const Topology& topo, const CurveUse& use) {
  const std::vector<int>& v = topo.curves[use.curve].vertices;
  return use.reversed ? std::make_pair(v.back(), v.front()) : std::make_pair(v.front(), v.back());
}

inline void ExpectConsistent(const TriMesh& mesh, std::span<const int> labels,
                             const Topology& topo) {
  std::set<std::pair<int, int>> curve_edges;
  for (const BoundaryCurve& c : topo.curves) {
    EXPECT_GE(c.left_region, 0) << "curve " << c.id;
    EXPECT_NE(c.left_region, c.right_region) << "curve " << c.id;
    EXPECT_EQ(c.closed, c.vertices.front() == c.vertices.back()) << "curve " << c.id;
    EXPECT_TRUE(c.closed || c.start_corner >= 0) << "open curve " << c.id << " without corner";
    for (size_t i = 0; i + 1 < c.vertices.size(); ++i) {
      const auto h = mesh.find_halfedge(OpenMesh::VertexHandle(c.vertices[i]),
                                        OpenMesh::VertexHandle(c.vertices[i + 1]));
      ASSERT_TRUE(h.is_valid()) << "curve " << c.id << " step " << i << " is no mesh edge";
      EXPECT_EQ(SideLabel(mesh, labels, h), c.left_region) << "curve " << c.id;
      EXPECT_EQ(SideLabel(mesh, labels, mesh.opposite_halfedge_handle(h)), c.right_region)
          << "curve " << c.id;
      const auto edge = std::minmax(c.vertices[i], c.vertices[i + 1]);
      EXPECT_TRUE(curve_edges.insert(edge).second)
          << "edge " << edge.first << "-" << edge.second << " on two curves";
    }
  }
  int boundary_edges = 0;
  for (auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0);
    if (SideLabel(mesh, labels, h) != SideLabel(mesh, labels, mesh.opposite_halfedge_handle(h))) {
      ++boundary_edges;
    }
  }
  EXPECT_EQ(static_cast<int>(curve_edges.size()), boundary_edges);
  for (const Loop& loop : topo.loops) {
    ASSERT_FALSE(loop.curves.empty()) << "loop " << loop.id;
    for (size_t i = 0; i < loop.curves.size(); ++i) {
      const CurveUse& use = loop.curves[i];
      const BoundaryCurve& c = topo.curves[use.curve];
      EXPECT_EQ(use.reversed ? c.right_region : c.left_region, loop.region) << "loop " << loop.id;
      const CurveUse& next = loop.curves[(i + 1) % loop.curves.size()];
      EXPECT_EQ(UseEnds(topo, use).second, UseEnds(topo, next).first)
          << "loop " << loop.id << " breaks after use " << i;
    }
  }
  EXPECT_EQ(BrepEulerCharacteristic(topo), LabelledEulerCharacteristic(mesh, labels));
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_TOPOLOGY_TOPOLOGY_CHECKS_H_
