// meshseg generate PART -o FILE [--voxel-size H] [--noise S] [--ground-truth GT.json]
//   [--volume OUT.nrrd [--binary]]
// meshseg generate CAD_PART --cad -o FILE.stl|obj [--deflection coarse|fine] [--unit m|mm|um]
//   [--ground-truth GT.json]
#include <cstdio>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "meshseg/generate.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

// The part as a CT volume (GenerateVolume); the ground truth, if asked for,
// labels the surface `meshseg segment` extracts from it. -o also writes that
// surface as a mesh.
absl::Status WriteVolume(const std::string& name, const GenerateParams& params, const std::string& path,
                         const Args& args) {
  const bool binary = args.Has("--binary");
  MESHSEG_ASSIGN_OR_RETURN(const VolumeData volume, GenerateVolume(name, binary, params));
  const bool gzip = path.ends_with(".nrrd");
  MESHSEG_RETURN_IF_ERROR(WriteNrrd(volume, path, gzip));
  const auto& d = volume.geometry.dims;
  std::printf("wrote %s: part %s, %lld x %lld x %lld %s voxels, h=%g\n", path.c_str(), name.c_str(),
              (long long)d[0], (long long)d[1], (long long)d[2], binary ? "binary" : "grey",
              volume.geometry.axes[0].norm());
  const std::optional<std::string> gt = args.Value("--ground-truth");
  const std::optional<std::string> out = args.Value("-o");
  if (!gt && !out) return absl::OkStatus();
  const absl::StatusOr<VolumeSurface> surface = ExtractSurface(path);
  if (!surface.ok()) return surface.status();
  if (out) MESHSEG_RETURN_IF_ERROR(WriteMesh(surface->mesh.tri, *out));
  if (gt) {
    MESHSEG_ASSIGN_OR_RETURN(const GeneratedPart part, LabelWithGroundTruth(name, surface->mesh, params));
    MESHSEG_RETURN_IF_ERROR(WriteTextFile(*gt, GroundTruthJson(part)));
  }
  return absl::OkStatus();
}

// The part as an exact B-rep, tessellated as CAD systems export it
// (GenerateCadPart).
absl::Status WriteCad(const std::string& name, const std::string& out, const Args& args) {
  for (const char* flag : {"--voxel-size", "--noise", "--seed", "--volume"}) {
    if (args.Value(flag)) {
      return absl::InvalidArgumentError(absl::StrCat(flag, " does not apply to --cad parts"));
    }
  }
  if (args.Has("--binary")) return absl::InvalidArgumentError("--binary goes with --volume OUT.nrrd");
  CadParams params;
  const std::string deflection = args.Value("--deflection").value_or("coarse");
  if (deflection != "coarse" && deflection != "fine") {
    return absl::InvalidArgumentError(
        absl::StrCat("--deflection \"", deflection, "\": expected coarse or fine"));
  }
  params.deflection = deflection == "fine" ? CadDeflection::kFine : CadDeflection::kCoarse;
  const std::string unit = args.Value("--unit").value_or("mm");
  MESHSEG_ASSIGN_OR_RETURN(params.unit_scale, UnitScale(unit));
  MESHSEG_ASSIGN_OR_RETURN(const GeneratedPart part, GenerateCadPart(name, params));
  MESHSEG_RETURN_IF_ERROR(WriteMesh(part.mesh.tri, out));
  if (const std::optional<std::string> gt = args.Value("--ground-truth")) {
    MESHSEG_RETURN_IF_ERROR(WriteTextFile(*gt, GroundTruthJson(part)));
  }
  std::printf("wrote %s: CAD part %s, %zu faces, %zu vertices, %zu B-rep faces, %s deflection, %s\n",
              out.c_str(), part.name.c_str(), part.mesh.tri.n_faces(), part.mesh.tri.n_vertices(),
              part.primitives.size(), deflection.c_str(), unit.c_str());
  return absl::OkStatus();
}

}  // namespace

absl::Status RunGenerate(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv,
                  {"-o", "--voxel-size", "--noise", "--ground-truth", "--seed", "--volume",
                   "--deflection", "--unit"},
                  {"--binary", "--cad"}, 1));
  const std::optional<std::string> out = args.Value("-o");
  const std::optional<std::string> volume = args.Value("--volume");
  if (!out && !volume) {
    return absl::InvalidArgumentError(absl::StrCat("-o FILE is required; parts: ",
                                                   absl::StrJoin(PartNames(), ", "),
                                                   "; with --cad: ",
                                                   absl::StrJoin(CadPartNames(), ", ")));
  }
  if (args.Has("--cad")) {
    if (!out) return absl::InvalidArgumentError("--cad writes a mesh: -o FILE.stl|obj is required");
    return WriteCad(args.positional(0), *out, args);
  }
  for (const char* flag : {"--deflection", "--unit"}) {
    if (args.Value(flag)) return absl::InvalidArgumentError(absl::StrCat(flag, " goes with --cad"));
  }
  GenerateParams params;
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> h, args.Double("--voxel-size"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> noise, args.Double("--noise"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> seed, args.Double("--seed"));
  if (h) params.voxel_size = *h;
  if (noise) params.noise = *noise;
  if (seed) params.seed = static_cast<uint64_t>(*seed);
  if (volume) return WriteVolume(args.positional(0), params, *volume, args);
  if (args.Has("--binary")) return absl::InvalidArgumentError("--binary goes with --volume OUT.nrrd");

  MESHSEG_ASSIGN_OR_RETURN(const GeneratedPart part,
                           GeneratePart(args.positional(0), params));
  MESHSEG_RETURN_IF_ERROR(WriteMesh(part.mesh.tri, *out));
  if (const std::optional<std::string> gt = args.Value("--ground-truth")) {
    MESHSEG_RETURN_IF_ERROR(WriteTextFile(*gt, GroundTruthJson(part)));
  }
  std::printf("wrote %s: part %s, %zu faces, %zu vertices, %zu primitives, h=%g, noise=%g\n",
              out->c_str(), part.name.c_str(), part.mesh.tri.n_faces(),
              part.mesh.tri.n_vertices(), part.primitives.size(), part.voxel_size, part.noise);
  return absl::OkStatus();
}

}  // namespace meshseg::cli
