// meshseg generate PART -o FILE [--voxel-size H] [--noise S] [--ground-truth GT.json]
//   [--volume OUT.nrrd [--binary]]
// meshseg generate CAD_PART --cad -o FILE.stl|obj [--deflection coarse|fine] [--unit m|mm|um]
//   [--ground-truth GT.json]
// meshseg generate PART --scan CLOUD.xyz [--scan-points N] [--views N]
//   [--scan-noise S] [--outliers F] [--scan-normals] [--ground-truth GT.json]
// meshseg generate PART --surface-points N -o CLOUD.xyz [--scan-noise S]
// The CAD form builds the part as an exact OpenCASCADE B-rep and writes its
// tessellation (GenerateCadPart). The scan form writes a simulated laser scan
// of the part (ScanPart); its ground truth adds the primitive and outlier flag
// of every point. The last writes N points uniform on the part's surface (SampleSurface), with
// Gaussian noise of S nominal spacings (sqrt(area / N)) if given.
#include <cmath>
#include <cstdio>
#include <random>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "client/commands.h"
#include "meshseg/generate.h"
#include "meshseg/point_cloud.h"
#include "meshseg/status_macros.h"
#include "meshseg/voxel.h"

namespace meshseg::cli {
namespace {

absl::Status WriteScan(const Args& args, const GenerateParams& part_params,
                       const std::string& out) {
  ScanParams params;
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> points, args.Double("--scan-points"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> views, args.Double("--views"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> noise, args.Double("--scan-noise"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> outliers, args.Double("--outliers"));
  if (points) params.points = static_cast<int64_t>(*points);
  if (views) params.views = static_cast<int>(*views);
  if (noise) params.noise = *noise;
  if (outliers) params.outliers = *outliers;
  params.normals = args.Has("--scan-normals");
  params.seed = part_params.seed;
  MESHSEG_ASSIGN_OR_RETURN(const ScannedPart scan,
                           ScanPart(args.positional(0), params, part_params));
  MESHSEG_RETURN_IF_ERROR(WritePointCloud(scan.cloud, out));
  if (const std::optional<std::string> gt = args.Value("--ground-truth")) {
    MESHSEG_RETURN_IF_ERROR(WriteTextFile(*gt, ScanTruthJson(scan)));
  }
  std::printf(
      "wrote %s: scan of %s, %zu points (%lld outliers) from %d views, spacing %g, noise %g, "
      "%.1f %% of the surface seen\n",
      out.c_str(), scan.part.name.c_str(), scan.cloud.points.size(),
      static_cast<long long>(scan.cloud.points.size() - params.points), params.views, scan.spacing,
      params.noise * scan.spacing, 100.0 * scan.seen_area_fraction);
  return absl::OkStatus();
}

absl::Status WriteSurfacePoints(const Args& args, const GenerateParams& part_params,
                                const std::string& out) {
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> count, args.Double("--surface-points"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> noise, args.Double("--scan-noise"));
  if (!(*count >= 1)) {
    return absl::InvalidArgumentError(absl::StrCat("--surface-points ", *count, " must be >= 1"));
  }
  GenerateParams clean = part_params;
  clean.noise = 0.0;
  MESHSEG_ASSIGN_OR_RETURN(const GeneratedPart part, GeneratePart(args.positional(0), clean));
  const SurfaceSamples samples =
      SampleSurface(part, static_cast<int64_t>(*count), part_params.seed);
  double area = 0.0;
  for (const auto f : part.mesh.tri.faces()) area += part.mesh.tri.calc_face_area(f);
  const double sigma = noise.value_or(0.0) * std::sqrt(area / *count);
  std::mt19937_64 rng(part_params.seed + 1);
  std::normal_distribution<double> gauss(0.0, sigma > 0.0 ? sigma : 1.0);
  PointCloud cloud;
  cloud.points = samples.points;
  if (sigma > 0.0) {
    for (size_t i = 0; i < cloud.points.size(); ++i)
      cloud.points[i] += gauss(rng) * samples.normals[i];
  }
  MESHSEG_RETURN_IF_ERROR(WritePointCloud(cloud, out));
  std::printf("wrote %s: %zu points on %s, noise %g\n", out.c_str(), cloud.points.size(),
              part.name.c_str(), sigma);
  return absl::OkStatus();
}

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
                   "--scan", "--scan-points", "--views", "--scan-noise", "--outliers",
                   "--surface-points", "--deflection", "--unit"},
                  {"--binary", "--scan-normals", "--cad"}, 1));
  const std::optional<std::string> out = args.Value("-o");
  const std::optional<std::string> volume = args.Value("--volume");
  const std::optional<std::string> scan = args.Value("--scan");
  if (args.Has("--surface-points")) {
    if (!out) return absl::InvalidArgumentError("--surface-points N needs -o CLOUD.xyz");
    GenerateParams params;
    MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> seed, args.Double("--seed"));
    if (seed) params.seed = static_cast<uint64_t>(*seed);
    return WriteSurfacePoints(args, params, *out);
  }
  if (!out && !volume && !scan) {
    return absl::InvalidArgumentError(
        absl::StrCat("-o FILE, --volume OUT.nrrd or --scan CLOUD.xyz is required; parts: ",
                     absl::StrJoin(PartNames(), ", "), "; with --cad: ",
                     absl::StrJoin(CadPartNames(), ", ")));
  }
  if (args.Has("--cad")) {
    if (!out) return absl::InvalidArgumentError("--cad writes a mesh: -o FILE.stl|obj is required");
    return WriteCad(args.positional(0), *out, args);
  }
  for (const char* flag : {"--deflection", "--unit"}) {
    if (args.Value(flag)) return absl::InvalidArgumentError(absl::StrCat(flag, " goes with --cad"));
  }
  if (out && scan) return absl::InvalidArgumentError("give -o FILE or --scan CLOUD.xyz, not both");
  GenerateParams params;
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> h, args.Double("--voxel-size"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> noise, args.Double("--noise"));
  MESHSEG_ASSIGN_OR_RETURN(const std::optional<double> seed, args.Double("--seed"));
  if (h) params.voxel_size = *h;
  if (noise) params.noise = *noise;
  if (seed) params.seed = static_cast<uint64_t>(*seed);
  if (scan) return WriteScan(args, params, *scan);
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
