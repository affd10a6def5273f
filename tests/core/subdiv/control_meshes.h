// Small control meshes with known structure for the subdiv tests.
#ifndef MESHSEG_TESTS_CORE_SUBDIV_CONTROL_MESHES_H_
#define MESHSEG_TESTS_CORE_SUBDIV_CONTROL_MESHES_H_

#include <cmath>

#include "meshseg/subdiv.h"

namespace meshseg::testing {

// A regular lattice of (nx + 1) x (ny + 1) vertices at (i, j, z(i, j)),
// triangulated along the (1, 1) diagonal: interior vertices have the six
// neighbours (+-1, 0), (0, +-1), +-(1, 1) of the three-direction box spline.
// The four lattice corners are tagged corners.
template <class Height>
ControlMesh Lattice(int nx, int ny, Height z) {
  ControlMesh m;
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) m.vertices.emplace_back(i, j, z(i, j));
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  m.corners = {id(0, 0), id(nx, 0), id(0, ny), id(nx, ny)};
  return m;
}

// A closed octahedron with perturbed vertices: poles 0 (top) and 5, equator
// 1-4. The equator is a crease loop, vertex 1 a tagged corner, and the edge
// from the top pole to vertex 3 a crease ending there: the top pole is a
// dart, vertex 3 a corner (three sharp edges), vertices 2 and 4 crease
// vertices, the bottom pole a smooth vertex of valence 4.
inline ControlMesh CreasedOctahedron() {
  ControlMesh m;
  m.vertices = {{0.1, -0.05, 1.2}, {1.0, 0.1, 0.0},  {0.05, 0.9, 0.2},
                {-1.1, 0.0, -0.1}, {0.0, -1.0, 0.1}, {-0.1, 0.05, -0.9}};
  m.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1},
             {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}};
  m.creases = {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {0, 3}};
  m.corners = {1};
  return m;
}

}  // namespace meshseg::testing

#endif  // MESHSEG_TESTS_CORE_SUBDIV_CONTROL_MESHES_H_
