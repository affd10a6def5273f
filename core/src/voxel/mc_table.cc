#include "voxel/mc_table.h"

#include <cassert>
#include <utility>

#include <Eigen/Geometry>

namespace meshseg::voxel_internal {
namespace {

Eigen::Vector3d CornerPosition(int c) { return Eigen::Vector3d(c & 1, (c >> 1) & 1, (c >> 2) & 1); }

Eigen::Vector3d EdgeMidpoint(int e) {
  return 0.5 * (CornerPosition(kCubeEdgeCorners[e][0]) + CornerPosition(kCubeEdgeCorners[e][1]));
}

int EdgeOf(int c0, int c1) {
  for (int e = 0; e < 12; ++e) {
    const auto& ec = kCubeEdgeCorners[e];
    if ((ec[0] == c0 && ec[1] == c1) || (ec[0] == c1 && ec[1] == c0)) return e;
  }
  assert(false && "corners do not share a cube edge");
  return -1;
}

// Orients the contour segment a -> b on a face with outward normal `n` so
// that the inside corner `inside_corner` lies on the side of (b - a) x n;
// traced that way, every loop runs counter-clockwise seen from outside.
std::pair<int, int> Oriented(int a, int b, const Eigen::Vector3d& n, int inside_corner) {
  const Eigen::Vector3d mid = 0.5 * (EdgeMidpoint(a) + EdgeMidpoint(b));
  const Eigen::Vector3d d = EdgeMidpoint(b) - EdgeMidpoint(a);
  if (d.cross(n).dot(CornerPosition(inside_corner) - mid) < 0.0) return {b, a};
  return {a, b};
}

McCase BuildCase(int mask) {
  const auto inside = [mask](int c) { return ((mask >> c) & 1) != 0; };
  std::array<int, 12> next;
  next.fill(-1);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = side ? 1.0 : -1.0;
      // The face's corners in cyclic order and the edges q[i] -> q[i+1].
      const std::array<std::array<int, 2>, 4> uv = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
      std::array<int, 4> q;
      for (int i = 0; i < 4; ++i) q[i] = (side << axis) | (uv[i][0] << u) | (uv[i][1] << v);
      std::array<int, 4> edge;
      int crossings = 0;
      for (int i = 0; i < 4; ++i) {
        edge[i] = EdgeOf(q[i], q[(i + 1) % 4]);
        crossings += inside(q[i]) != inside(q[(i + 1) % 4]);
      }
      std::vector<std::pair<int, int>> segments;
      if (crossings == 2) {
        std::array<int, 2> cut{};
        int k = 0, in_corner = -1;
        for (int i = 0; i < 4; ++i) {
          if (inside(q[i]) != inside(q[(i + 1) % 4])) cut[k++] = edge[i];
          if (inside(q[i])) in_corner = q[i];
        }
        segments.push_back(Oriented(cut[0], cut[1], n, in_corner));
      } else if (crossings == 4) {
        // Ambiguous face: cut off each inside corner on its own.
        for (int i = 0; i < 4; ++i) {
          if (inside(q[i])) segments.push_back(Oriented(edge[(i + 3) % 4], edge[i], n, q[i]));
        }
      }
      for (const auto& [a, b] : segments) {
        assert(next[a] == -1 && "cube edge starts two contour segments");
        next[a] = b;
      }
    }
  }
  McCase triangles;
  std::array<bool, 12> done{};
  for (int start = 0; start < 12; ++start) {
    if (next[start] < 0 || done[start]) continue;
    std::vector<int> loop;
    for (int e = start; !done[e]; e = next[e]) {
      done[e] = true;
      loop.push_back(e);
      assert(next[e] >= 0 && "open contour on the cube");
    }
    for (size_t i = 1; i + 1 < loop.size(); ++i) {
      triangles.push_back({static_cast<int8_t>(loop[0]), static_cast<int8_t>(loop[i]),
                           static_cast<int8_t>(loop[i + 1])});
    }
  }
  return triangles;
}

}  // namespace

McTable BuildMcTable() {
  McTable table;
  for (int mask = 0; mask < 256; ++mask) table[mask] = BuildCase(mask);
  return table;
}

}  // namespace meshseg::voxel_internal
