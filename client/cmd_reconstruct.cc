// meshseg reconstruct CLOUD -o MESH.ply|.off [--format FMT] [--open]
// Reconstructs a watertight mesh from a point cloud (seed 001) with the
// default ReconstructParams and writes it with the mesh writers. Areas no
// point supports are closed by minimal patches, or with --open left open.
#include <cstdio>

#include "absl/strings/str_cat.h"
#include "client/commands.h"
#include "client/progress.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/proto/convert.h"
#include "meshseg/reconstruct.h"
#include "meshseg/status_macros.h"

namespace meshseg::cli {

absl::Status RunReconstruct(const Argv& argv) {
  MESHSEG_ASSIGN_OR_RETURN(const Args args, Args::Parse(argv, {"-o", "--format"}, {"--open"}, 1));
  const std::string& input = args.positional(0);
  const std::optional<std::string> out = args.Value("-o");
  if (!out) return absl::InvalidArgumentError("-o MESH.ply is required (.ply or .off)");
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<FileFormat> format,
                           FormatFromHint(args.Value("--format").value_or("")));
  if (!format) {
    MESHSEG_ASSIGN_OR_RETURN(const bool cloud, IsPointCloudFile(input));
    if (!cloud) {
      return absl::InvalidArgumentError(absl::StrCat(
          "\"", input, "\" is a mesh, not a point cloud (xyz, pwn, ply without faces)"));
    }
  }
  MESHSEG_ASSIGN_OR_RETURN(const PointCloud cloud, ReadPointCloud(input, {.format = format}));
  ProgressPrinter progress;
  RunContext ctx;
  ctx.on_progress = [&](std::string_view stage, double f) { progress.Update(stage, f); };
  ReconstructParams params;
  params.leave_unsupported_open = args.Has("--open");
  const absl::StatusOr<Reconstruction> r = Reconstruct(cloud, params, ctx);
  progress.Finish();
  if (!r.ok()) return r.status();
  MESHSEG_RETURN_IF_ERROR(WriteMesh(r->mesh.tri, *out));
  std::printf(
      "wrote %s: %zu vertices, %zu faces from %zu points (%lld outliers, spacing %.6g, "
      "edge %.6g, %lld vertices far from the points put on f = 0%s)\n",
      out->c_str(), r->mesh.tri.n_vertices(), r->mesh.tri.n_faces(), cloud.points.size(),
      static_cast<long long>(r->stats.outlier_count), r->stats.point_spacing,
      r->stats.refine_edge_length, static_cast<long long>(r->stats.unsupported_vertex_count),
      r->stats.normals_estimated ? ", normals estimated" : "");
  const ReconstructStats& s = r->stats;
  if (params.leave_unsupported_open) {
    std::printf("%lld faces no point supports removed, %lld holes left open, genus %d\n",
                static_cast<long long>(s.unsupported_face_count),
                static_cast<long long>(s.hole_count), s.genus);
  } else {
    std::printf(
        "%lld faces no point supports replaced by %lld filled faces in %lld holes "
        "(area %.6g), genus %d (before %d)\n",
        static_cast<long long>(s.unsupported_face_count),
        static_cast<long long>(s.filled_face_count), static_cast<long long>(s.hole_count),
        s.filled_area, s.genus, s.genus_before_support);
  }
  return absl::OkStatus();
}

}  // namespace meshseg::cli
