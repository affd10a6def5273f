// The marching-cubes case table, derived from first principles instead of
// typed in: for each of the 256 inside/outside patterns of a cube's corners,
// the iso-contour is traced face by face and closed into loops, which are
// fan-triangulated. An ambiguous face (diagonal corners alike) always
// separates its inside corners; the decision depends on that face's corners
// only, so two cubes sharing a face cut it alike and the mesh is watertight.
#ifndef MESHSEG_VOXEL_MC_TABLE_H_
#define MESHSEG_VOXEL_MC_TABLE_H_

#include <array>
#include <cstdint>
#include <vector>

namespace meshseg::voxel_internal {

// Corner c of the unit cube sits at (c & 1, (c >> 1) & 1, (c >> 2) & 1).
// Edge e joins kCubeEdgeCorners[e][0] and [1]; edges 0-3 run along x, 4-7
// along y, 8-11 along z, and the first corner is the one at the lower end.
inline constexpr std::array<std::array<int, 2>, 12> kCubeEdgeCorners = {{
    {0, 1},
    {2, 3},
    {4, 5},
    {6, 7},  // x
    {0, 2},
    {1, 3},
    {4, 6},
    {5, 7},  // y
    {0, 4},
    {1, 5},
    {2, 6},
    {3, 7},  // z
}};

// Triangles of one case as cube-edge ids, oriented so that their normals
// point to the outside (the corners whose bit is 0).
using McCase = std::vector<std::array<int8_t, 3>>;

// Index: bit c set = corner c inside the solid.
using McTable = std::array<McCase, 256>;

// Returns the table described above.
McTable BuildMcTable();

}  // namespace meshseg::voxel_internal

#endif  // MESHSEG_VOXEL_MC_TABLE_H_
