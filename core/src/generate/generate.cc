// GeneratePart: checks the parameters, samples the named part on the voxel
// grid, labels vertices and faces with their primitives, adds the noise and
// builds the Mesh.
#include "meshseg/generate.h"

#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "generate/ground_truth.h"
#include "generate/marching_cubes.h"
#include "generate/noise.h"
#include "generate/parts.h"
#include "meshseg/fit.h"
#include "meshseg/status_macros.h"

namespace meshseg {
namespace {

using generate_internal::Grid;
using generate_internal::PartSpec;
using generate_internal::RawSurface;

// Grid points the sampler accepts (about 5 M triangles for test_piece).
constexpr double kMaxGridPoints = 2e8;
// Empty layers of voxels around the part.
constexpr double kPadding = 2.0;

absl::Status ValidateParams(std::string_view name, const GenerateParams& params) {
  if (!std::isfinite(params.voxel_size) || params.voxel_size < 0.0) {
    return absl::InvalidArgumentError(absl::StrCat("generate: part \"", std::string(name), "\": voxel_size ",
                                                   params.voxel_size, " must be >= 0 (0 = default)"));
  }
  if (!std::isfinite(params.noise) || params.noise < 0.0) {
    return absl::InvalidArgumentError(absl::StrCat("generate: part \"", std::string(name), "\": noise ",
                                                   params.noise, " must be >= 0"));
  }
  return absl::OkStatus();
}

// The grid around spec.bounds, its origin set off the part's round numbers.
absl::StatusOr<Grid> GridFor(const PartSpec& spec, double h) {
  Grid g;
  g.h = h;
  const Eigen::Vector3d offset(0.137, 0.291, 0.443);
  g.origin = spec.bounds.min() - (kPadding + 1.0) * h * Eigen::Vector3d::Ones() + h * offset;
  const Eigen::Vector3d extent = spec.bounds.max() - g.origin;
  double total = 1.0;
  std::array<int*, 3> n = {&g.nx, &g.ny, &g.nz};
  for (int a = 0; a < 3; ++a) {
    const double count = std::ceil(extent[a] / h) + kPadding + 1.0;
    total *= count;
    if (total > kMaxGridPoints) {
      return absl::InvalidArgumentError(absl::StrCat(
          "generate: part \"", spec.name, "\": voxel_size ", h, " needs a grid of more than ",
          kMaxGridPoints, " points (limit); use a larger voxel_size"));
    }
    *n[a] = static_cast<int>(count);
  }
  return g;
}

absl::StatusOr<PartSpec> SpecNamed(std::string_view name) {
  std::optional<PartSpec> spec = generate_internal::FindPart(name);
  if (!spec) {
    return absl::InvalidArgumentError(absl::StrCat("generate: unknown part \"", std::string(name),
                                                   "\"; known parts: ",
                                                   absl::StrJoin(PartNames(), ", ")));
  }
  return *std::move(spec);
}

}  // namespace

absl::StatusOr<Grid> generate_internal::PartGrid(std::string_view name, const GenerateParams& params) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(name, params));
  MESHSEG_ASSIGN_OR_RETURN(const PartSpec spec, SpecNamed(name));
  return GridFor(spec, params.voxel_size > 0.0 ? params.voxel_size : spec.default_voxel_size);
}

std::vector<std::string> PartNames() { return generate_internal::CatalogueNames(); }

absl::StatusOr<GeneratedPart> GeneratePart(std::string_view name, const GenerateParams& params,
                                           const RunContext& ctx) {
  MESHSEG_RETURN_IF_ERROR(ValidateParams(name, params));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<PartSpec> spec, SpecNamed(name));
  const double h = params.voxel_size > 0.0 ? params.voxel_size : spec->default_voxel_size;
  MESHSEG_ASSIGN_OR_RETURN(const Grid grid, GridFor(*spec, h));
  MESHSEG_ASSIGN_OR_RETURN(RawSurface raw, generate_internal::MarchingCubes(spec->solid, grid, ctx));
  if (raw.triangles.empty()) {
    return absl::InternalError(absl::StrCat("generate: part \"", spec->name, "\" gave no triangles"));
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("generate"));

  GeneratedPart part;
  part.name = spec->name;
  part.voxel_size = h;
  part.noise = params.noise * h;
  part.primitives = spec->primitives;
  part.vertex_primitive = generate_internal::VertexPrimitives(spec->solid, raw);
  const std::vector<int> face_primitive =
      generate_internal::FacePrimitives(raw, part.vertex_primitive, part.primitives, h);
  const std::vector<uint8_t> near = generate_internal::NearBoundary(raw, part.vertex_primitive, h);

  if (part.noise > 0.0) {
    std::vector<Eigen::Vector3d> normals(raw.vertices.size());
    for (size_t v = 0; v < normals.size(); ++v) {
      const int p = part.vertex_primitive[v];
      const Surface& s = p >= 0 ? part.primitives[p].surface
                                : spec->solid.leaves()[raw.vertex_leaf[v]].surface;
      normals[v] = Project(s, raw.vertices[v]).normal;
    }
    generate_internal::AddNormalNoise(raw.vertices, normals, part.noise, params.seed);
  }

  MESHSEG_ASSIGN_OR_RETURN(part.mesh, BuildMesh(std::move(raw.vertices), raw.triangles, part.name));
  const size_t nf = part.mesh.tri.n_faces();
  part.face_primitive.assign(nf, -1);
  part.face_near_boundary.assign(nf, 1);
  for (size_t t = 0; t < part.mesh.face_of_input.size(); ++t) {
    const int f = part.mesh.face_of_input[t];
    if (f < 0) continue;
    part.face_primitive[f] = face_primitive[t];
    part.face_near_boundary[f] = near[t];
  }
  ctx.Progress("generate", 1.0);
  return part;
}

}  // namespace meshseg
