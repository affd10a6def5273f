// meshseg generate PART -o FILE [--voxel-size H] [--noise S] [--ground-truth GT.json]
#include <cstdio>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "meshseg/generate.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunGenerate(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(
      const Args args,
      Args::Parse(argv, {"-o", "--voxel-size", "--noise", "--ground-truth", "--seed"}, {}, 1));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) {
    return absl::InvalidArgumentError(absl::StrCat("-o FILE is required; parts: ",
                                                   absl::StrJoin(PartNames(), ", ")));
  }
  GenerateParams params;
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> h, args.Double("--voxel-size"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> noise, args.Double("--noise"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> seed, args.Double("--seed"));
  if (h) params.voxel_size = *h;
  if (noise) params.noise = *noise;
  if (seed) params.seed = static_cast<uint64_t>(*seed);

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
