#include "generate/ground_truth.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "meshseg/fit.h"

namespace meshseg::generate_internal {

std::vector<int> VertexPrimitives(const Csg& solid, const RawSurface& surface) {
  const std::vector<Leaf>& leaves = solid.leaves();
  std::vector<int> primitive(surface.vertices.size(), -1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, primitive.size()),
                    [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v < r.end(); ++v) {
      primitive[v] = leaves[surface.vertex_leaf[v]].primitive;
      if (primitive[v] >= 0) continue;
      double best = std::numeric_limits<double>::infinity();
      for (const Leaf& leaf : leaves) {
        const double d = std::abs(LeafValue(leaf, surface.vertices[v]));
        if (leaf.primitive >= 0 && d < best) best = d, primitive[v] = leaf.primitive;
      }
    }
  });
  return primitive;
}

std::vector<int> FacePrimitives(const RawSurface& surface, const std::vector<int>& vertex_primitive,
                                const std::vector<PrimitiveTruth>& primitives, double h) {
  std::vector<int> face(surface.triangles.size(), -1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, face.size()),
                    [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t < r.end(); ++t) {
      const auto& tri = surface.triangles[t];
      const Eigen::Vector3d centroid =
          (surface.vertices[tri[0]] + surface.vertices[tri[1]] + surface.vertices[tri[2]]) / 3.0;
      double best = h;
      for (int c = 0; c < 3; ++c) {
        const int p = vertex_primitive[tri[c]];
        if (p < 0 || p == face[t]) continue;
        const double d = std::abs(SignedDistance(primitives[p].surface, centroid));
        if (d <= best) best = d, face[t] = p;
      }
    }
  });
  return face;
}

std::vector<uint8_t> NearBoundary(const RawSurface& surface, const std::vector<int>& vertex_primitive,
                                  double h) {
  const size_t nv = surface.vertices.size();
  // Vertex adjacency (CSR) over the triangle edges.
  std::vector<int> start(nv + 1, 0);
  for (const auto& tri : surface.triangles) {
    for (int c = 0; c < 3; ++c) start[tri[c] + 1] += 2;
  }
  for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1), neighbour(start[nv]);
  for (const auto& tri : surface.triangles) {
    for (int c = 0; c < 3; ++c) {
      neighbour[fill[tri[c]]++] = tri[(c + 1) % 3];
      neighbour[fill[tri[c]]++] = tri[(c + 2) % 3];
    }
  }
  // Multi-source Dijkstra from the corners of mixed triangles, cut at h.
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const auto& tri : surface.triangles) {
    const int p = vertex_primitive[tri[0]];
    if (p == vertex_primitive[tri[1]] && p == vertex_primitive[tri[2]] && p >= 0) continue;
    for (int c = 0; c < 3; ++c) {
      if (dist[tri[c]] > 0.0) dist[tri[c]] = 0.0, queue.push({0.0, tri[c]});
    }
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (int k = start[v]; k < start[v + 1]; ++k) {
      const int w = neighbour[k];
      const double dw = d + (surface.vertices[w] - surface.vertices[v]).norm();
      if (dw <= h && dw < dist[w]) dist[w] = dw, queue.push({dw, w});
    }
  }
  std::vector<uint8_t> near(surface.triangles.size(), 0);
  for (size_t t = 0; t < near.size(); ++t) {
    for (int c : surface.triangles[t]) near[t] |= dist[c] <= h;
  }
  return near;
}

}  // namespace meshseg::generate_internal
