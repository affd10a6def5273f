// DetectBinaryLattice(), BinaryMeshFeatures() and RelaxTerraces(): marching cubes on binary
// occupancy puts every vertex at the midpoint of a lattice edge, so each
// coordinate axis holds only the lattice values and the midpoints between
// them. The occupancy is recovered from the mesh itself: the two ends of
// each crossed edge are inside and outside (the vertex normal says which),
// and lattice points joined by an uncrossed edge share their state.
#include <algorithm>
#include <cmath>
#include <deque>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/voxel.h"

namespace meshseg {
namespace {

// Distinct values of one coordinate may not exceed this share of the
// vertices: a grey iso-surface has about one distinct value per vertex.
constexpr double kMaxDistinctShare = 0.05;
// Offsets from the half-lattice, in half steps (coordinates stored as float).
constexpr double kLatticeTolerance = 1e-3;

struct AxisLattice {
  double first = 0.0;  // smallest coordinate
  double half = 0.0;   // half the spacing
};

std::optional<AxisLattice> AxisOf(std::vector<double> values, double extent) {
  std::sort(values.begin(), values.end());
  std::vector<double> distinct;
  const double merge = 1e-7 * extent;
  for (double v : values) {
    if (distinct.empty() || v - distinct.back() > merge) distinct.push_back(v);
  }
  if (distinct.size() < 3 || distinct.size() > kMaxDistinctShare * values.size())
    return std::nullopt;
  double gap = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < distinct.size(); ++i) gap = std::min(gap, distinct[i] - distinct[i - 1]);
  for (double v : distinct) {
    const double m = (v - distinct.front()) / gap;
    if (std::abs(m - std::round(m)) > kLatticeTolerance) return std::nullopt;
  }
  return AxisLattice{distinct.front(), gap};
}

// Position of lattice point x of the box `occ` whose point 0 is `base`.
Eigen::Vector3d LatticePoint(int64_t x, const Occupancy& occ, const int64_t base[3],
                             const BinaryLattice& lattice) {
  const int64_t c[3] = {x % occ.dims[0], (x / occ.dims[0]) % occ.dims[1],
                        x / (int64_t{occ.dims[0]} * occ.dims[1])};
  Eigen::Vector3d p;
  for (int a = 0; a < 3; ++a)
    p[a] = lattice.origin[a] + lattice.spacing[a] * static_cast<double>(base[a] + c[a]);
  return p;
}

// Index along an axis in half steps from `first`.
int64_t HalfSteps(double v, const AxisLattice& a) { return std::llround((v - a.first) / a.half); }

}  // namespace

std::optional<BinaryLattice> DetectBinaryLattice(const TriMesh& mesh) {
  if (mesh.n_vertices() < 64) return std::nullopt;
  std::array<std::vector<double>, 3> coords;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (auto v : mesh.vertices()) {
    const Eigen::Vector3d p = ToEigen(mesh.point(v));
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    for (int a = 0; a < 3; ++a) coords[a].push_back(p[a]);
  }
  const double extent = (hi - lo).maxCoeff();
  std::array<AxisLattice, 3> axes;
  for (int a = 0; a < 3; ++a) {
    const std::optional<AxisLattice> axis = AxisOf(coords[a], extent);
    if (!axis) return std::nullopt;
    axes[a] = *axis;
  }
  // Which parity of half steps is the lattice on each axis: every vertex has
  // exactly one coordinate at a midpoint.
  for (int parity = 0; parity < 8; ++parity) {
    bool all = true;
    for (size_t v = 0; v < coords[0].size() && all; ++v) {
      int mid = 0;
      for (int a = 0; a < 3; ++a) mid += ((HalfSteps(coords[a][v], axes[a]) + (parity >> a)) & 1);
      all = mid == 1;
    }
    if (!all) continue;
    BinaryLattice lattice;
    for (int a = 0; a < 3; ++a) {
      lattice.spacing[a] = 2.0 * axes[a].half;
      lattice.origin[a] = axes[a].first + (((parity >> a) & 1) ? axes[a].half : 0.0);
    }
    return lattice;
  }
  return std::nullopt;
}

