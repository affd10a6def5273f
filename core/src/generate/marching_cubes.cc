#include "generate/marching_cubes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "generate/mc_table.h"
#include "meshseg/fit.h"
#include "meshseg/status_macros.h"

namespace meshseg::generate_internal {
namespace {

constexpr int kTile = 8;

struct EdgeHit {
  int i = 0;  // position of the edge along its row
  Eigen::Vector3d point;
  int leaf = -1;
};

// Samples slice k into f (nx * ny values, row-major in j). A tile whose
// centre value exceeds its half-diagonal plus 1.5 h keeps that value at every
// point: the sign is right, and no edge at such a point can cross.
void SampleSlice(const Csg& solid, const Grid& g, int k, std::vector<double>& f) {
  const int tiles_x = (g.nx + kTile - 1) / kTile;
  const int tiles_y = (g.ny + kTile - 1) / kTile;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_y), [&](const tbb::blocked_range<int>& r) {
    for (int tj = r.begin(); tj < r.end(); ++tj) {
      const int j0 = tj * kTile, j1 = std::min(g.ny, j0 + kTile);
      for (int ti = 0; ti < tiles_x; ++ti) {
        const int i0 = ti * kTile, i1 = std::min(g.nx, i0 + kTile);
        const double ci = 0.5 * (i0 + i1 - 1), cj = 0.5 * (j0 + j1 - 1);
        const double fc = solid.Eval(g.Point(ci, cj, k)).f;
        const double reach = g.h * (std::hypot(0.5 * (i1 - i0 - 1), 0.5 * (j1 - j0 - 1)) + 1.5);
        const bool far = std::abs(fc) > reach;
        for (int j = j0; j < j1; ++j) {
          for (int i = i0; i < i1; ++i) {
            f[static_cast<size_t>(j) * g.nx + i] = far ? fc : solid.Eval(g.Point(i, j, k)).f;
          }
        }
      }
    }
  });
}

// The vertex on the edge a -> b whose ends have values fa, fb of opposite
// sign: Illinois root finding, then kept off the ends and projected.
EdgeHit EdgeVertex(const Csg& solid, const Eigen::Vector3d& a, double fa,
                   const Eigen::Vector3d& b, double fb, double h) {
  const double tol = 1e-10 * h;
  double t0 = 0.0, f0 = fa, t1 = 1.0, f1 = fb, t = 0.5;
  int side = 0;
  Csg::Value v;
  for (int it = 0; it < 60; ++it) {
    t = (t0 * f1 - t1 * f0) / (f1 - f0);
    v = solid.Eval(a + t * (b - a));
    if (std::abs(v.f) <= tol || t1 - t0 < 1e-13) break;
    if ((v.f < 0.0) == (f0 < 0.0)) {
      t0 = t, f0 = v.f;
      if (side == -1) f1 *= 0.5;
      side = -1;
    } else {
      t1 = t, f1 = v.f;
      if (side == 1) f0 *= 0.5;
      side = 1;
    }
  }
  const double kept = std::clamp(t, kMinEdgeFraction, 1.0 - kMinEdgeFraction);
  if (kept != t) v = solid.Eval(a + kept * (b - a));
  const Eigen::Vector3d p = a + kept * (b - a);
  return {0, Project(solid.leaves()[v.leaf].surface, p).point, v.leaf};
}

// Finds the crossing edges of `rows` rows in parallel (hits_of_row(j, hits)),
// then numbers their vertices in row order: index[j * stride + i] = id.
template <typename HitsOfRow>
void AddEdgeVertices(int rows, int stride, const HitsOfRow& hits_of_row, std::vector<int>& index,
                     RawSurface& out) {
  std::vector<std::vector<EdgeHit>> hits(rows);
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) hits_of_row(j, hits[j]);
  });
  for (int j = 0; j < rows; ++j) {
    for (const EdgeHit& hit : hits[j]) {
      index[static_cast<size_t>(j) * stride + hit.i] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(hit.point);
      out.vertex_leaf.push_back(hit.leaf);
    }
  }
}

// Sampled values and edge-vertex ids of one slice.
struct Slice {
  std::vector<double> f;
  std::vector<int> x_edge;  // (nx - 1) * ny
  std::vector<int> y_edge;  // nx * (ny - 1)
};

