// Issue #33's binary bar on seed 003's own route (ALGORITHMS.md S4: relax the
// terraces with the feature points locked, feature-preserving QEM on the
// relaxed surface, remesh, segment; PipelineParams::BinarySurface::kSimplify)
// or on the default route (--route relax). Each part is written as a binary
// volume at its default resolution, segmented by RunPipeline, and scored
// against the generator's ground truth on the surface the volume yields.
// Prints one row per part and whether it meets the bar: face accuracy >= 98 %,
// regions <= 1.1 x true surfaces, the right type for every surface of >= 200
// faces, full-cylinder radius within 0.15 h, plane normals within 0.3 deg.
// Usage: voxel_binary_route_bench [--route simplify|relax] [--share F] [--max-error-voxels E]
//          [PART...]   (F, E: PipelineParams::binary_face_share, binary_max_error_voxels)
//        (default: test_piece small_block plate_boss stepped_shaft)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "bench/peak_rss.h"
#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/voxel.h"
#include "segment_eval.h"

namespace {

using meshseg::PipelineParams;

constexpr double kMinAccuracy = 0.98;
constexpr double kMaxRegionRatio = 1.1;
constexpr int kTypedFaces = 200;
constexpr double kRadiusTolH = 0.15;
constexpr double kNormalTolDeg = 0.3;
constexpr double kFullTurn = 0.95;

struct Row {
  double accuracy = 0.0;
  int regions = 0, surfaces = 0, wrong_types = 0;
  double radius_error_h = 0.0, normal_deg = 0.0, wall = 0.0, cpu = 0.0;
  int64_t simplified_faces = 0;
  bool ok = false;
};

// Segments `name` as a binary volume on `route`; false on an error.
bool Score(const std::string& name, const PipelineParams& params, Row* row) {
  const absl::StatusOr<meshseg::VolumeData> volume = meshseg::GenerateVolume(name, true, {});
  if (!volume.ok()) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), std::string(volume.status().message()).c_str());
    return false;
  }
  const std::string path = "/tmp/voxel_binary_route_bench_" + name + ".nrrd";
  if (const absl::Status s = meshseg::WriteNrrd(*volume, path, /*gzip=*/true); !s.ok()) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), std::string(s.message()).c_str());
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = meshseg::bench::CpuSeconds();
  const absl::StatusOr<meshseg::PipelineResult> result = meshseg::RunPipeline(path, params);
  row->wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row->cpu = meshseg::bench::CpuSeconds() - cpu0;
  const absl::StatusOr<meshseg::VolumeSurface> surface = meshseg::ExtractSurface(path);
  if (!result.ok() || !surface.ok()) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(),
                 std::string((result.ok() ? surface.status() : result.status()).message()).c_str());
    return false;
  }
  const absl::StatusOr<meshseg::GeneratedPart> truth =
      meshseg::LabelWithGroundTruth(name, surface->mesh, {});
  if (!truth.ok()) return false;
  meshseg::Segmentation seg;
  seg.face_labels.assign(surface->mesh.tri.n_faces(), -1);
  for (size_t t = 0; t < surface->mesh.face_of_input.size(); ++t) {
    if (surface->mesh.face_of_input[t] >= 0) {
      seg.face_labels[surface->mesh.face_of_input[t]] = result->face_labels[t];
    }
  }
  seg.regions = result->regions;
  const meshseg::testing::Evaluation eval = meshseg::testing::Evaluate(*truth, seg);
  const double h = truth->voxel_size;
  row->accuracy = eval.area_fraction;
  row->regions = eval.region_count;
  row->surfaces = eval.true_count;
  row->simplified_faces = result->simplified_face_count;
  for (const meshseg::testing::PrimitiveScore& p : eval.primitives) {
    if (p.region < 0) {
      if (p.faces >= kTypedFaces) ++row->wrong_types;
      continue;
    }
    const meshseg::Region& r = result->regions[p.region];
    if (p.faces >= kTypedFaces && r.type != p.true_type) ++row->wrong_types;
    const meshseg::Surface& true_surface = truth->primitives[p.primitive].surface;
    const auto* cyl = std::get_if<meshseg::Cylinder>(&true_surface);
    if (cyl != nullptr && p.angular_span >= kFullTurn) {
      const auto* fit = std::get_if<meshseg::Cylinder>(&r.surface);
      row->radius_error_h =
          std::max(row->radius_error_h, fit ? std::abs(fit->radius - cyl->radius) / h : HUGE_VAL);
    }
    const auto* plane = std::get_if<meshseg::Plane>(&true_surface);
    if (plane != nullptr && p.faces >= kTypedFaces) {
      const auto* fit = std::get_if<meshseg::Plane>(&r.surface);
      row->normal_deg =
          std::max(row->normal_deg,
                   fit ? meshseg::testing::AxisAngleDeg(fit->normal, plane->normal) : HUGE_VAL);
    }
  }
  row->ok = row->accuracy >= kMinAccuracy && row->regions <= kMaxRegionRatio * row->surfaces &&
            row->wrong_types == 0 && row->radius_error_h <= kRadiusTolH &&
            row->normal_deg <= kNormalTolDeg;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  PipelineParams params;
  params.binary_surface = PipelineParams::BinarySurface::kSimplify;
  std::vector<std::string> parts;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--route" && i + 1 < argc) {
      const std::string r = argv[++i];
      params.binary_surface = r == "relax" ? PipelineParams::BinarySurface::kRelax
                                           : PipelineParams::BinarySurface::kSimplify;
    } else if (a == "--share" && i + 1 < argc) {
      params.binary_face_share = std::stod(argv[++i]);
    } else if (a == "--max-error-voxels" && i + 1 < argc) {
      params.binary_max_error_voxels = std::stod(argv[++i]);
    } else {
      parts.push_back(a);
    }
  }
  if (parts.empty()) parts = {"test_piece", "small_block", "plate_boss", "stepped_shaft"};
  std::printf(
      "binary volumes, route %s; bar: accuracy >= %.0f %%, regions <= %.1f x surfaces, "
      "types right (>= %d faces), radius <= %.2f h, normals <= %.1f deg\n",
      params.binary_surface == PipelineParams::BinarySurface::kRelax ? "relax" : "simplify",
      100 * kMinAccuracy, kMaxRegionRatio, kTypedFaces, kRadiusTolH, kNormalTolDeg);
  std::printf("%-14s %9s %8s %6s %9s %9s %10s %8s %8s  %s\n", "part", "accuracy", "regions",
              "wrong", "radius/h", "normal", "simplified", "wall s", "cpu s", "bar");
  int failed = 0;
  for (const std::string& name : parts) {
    Row row;
    if (!Score(name, params, &row)) {
      ++failed;
      continue;
    }
    std::printf("%-14s %8.2f%% %4d/%-3d %6d %9.3f %7.3f d %10lld %8.1f %8.1f  %s\n", name.c_str(),
                100 * row.accuracy, row.regions, row.surfaces, row.wrong_types, row.radius_error_h,
                row.normal_deg, static_cast<long long>(row.simplified_faces), row.wall, row.cpu,
                row.ok ? "met" : "NOT met");
    std::fflush(stdout);
    if (!row.ok) ++failed;
  }
  return failed == 0 ? 0 : 1;
}