absl::StatusOr<BinaryVertices> BinaryMeshFeatures(const TriMesh& mesh, const BinaryLattice& lattice,
                                                  const VolumeParams& params) {
  // Lattice box around the vertices, one point of air beyond.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (auto v : mesh.vertices()) {
    lo = lo.cwiseMin(ToEigen(mesh.point(v))), hi = hi.cwiseMax(ToEigen(mesh.point(v)));
  }
  Occupancy occ;
  int64_t base[3];
  double voxels = 1.0;
  for (int a = 0; a < 3; ++a) {
    base[a] =
        static_cast<int64_t>(std::floor((lo[a] - lattice.origin[a]) / lattice.spacing[a])) - 1;
    const int64_t top =
        static_cast<int64_t>(std::ceil((hi[a] - lattice.origin[a]) / lattice.spacing[a])) + 1;
    occ.dims[a] = static_cast<int>(top - base[a] + 1);
    voxels *= occ.dims[a];
  }
  if (voxels > static_cast<double>(params.read.max_voxels)) {
    return absl::InvalidArgumentError(absl::StrCat("binary mesh: a lattice of ", voxels,
                                                   " voxels is over the limit of ",
                                                   params.read.max_voxels));
  }
  const auto index = [&](const int64_t c[3]) { return occ.Index(int(c[0]), int(c[1]), int(c[2])); };
  std::vector<int8_t> state(static_cast<size_t>(voxels), -1);
  std::unordered_map<int64_t, int> crossed;  // lattice edge id -> vertex
  std::vector<int64_t> inside_end(mesh.n_vertices(), -1), outside_end(mesh.n_vertices(), -1);
  std::deque<size_t> queue;
  for (auto v : mesh.vertices()) {
    const Eigen::Vector3d p = ToEigen(mesh.point(v));
    double u[3];
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      u[a] = (p[a] - lattice.origin[a]) / lattice.spacing[a] - base[a];
      if (std::abs(u[a] - std::round(u[a])) > 0.25) axis = a;
    }
    if (axis < 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("binary mesh: vertex ", v.idx(), " is off the lattice"));
    }
    int64_t c[3] = {std::llround(u[0]), std::llround(u[1]), std::llround(u[2])};
    c[axis] = static_cast<int64_t>(std::floor(u[axis]));
    const size_t lower = index(c);
    crossed[static_cast<int64_t>(lower) * 3 + axis] = v.idx();
    // The surface faces away from the inside: the normal's sign along the
    // edge says which end is material.
    const bool upper_inside = mesh.normal(v)[axis] < 0.0;
    int64_t d[3] = {c[0], c[1], c[2]};
    ++d[axis];
    const size_t upper = index(d);
    inside_end[v.idx()] = static_cast<int64_t>(upper_inside ? upper : lower);
    outside_end[v.idx()] = static_cast<int64_t>(upper_inside ? lower : upper);
    state[upper_inside ? upper : lower] = 1;
    state[upper_inside ? lower : upper] = 0;
    queue.push_back(lower);
    queue.push_back(upper);
  }
  // Spread along uncrossed lattice edges.
  const int64_t stride[3] = {1, occ.dims[0], int64_t{occ.dims[0]} * occ.dims[1]};
  while (!queue.empty()) {
    const size_t x = queue.front();
    queue.pop_front();
    int64_t c[3] = {static_cast<int64_t>(x) % occ.dims[0],
                    (static_cast<int64_t>(x) / occ.dims[0]) % occ.dims[1],
                    static_cast<int64_t>(x) / stride[2]};
    for (int a = 0; a < 3; ++a) {
      for (int step : {-1, 1}) {
        if (c[a] + step < 0 || c[a] + step >= occ.dims[a]) continue;
        const size_t y = x + step * stride[a];
        if (state[y] >= 0) continue;
        const size_t lower = step > 0 ? x : y;
        if (crossed.count(static_cast<int64_t>(lower) * 3 + a)) continue;
        state[y] = state[x];
        queue.push_back(y);
      }
    }
  }
  occ.inside.resize(state.size());
  for (size_t x = 0; x < state.size(); ++x) occ.inside[x] = state[x] == 1;
  const std::vector<uint8_t> features =
      FeatureVoxels(occ, params.opening_radius, params.closing_radius);
  BinaryVertices out;
  out.feature.assign(mesh.n_vertices(), 0);
  for (size_t v = 0; v < out.feature.size(); ++v) {
    out.feature[v] = inside_end[v] >= 0 && features[inside_end[v]];
    out.inside.push_back(LatticePoint(inside_end[v], occ, base, lattice));
    out.outside.push_back(LatticePoint(outside_end[v], occ, base, lattice));
  }
  return out;
}

std::vector<Eigen::Vector3d> RelaxTerraces(const TriMesh& mesh, const BinaryVertices& vertices,
                                           int iterations) {
  // Keeps vertices this fraction of their edge from its ends (no two
  // vertices of a cube meet).
  constexpr double kMargin = 0.05;
  constexpr double kStep = 0.5;
  const size_t n = mesh.n_vertices();
  std::vector<Eigen::Vector3d> at(n), next(n);
  for (auto v : mesh.vertices()) at[v.idx()] = ToEigen(mesh.point(v));
  std::vector<int> start(n + 1, 0), ring;
  for (auto v : mesh.vertices()) {
    for (auto w : mesh.vv_range(v)) ring.push_back(w.idx());
    start[v.idx() + 1] = static_cast<int>(ring.size());
  }
  for (int it = 0; it < iterations; ++it) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t v = r.begin(); v < r.end(); ++v) {
        next[v] = at[v];
        if (vertices.feature[v] || start[v] == start[v + 1]) continue;
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (int k = start[v]; k < start[v + 1]; ++k) mean += at[ring[k]];
        mean /= start[v + 1] - start[v];
        const Eigen::Vector3d target = at[v] + kStep * (mean - at[v]);
        const Eigen::Vector3d a = vertices.inside[v], d = vertices.outside[v] - a;
        const double t = std::clamp((target - a).dot(d) / d.squaredNorm(), kMargin, 1.0 - kMargin);
        next[v] = a + t * d;
      }
    });
    std::swap(at, next);
  }
  return at;
}

}  // namespace meshseg
