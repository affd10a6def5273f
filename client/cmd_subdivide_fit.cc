// meshseg subdivide-fit IN -o CONTROL.obj [--faces N | --tolerance E] [--limit OUT.ply]
// Seed 004 (ALGORITHMS.md S5): a Loop subdivision surface with sharp creases
// fitted to the mesh IN. Writes the control mesh as OBJ with OpenSubdiv's
// crease/corner tag lines (meshseg/subdiv.h WriteControlObj) and, with
// --limit, the limit surface as a mesh. Prints the sizes and the rms / max
// distance from IN's vertices to the limit surface.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "meshseg/mesh.h"
#include "meshseg/status_macros.h"
#include "meshseg/subdiv.h"

namespace meshseg::cli {

absl::Status RunSubdivideFit(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args,
                           Args::Parse(argv, {"-o", "--faces", "--tolerance", "--limit"}, {}, 1));
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o CONTROL.obj is required");
  if (!absl::EndsWith(*out, ".obj")) {
    return absl::InvalidArgumentError(
        absl::StrCat("-o \"", *out, "\": the control mesh is written as OBJ (.obj)"));
  }
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> faces, args.Double("--faces"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> tolerance, args.Double("--tolerance"));
  if (faces && tolerance) {
    return absl::InvalidArgumentError("give --faces N or --tolerance E, not both");
  }
  SubdivParams params;
  if (faces) {
    if (!(*faces >= 4.0 && *faces == std::floor(*faces) && *faces < 1e12)) {
      return absl::InvalidArgumentError(
          absl::StrCat("--faces ", *faces, " must be a whole number of at least 4"));
    }
    params.target_faces = static_cast<int64_t>(*faces);
  }
  if (tolerance) params.tolerance = *tolerance;
  const std::optional<std::string> limit = args.Value("--limit");
  const absl::StatusOr<Mesh> mesh = ReadMesh(args.positional(0));
  if (!mesh.ok()) return mesh.status();
  const auto start = std::chrono::steady_clock::now();
  const absl::StatusOr<SubdivFit> fit = FitSubdivisionSurface(*mesh, params);
  if (!fit.ok()) return fit.status();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MESHSEG_RETURN_IF_ERROR(WriteControlObj(fit->control, *out));
  if (limit) {
    MESHSEG_ASSIGN_OR_RETURN(const Mesh& limit_mesh,
                             BuildMesh(fit->limit_vertices, fit->limit_faces, "limit surface"));
    MESHSEG_RETURN_IF_ERROR(WriteMesh(limit_mesh.tri, *limit));
  }
  std::printf(
      "wrote %s: %zu faces -> control mesh of %zu faces, %zu creases, %zu corners; "
      "input to limit surface rms %.6g, max %.6g; %.2f s\n",
      out->c_str(), mesh->tri.n_faces(), fit->control.faces.size(), fit->control.creases.size(),
      fit->control.corners.size(), fit->rms_distance, fit->max_distance, seconds);
  std::string rounds;
  for (double r : fit->rms_per_round) absl::StrAppend(&rounds, rounds.empty() ? "" : " -> ", r);
  std::printf("rms after quasi-interpolation, then per fit round: %s\n", rounds.c_str());
  if (tolerance && fit->rms_distance > *tolerance) {
    std::printf(
        "note: rms %.6g stays above --tolerance %.6g at %zu control faces (the size bound)\n",
        fit->rms_distance, *tolerance, fit->control.faces.size());
  }
  if (limit)
    std::printf("wrote %s: limit surface, %zu faces\n", limit->c_str(), fit->limit_faces.size());
  return absl::OkStatus();
}

}  // namespace meshseg::cli
