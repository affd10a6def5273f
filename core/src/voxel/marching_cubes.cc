// MarchingCubes(): the one marching-cubes implementation (volumes and the
// generator). Two slices in memory at a time; crossing edges of a slice are
// found row by row in parallel (oneTBB) and numbered in row order, so the
// mesh is the same at any thread count.
#include <algorithm>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"
#include "voxel/mc_table.h"

namespace meshseg {
namespace {

using voxel_internal::kCubeEdgeCorners;
using voxel_internal::McTable;

struct EdgeHit {
  int i = 0;  // position of the edge along its row
  SampledField::Vertex vertex;
};

// Values and edge-vertex ids of one slice.
struct Slice {
  std::vector<double> f;
  std::vector<int> x_edge;  // (nx - 1) * ny
  std::vector<int> y_edge;  // nx * (ny - 1)
};

class Marcher {
 public:
  explicit Marcher(const SampledField& field)
      : field_(field), nx_(field.dims[0]), ny_(field.dims[1]) {}

  Slice FreshSlice() const {
    const size_t points = static_cast<size_t>(nx_) * ny_;
    return Slice{std::vector<double>(points),
                 std::vector<int>((nx_ - 1) * static_cast<size_t>(ny_), -1),
                 std::vector<int>(nx_ * static_cast<size_t>(ny_ - 1), -1)};
  }

  // Vertices on the x and y edges of slice k.
  void AddSliceVertices(int k, Slice& s) {
    AddEdgeVertices(
        ny_, nx_ - 1, k, 0,
        [&](int j, int i) { return std::pair(s.f[At(i, j)], s.f[At(i + 1, j)]); }, s.x_edge);
    AddEdgeVertices(
        ny_ - 1, nx_, k, 1,
        [&](int j, int i) { return std::pair(s.f[At(i, j)], s.f[At(i, j + 1)]); }, s.y_edge);
  }

  // Vertices on the z edges between slices k and k + 1.
  void AddSlabVertices(int k, const Slice& lo, const Slice& hi, std::vector<int>& z_edge) {
    AddEdgeVertices(
        ny_, nx_, k, 2, [&](int j, int i) { return std::pair(lo.f[At(i, j)], hi.f[At(i, j)]); },
        z_edge);
  }

  // Triangles of the cubes between slices k and k + 1, in row order.
  void AddSlabTriangles(const McTable& table, const Slice& lo, const Slice& hi,
                        const std::vector<int>& z_edge) {
    std::vector<std::vector<std::array<int, 3>>> rows(ny_ - 1);
    tbb::parallel_for(tbb::blocked_range<int>(0, ny_ - 1), [&](const tbb::blocked_range<int>& r) {
      for (int j = r.begin(); j < r.end(); ++j) {
        for (int i = 0; i + 1 < nx_; ++i) {
          int mask = 0;
          for (int c = 0; c < 8; ++c) {
            const Slice& s = (c >> 2) & 1 ? hi : lo;
            mask |= (s.f[At(i + (c & 1), j + ((c >> 1) & 1))] < 0.0) << c;
          }
          if (mask == 0 || mask == 255) continue;
          const auto vertex_of_edge = [&](int e) {
            const int c = kCubeEdgeCorners[e][0];
            const int di = c & 1, dj = (c >> 1) & 1;
            const Slice& s = (c >> 2) & 1 ? hi : lo;
            if (e < 4) return s.x_edge[static_cast<size_t>(j + dj) * (nx_ - 1) + i];
            if (e < 8) return s.y_edge[At(i + di, j)];
            return z_edge[At(i + di, j + dj)];
          };
          for (const auto& tri : table[mask]) {
            rows[j].push_back(
                {vertex_of_edge(tri[0]), vertex_of_edge(tri[1]), vertex_of_edge(tri[2])});
          }
        }
      }
    });
    for (const auto& row : rows)
      out_.triangles.insert(out_.triangles.end(), row.begin(), row.end());
  }

  IsoSurface Take() { return std::move(out_); }

 private:
  size_t At(int i, int j) const { return static_cast<size_t>(j) * nx_ + i; }

  // Finds the crossing edges of `rows` rows along `axis` in parallel, then
  // numbers their vertices in row order: index[j * stride + i] = id.
  template <typename Ends>
  void AddEdgeVertices(int rows, int stride, int k, int axis, const Ends& ends,
                       std::vector<int>& index) {
    std::vector<std::vector<EdgeHit>> hits(rows);
    tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& r) {
      for (int j = r.begin(); j < r.end(); ++j) {
        for (int i = 0; i < stride; ++i) {
          const auto [fa, fb] = ends(j, i);
          if ((fa < 0.0) == (fb < 0.0)) continue;
          hits[j].push_back({i, field_.edge_vertex(i, j, k, axis, fa, fb)});
        }
      }
    });
    for (int j = 0; j < rows; ++j) {
      for (const EdgeHit& hit : hits[j]) {
        index[static_cast<size_t>(j) * stride + hit.i] = static_cast<int>(out_.vertices.size());
        out_.vertices.push_back(hit.vertex.point);
        out_.vertex_tag.push_back(hit.vertex.tag);
        const int64_t lower = hit.i + int64_t{nx_} * (j + int64_t{ny_} * k);
        out_.vertex_edge.push_back(3 * lower + axis);
      }
    }
  }

  const SampledField& field_;
  const int nx_, ny_;
  IsoSurface out_;
};

}  // namespace

absl::StatusOr<IsoSurface> MarchingCubes(const SampledField& field, const RunContext& ctx,
                                         std::string_view stage) {
  const int nx = field.dims[0], ny = field.dims[1], nz = field.dims[2];
  if (nx < 2 || ny < 2 || nz < 2) {
    return absl::InvalidArgumentError(absl::StrCat(std::string(stage), ": a grid of ", nx, " x ",
                                                   ny, " x ", nz, " points has no cubes"));
  }
  const McTable table = voxel_internal::BuildMcTable();
  Marcher marcher(field);
  Slice lo = marcher.FreshSlice(), hi = marcher.FreshSlice();
  std::vector<int> z_edge(static_cast<size_t>(nx) * ny, -1);
  MESHSEG_RETURN_IF_ERROR(field.slice(0, lo.f));
  marcher.AddSliceVertices(0, lo);
  for (int k = 0; k + 1 < nz; ++k) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(stage));
    ctx.Progress(stage, static_cast<double>(k) / nz);
    MESHSEG_RETURN_IF_ERROR(field.slice(k + 1, hi.f));
    std::fill(hi.x_edge.begin(), hi.x_edge.end(), -1);
    std::fill(hi.y_edge.begin(), hi.y_edge.end(), -1);
    std::fill(z_edge.begin(), z_edge.end(), -1);
    marcher.AddSliceVertices(k + 1, hi);
    marcher.AddSlabVertices(k, lo, hi, z_edge);
    marcher.AddSlabTriangles(table, lo, hi, z_edge);
    std::swap(lo, hi);
  }
  ctx.Progress(stage, 1.0);
  return marcher.Take();
}

}  // namespace meshseg
