// ExtractSurface(): one streamed pass for the value statistics (range, the
// first distinct values, Otsu's histogram), a second for float histograms,
// and a marching-cubes pass over a virtual layer of air around the volume so
// the surface is closed where material touches the border.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg {
namespace {

// Vertices stay this fraction of a grid edge away from samples, so no two
// vertices of a cube coincide (no zero-area triangles); the generator uses
// the same margin.
constexpr double kMinEdgeFraction = 0.02;
constexpr int kFloatBins = 4096;

struct ValueStats {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  std::vector<double> distinct;  // the first three distinct values
  std::vector<int64_t> histogram;
  double hist_lo = 0.0, hist_hi = 1.0;
};

// Integer types get one bin per value; floats a second pass over [lo, hi].
absl::StatusOr<ValueStats> Statistics(const VolumeInfo& info, const RunContext& ctx) {
  ValueStats s;
  const bool integer = info.type != VoxelType::kFloat32;
  if (integer) {
    const bool is_signed = info.type == VoxelType::kInt16;
    const int bins = info.type == VoxelType::kUint8 ? 256 : 65536;
    s.histogram.assign(bins, 0);
    s.hist_lo = is_signed ? -32768.0 : 0.0;
    s.hist_hi = s.hist_lo + bins;
  }
  MESHSEG_ASSIGN_OR_RETURN(VolumeSlices slices, VolumeSlices::Open(info));
  std::vector<double> values;
  const int64_t nz = info.geometry.dims[2];
  for (int64_t k = 0; k < nz; ++k) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("volume"));
    ctx.Progress("volume", 0.3 * k / nz);
    MESHSEG_RETURN_IF_ERROR(slices.Next(values));
    for (double v : values) {
      s.lo = std::min(s.lo, v);
      s.hi = std::max(s.hi, v);
      if (s.distinct.size() < 3 &&
          std::find(s.distinct.begin(), s.distinct.end(), v) == s.distinct.end()) {
        s.distinct.push_back(v);
      }
      if (integer) ++s.histogram[static_cast<size_t>(v - s.hist_lo)];
    }
  }
  if (!integer && s.hi > s.lo) {
    s.histogram.assign(kFloatBins, 0);
    s.hist_lo = s.lo;
    s.hist_hi = s.hi;
    MESHSEG_ASSIGN_OR_RETURN(VolumeSlices again, VolumeSlices::Open(info));
    const double scale = kFloatBins / (s.hi - s.lo);
    for (int64_t k = 0; k < nz; ++k) {
      MESHSEG_RETURN_IF_ERROR(again.Next(values));
      for (double v : values) {
        ++s.histogram[std::min<size_t>(kFloatBins - 1, static_cast<size_t>((v - s.lo) * scale))];
      }
    }
  }
  std::sort(s.distinct.begin(), s.distinct.end());
  return s;
}

// The iso value and whether the volume is treated as binary.
absl::Status ChooseIso(const VolumeInfo& info, const VolumeParams& params, const ValueStats& s,
                       VolumeSurface* out) {
  if (s.distinct.size() < 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("volume: \"", info.name, "\": every sample is ", s.lo, "; no surface"));
  }
  out->binary = params.mode == VolumeMode::kBinary ||
                (params.mode == VolumeMode::kAuto && s.distinct.size() == 2);
  if (params.iso) {
    out->iso = *params.iso;
  } else if (out->binary && s.distinct.size() == 2) {
    out->iso = 0.5 * (s.distinct[0] + s.distinct[1]);
  } else {
    out->iso = OtsuThreshold(s.histogram, s.hist_lo, s.hist_hi);
  }
  if (!(out->iso >= s.lo && out->iso < s.hi)) {
    return absl::InvalidArgumentError(absl::StrCat("volume: \"", info.name, "\": iso value ",
                                                   out->iso, " is outside the samples' range [",
                                                   s.lo, ", ", s.hi, ")"));
  }
  return absl::OkStatus();
}

}  // namespace

double OtsuThreshold(std::span<const int64_t> histogram, double lo, double hi) {
  const size_t n = histogram.size();
  const double width = (hi - lo) / static_cast<double>(n);
  double total = 0.0, sum = 0.0;
  for (size_t b = 0; b < n; ++b) {
    total += histogram[b];
    sum += static_cast<double>(b) * histogram[b];
  }
  double w0 = 0.0, sum0 = 0.0, best = -1.0;
  size_t best_b = 0;
  for (size_t b = 0; b + 1 < n; ++b) {
    w0 += histogram[b];
    sum0 += static_cast<double>(b) * histogram[b];
    const double w1 = total - w0;
    if (w0 == 0.0 || w1 == 0.0) continue;
    const double m0 = sum0 / w0, m1 = (sum - sum0) / w1;
    const double between = w0 * w1 * (m0 - m1) * (m0 - m1);
    if (between > best) best = between, best_b = b;
  }
  // Class 0 holds bins 0..best_b: the threshold is the upper edge of best_b.
  return lo + width * static_cast<double>(best_b + 1) - (width == 1.0 ? 0.5 : 0.0);
}

