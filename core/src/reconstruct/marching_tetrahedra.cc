#include "reconstruct/marching_tetrahedra.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/container/flat_hash_map.h"
#include "meshseg/status_macros.h"

namespace meshseg::reconstruct_internal {
namespace {

constexpr char kStage[] = "reconstruct: marching tetrahedra";

uint64_t EdgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(a) << 32) | static_cast<uint32_t>(b);
}

// A surface vertex lies at least this fraction of its tet edge from the ends.
constexpr double kMinEdgeFraction = 1e-3;

// Returns the zero of f on segment a–b (f(a) = fa and f(b) = fb of opposite
// signs) by regula falsi with the Illinois modification.
Eigen::Vector3d ZeroOnSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double fa,
                              double fb, const PuFunction& pu) {
  constexpr int kSteps = 4;
  double lo = 0.0, hi = 1.0;
  double flo = fa, fhi = fb;
  double t = flo / (flo - fhi);
  for (int i = 0; i < kSteps; ++i) {
    const double ft = pu(a + t * (b - a));
    if ((ft >= 0) == (flo >= 0)) {
      lo = t;
      flo = ft;
      fhi *= 0.5;
    } else {
      hi = t;
      fhi = ft;
      flo *= 0.5;
    }
    t = lo + (hi - lo) * flo / (flo - fhi);
  }
  // Strictly inside the edge (f may vanish at an end, e.g. where no support
  // reaches): cut edges sharing that end must not share their vertex.
  t = std::clamp(t, kMinEdgeFraction, 1.0 - kMinEdgeFraction);
  return a + t * (b - a);
}

// True when `listed` holds the vertices of `tet` in an odd permutation of
// the tet's own order.
bool IsOddPermutation(const std::array<int, 4>& tet, const int (&listed)[4]) {
  int rank[4];
  for (int i = 0; i < 4; ++i) {
    rank[i] = static_cast<int>(std::find(tet.begin(), tet.end(), listed[i]) - tet.begin());
  }
  bool odd = false;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) odd ^= rank[i] > rank[j];
  }
  return odd;
}

}  // namespace

absl::StatusOr<IsoSurface> MarchingTetrahedra(const TetMesh& tets,
                                              const std::vector<Eigen::Vector3d>& position,
                                              const std::vector<double>& f,
                                              const std::vector<uint8_t>& inside,
                                              const std::vector<uint8_t>& sparse,
                                              const PuFunction& pu, const RunContext& ctx) {
  IsoSurface out;
  std::vector<std::array<int, 2>> cut;
  absl::flat_hash_map<uint64_t, int> vertex_of_edge;
  for (const auto& e : tets.edges) {
    if (inside[e[0]] == inside[e[1]]) continue;
    vertex_of_edge[EdgeKey(e[0], e[1])] = static_cast<int>(cut.size());
    cut.push_back(e);
  }
  out.vertices.resize(cut.size());
  out.to_smooth.resize(cut.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, cut.size()), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const auto [a, b] = cut[i];
      const bool same_sign = (f[a] >= 0) == (f[b] >= 0);
      if (same_sign) {
        // The cut crosses an edge f does not change sign on: put the vertex
        // where |f| would vanish if it did, nearer the end of smaller |f|.
        // Never on the end itself: the other cut edges of that end would put
        // their vertices there too, and their triangles would have no area.
        const double sum = std::abs(f[a]) + std::abs(f[b]);
        const double t = std::clamp(sum > 0 ? std::abs(f[a]) / sum : 0.5, kMinEdgeFraction,
                                    1.0 - kMinEdgeFraction);
        out.vertices[i] = position[a] + t * (position[b] - position[a]);
      } else {
        out.vertices[i] = ZeroOnSegment(position[a], position[b], f[a], f[b], pu);
      }
      out.to_smooth[i] = same_sign || sparse[a] || sparse[b];
    }
  });
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop(kStage));
  const auto edge_vertex = [&](int a, int b) { return vertex_of_edge.at(EdgeKey(a, b)); };
  for (const auto& tet : tets.tets) {
    int in[4], out_v[4], n_in = 0, n_out = 0;
    for (const int v : tet) (inside[v] ? in[n_in++] : out_v[n_out++]) = v;
    if (n_in == 0 || n_out == 0) continue;
    // The tet's vertices are in positive order (regular_triangulation.h).
    // Listed as (in..., out...), a triangle written below as
    // (in0 out0, in0 out1, in0 out2), (in0 out0, in1 out0, in2 out0) or the
    // quad (in0 out0, in0 out1, in1 out1, in1 out0) has a normal whose dot
    // with (mean of out − mean of in) is a positive multiple of that list's
    // orientation determinant. So it faces from in to out exactly when the
    // list is an even permutation of the tet's order. Read from the order,
    // not from coordinates: on a tet of almost no volume (four centres
    // coplanar up to rounding) a floating-point side test can come out
    // against the exact predicate that built the tet, and the triangle then
    // runs the same way as its neighbour along their edge.
    int listed[4], k = 0;
    for (int i = 0; i < n_in; ++i) listed[k++] = in[i];
    for (int i = 0; i < n_out; ++i) listed[k++] = out_v[i];
    const bool odd = IsOddPermutation(tet, listed);
    const auto emit = [&](std::array<std::array<int, 2>, 3> corner) {
      if (odd) std::swap(corner[1], corner[2]);
      out.triangles.push_back({edge_vertex(corner[0][0], corner[0][1]),
                               edge_vertex(corner[1][0], corner[1][1]),
                               edge_vertex(corner[2][0], corner[2][1])});
    };
    if (n_in == 1) {
      emit({{{in[0], out_v[0]}, {in[0], out_v[1]}, {in[0], out_v[2]}}});
    } else if (n_out == 1) {
      emit({{{in[0], out_v[0]}, {in[1], out_v[0]}, {in[2], out_v[0]}}});
    } else {
      // Quad q0..q3 around the cut; split along its shorter diagonal.
      const std::array<std::array<int, 2>, 4> q = {
          {{in[0], out_v[0]}, {in[0], out_v[1]}, {in[1], out_v[1]}, {in[1], out_v[0]}}};
      const auto p = [&](int i) { return out.vertices[edge_vertex(q[i][0], q[i][1])]; };
      if ((p(0) - p(2)).squaredNorm() <= (p(1) - p(3)).squaredNorm()) {
        emit({q[0], q[1], q[2]});
        emit({q[0], q[2], q[3]});
      } else {
        emit({q[1], q[2], q[3]});
        emit({q[1], q[3], q[0]});
      }
    }
  }
  return out;
}

}  // namespace meshseg::reconstruct_internal
