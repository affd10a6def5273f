// GenerateVolume and LabelWithGroundTruth: a part as a CT volume on its own
// voxel grid, and the answer key for any mesh of it.
#include <cmath>
#include <random>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "generate/ground_truth.h"
#include "generate/marching_cubes.h"
#include "generate/parts.h"
#include "meshseg/generate.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

constexpr double kAir = 1000.0;
constexpr double kMaterial = 3000.0;

absl::StatusOr<generate_internal::PartSpec> Find(std::string_view name) {
  std::optional<generate_internal::PartSpec> spec = generate_internal::FindPart(name);
  if (!spec) {
    return absl::InvalidArgumentError(
        absl::StrCat("generate: unknown part \"", std::string(name), "\""));
  }
  return *std::move(spec);
}

}  // namespace

absl::StatusOr<VolumeData> GenerateVolume(std::string_view name, bool binary,
                                          const GenerateParams& params, const RunContext& ctx) {
  // The mesh's own checks and grid: generate the part's grid once.
  MESHSEG_ASSIGN_OR_RETURN(const generate_internal::PartSpec spec, Find(name));
  MESHSEG_ASSIGN_OR_RETURN(const generate_internal::Grid g,
                           generate_internal::PartGrid(name, params));
  VolumeData v;
  v.type = binary ? VoxelType::kUint8 : VoxelType::kUint16;
  v.geometry.dims = {g.nx, g.ny, g.nz};
  v.geometry.origin = g.origin;
  for (int a = 0; a < 3; ++a) v.geometry.axes[a] = g.h * Eigen::Vector3d::Unit(a);
  v.values.resize(static_cast<size_t>(v.geometry.VoxelCount()));
  const size_t slice = static_cast<size_t>(g.nx) * g.ny;
  for (int k = 0; k < g.nz; ++k) {
    MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("generate"));
    ctx.Progress("generate", static_cast<double>(k) / g.nz);
    tbb::parallel_for(tbb::blocked_range<int>(0, g.ny), [&](const tbb::blocked_range<int>& r) {
      for (int j = r.begin(); j < r.end(); ++j) {
        for (int i = 0; i < g.nx; ++i) {
          const double f = spec.solid.Eval(g.Point(i, j, k)).f;
          const size_t at = k * slice + static_cast<size_t>(j) * g.nx + i;
          v.values[at] =
              binary ? (f < 0.0 ? 1.0 : 0.0)
                     : kAir + (kMaterial - kAir) * std::clamp(0.5 - f / (2.0 * g.h), 0.0, 1.0);
        }
      }
    });
  }
  if (!binary && params.noise > 0.0) {
    std::mt19937_64 rng(params.seed);
    std::normal_distribution<double> normal(0.0, params.noise * 0.5 * (kMaterial - kAir));
    for (double& x : v.values) x += normal(rng);
  }
  ctx.Progress("generate", 1.0);
  return v;
}

absl::StatusOr<GeneratedPart> LabelWithGroundTruth(std::string_view name, const Mesh& mesh,
                                                   const GenerateParams& params) {
  MESHSEG_ASSIGN_OR_RETURN(const generate_internal::PartSpec spec, Find(name));
  GeneratedPart part;
  part.name = spec.name;
  part.voxel_size = params.voxel_size > 0.0 ? params.voxel_size : spec.default_voxel_size;
  part.noise = params.noise * part.voxel_size;
  part.primitives = spec.primitives;
  generate_internal::RawSurface raw;
  for (auto v : mesh.tri.vertices()) {
    raw.vertices.push_back(ToEigen(mesh.tri.point(v)));
    raw.vertex_leaf.push_back(spec.solid.Eval(raw.vertices.back()).leaf);
  }
  for (auto f : mesh.tri.faces()) {
    std::array<int, 3> t;
    int c = 0;
    for (auto v : mesh.tri.fv_range(f)) t[c++] = v.idx();
    raw.triangles.push_back(t);
  }
  part.vertex_primitive = generate_internal::VertexPrimitives(spec.solid, raw);
  part.face_primitive = generate_internal::FacePrimitives(raw, part.vertex_primitive,
                                                          part.primitives, part.voxel_size);
  part.face_near_boundary =
      generate_internal::NearBoundary(raw, part.vertex_primitive, part.voxel_size);
  part.mesh.tri = mesh.tri;
  part.mesh.face_of_input = mesh.face_of_input;
  part.mesh.name = mesh.name;
  return part;
}

}  // namespace meshseg