absl::StatusOr<VolumeSurface> ExtractSurface(const std::string& path, const VolumeParams& params,
                                             const RunContext& ctx) {
  VolumeSurface out;
  MESHSEG_ASSIGN_OR_RETURN(out.info, ReadVolumeInfo(path, params.read));
  const VolumeInfo& info = out.info;
  ctx.Progress("volume", 0.0);
  MESHSEG_ASSIGN_OR_RETURN(const ValueStats stats, Statistics(info, ctx));
  MESHSEG_RETURN_IF_ERROR(ChooseIso(info, params, stats, &out));

  const VolumeGeometry& g = info.geometry;
  const int nx = static_cast<int>(g.dims[0]), ny = static_cast<int>(g.dims[1]);
  const int nz = static_cast<int>(g.dims[2]);
  Occupancy occupancy;
  if (out.binary) {
    occupancy.dims = {nx, ny, nz};
    occupancy.inside.assign(static_cast<size_t>(g.VoxelCount()), 0);
  }
  MESHSEG_ASSIGN_OR_RETURN(VolumeSlices slices, VolumeSlices::Open(info));
  std::vector<double> values;
  SampledField field;
  // One layer of air around the volume: padded index p is sample p - 1.
  field.dims = {nx + 2, ny + 2, nz + 2};
  const double iso = out.iso;
  field.slice = [&](int k, std::vector<double>& f) -> absl::Status {
    std::fill(f.begin(), f.end(), 1.0);
    if (k == 0 || k == nz + 1) return absl::OkStatus();
    MESHSEG_RETURN_IF_ERROR(slices.Next(values));
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double v = values[static_cast<size_t>(j) * nx + i];
        f[static_cast<size_t>(j + 1) * (nx + 2) + i + 1] = iso - v;
        if (out.binary && v > iso) occupancy.inside[occupancy.Index(i, j, k - 1)] = 1;
      }
    }
    return absl::OkStatus();
  };
  field.edge_vertex = [&](int i, int j, int k, int axis, double fa, double fb) {
    const double t = std::clamp(fa / (fa - fb), kMinEdgeFraction, 1.0 - kMinEdgeFraction);
    double p[3] = {i - 1.0, j - 1.0, k - 1.0};
    p[axis] += t;
    return SampledField::Vertex{g.Point(p[0], p[1], p[2]), fa < 0.0 ? 0 : 1};
  };
  RunContext mc_ctx = ctx;
  mc_ctx.on_progress = [&](std::string_view, double f) { ctx.Progress("volume", 0.3 + 0.6 * f); };
  MESHSEG_ASSIGN_OR_RETURN(IsoSurface iso_surface, MarchingCubes(field, mc_ctx, "volume"));
  if (iso_surface.triangles.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("volume: \"", info.name, "\": no surface at iso value ", iso));
  }
  // A left-handed frame turns the triangles inside out.
  if (g.axes[0].cross(g.axes[1]).dot(g.axes[2]) < 0.0) {
    for (auto& t : iso_surface.triangles) std::swap(t[1], t[2]);
  }
  if (out.binary) {
    const std::vector<uint8_t> features =
        FeatureVoxels(occupancy, params.opening_radius, params.closing_radius);
    out.feature_vertex.assign(iso_surface.vertices.size(), 0);
    const int64_t px = nx + 2, py = ny + 2;
    for (size_t v = 0; v < iso_surface.vertices.size(); ++v) {
      // The vertex's grid edge (padded indices) and its end inside the solid.
      const int64_t e = iso_surface.vertex_edge[v];
      const int axis = static_cast<int>(e % 3);
      int64_t lower = e / 3;
      int64_t c[3] = {lower % px, (lower / px) % py, lower / (px * py)};
      int64_t o[3] = {c[0], c[1], c[2]};
      if (iso_surface.vertex_tag[v] == 1) {
        ++c[axis];  // the upper end is inside
      } else {
        ++o[axis];
      }
      out.edge_inside.push_back(g.Point(c[0] - 1.0, c[1] - 1.0, c[2] - 1.0));
      out.edge_outside.push_back(g.Point(o[0] - 1.0, o[1] - 1.0, o[2] - 1.0));
      out.feature_vertex[v] = features[occupancy.Index(
          static_cast<int>(c[0] - 1), static_cast<int>(c[1] - 1), static_cast<int>(c[2] - 1))];
    }
  }
  ctx.Progress("volume", 0.95);
  MESHSEG_ASSIGN_OR_RETURN(
      out.mesh, BuildMesh(std::move(iso_surface.vertices), iso_surface.triangles, info.name));
  ctx.Progress("volume", 1.0);
  return out;
}

}  // namespace meshseg