void AddSliceVertices(const Csg& solid, const Grid& g, int k, Slice& s, RawSurface& out) {
  const int nx = g.nx;
  AddEdgeVertices(g.ny, nx - 1, [&](int j, std::vector<EdgeHit>& hits) {
    for (int i = 0; i + 1 < nx; ++i) {
      const double fa = s.f[static_cast<size_t>(j) * nx + i], fb = s.f[static_cast<size_t>(j) * nx + i + 1];
      if ((fa < 0.0) == (fb < 0.0)) continue;
      EdgeHit hit = EdgeVertex(solid, g.Point(i, j, k), fa, g.Point(i + 1, j, k), fb, g.h);
      hit.i = i;
      hits.push_back(hit);
    }
  }, s.x_edge, out);
  AddEdgeVertices(g.ny - 1, nx, [&](int j, std::vector<EdgeHit>& hits) {
    for (int i = 0; i < nx; ++i) {
      const double fa = s.f[static_cast<size_t>(j) * nx + i], fb = s.f[static_cast<size_t>(j + 1) * nx + i];
      if ((fa < 0.0) == (fb < 0.0)) continue;
      EdgeHit hit = EdgeVertex(solid, g.Point(i, j, k), fa, g.Point(i, j + 1, k), fb, g.h);
      hit.i = i;
      hits.push_back(hit);
    }
  }, s.y_edge, out);
}

void AddSlabVertices(const Csg& solid, const Grid& g, int k, const Slice& lo, const Slice& hi,
                     std::vector<int>& z_edge, RawSurface& out) {
  const int nx = g.nx;
  AddEdgeVertices(g.ny, nx, [&](int j, std::vector<EdgeHit>& hits) {
    for (int i = 0; i < nx; ++i) {
      const size_t at = static_cast<size_t>(j) * nx + i;
      if ((lo.f[at] < 0.0) == (hi.f[at] < 0.0)) continue;
      EdgeHit hit = EdgeVertex(solid, g.Point(i, j, k), lo.f[at], g.Point(i, j, k + 1), hi.f[at], g.h);
      hit.i = i;
      hits.push_back(hit);
    }
  }, z_edge, out);
}

// Triangles of the cubes between slices k and k + 1, in row order.
void AddSlabTriangles(const McTable& table, const Grid& g, const Slice& lo, const Slice& hi,
                      const std::vector<int>& z_edge, RawSurface& out) {
  const int nx = g.nx;
  std::vector<std::vector<std::array<int, 3>>> rows(g.ny - 1);
  tbb::parallel_for(tbb::blocked_range<int>(0, g.ny - 1), [&](const tbb::blocked_range<int>& r) {
    for (int j = r.begin(); j < r.end(); ++j) {
      for (int i = 0; i + 1 < nx; ++i) {
        int mask = 0;
        for (int c = 0; c < 8; ++c) {
          const Slice& s = (c >> 2) & 1 ? hi : lo;
          const size_t at = static_cast<size_t>(j + ((c >> 1) & 1)) * nx + i + (c & 1);
          mask |= (s.f[at] < 0.0) << c;
        }
        const auto vertex_of_edge = [&](int e) {
          const int c = kCubeEdgeCorners[e][0];
          const int di = c & 1, dj = (c >> 1) & 1;
          const Slice& s = (c >> 2) & 1 ? hi : lo;
          if (e < 4) return s.x_edge[static_cast<size_t>(j + dj) * (nx - 1) + i];
          if (e < 8) return s.y_edge[static_cast<size_t>(j) * nx + i + di];
          return z_edge[static_cast<size_t>(j + dj) * nx + i + di];
        };
        for (const auto& tri : table[mask]) {
          rows[j].push_back({vertex_of_edge(tri[0]), vertex_of_edge(tri[1]), vertex_of_edge(tri[2])});
        }
      }
    }
  });
  for (const auto& row : rows) out.triangles.insert(out.triangles.end(), row.begin(), row.end());
}

}  // namespace

absl::StatusOr<RawSurface> MarchingCubes(const Csg& solid, const Grid& g, const RunContext& ctx) {
  const McTable table = BuildMcTable();
  const size_t points = static_cast<size_t>(g.nx) * g.ny;
  const auto fresh_slice = [&] {
    return Slice{std::vector<double>(points), std::vector<int>((g.nx - 1) * static_cast<size_t>(g.ny), -1),
                 std::vector<int>(g.nx * static_cast<size_t>(g.ny - 1), -1)};
  };
  Slice lo = fresh_slice(), hi = fresh_slice();
  std::vector<int> z_edge(points, -1);
  RawSurface out;
  SampleSlice(solid, g, 0, lo.f);
  AddSliceVertices(solid, g, 0, lo, out);
  for (int k = 0; k + 1 < g.nz; ++k) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("generate"));
    ctx.Progress("generate", static_cast<double>(k) / g.nz);
    SampleSlice(solid, g, k + 1, hi.f);
    AddSliceVertices(solid, g, k + 1, hi, out);
    AddSlabVertices(solid, g, k, lo, hi, z_edge, out);
    AddSlabTriangles(table, g, lo, hi, z_edge, out);
    std::swap(lo, hi);
  }
  return out;
}

}  // namespace meshseg::generate_internal
