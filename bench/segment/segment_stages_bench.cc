// Per-stage wall time and peak memory of curvature + segment.
// Usage: segment_stages_bench PART VOXEL_SIZE [NOISE]   (a generated part)
//        segment_stages_bench --file MESH_FILE [OUT.ply] (a mesh file)
// Prints one line per stage: wall seconds, CPU seconds (user + system, all
// threads: on a shared machine the wall time says more about the neighbours)
// and peak resident set (ru_maxrss), then the region count per type.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/segment.h"
#include "bench/peak_rss.h"

namespace {

class Timer {
 public:
  // Prints the stage's wall and CPU seconds since the last lap and the peak
  // resident set so far.
  void Lap(const char* stage) {
    const auto now = std::chrono::steady_clock::now();
    const double cpu = meshseg::bench::CpuSeconds();
    std::printf("%-10s %8.2f s  cpu %8.2f s  peak %8.1f MiB\n", stage,
                std::chrono::duration<double>(now - last_).count(), cpu - last_cpu_,
                meshseg::bench::PeakRssMiB());
    last_ = now;
    last_cpu_ = cpu;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  double last_cpu_ = meshseg::bench::CpuSeconds();
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PART VOXEL [NOISE] | --file MESH [OUT.ply]\n", argv[0]);
    return 2;
  }
  const std::string first = argv[1];
  Timer timer;
  // The mesh stays in the StatusOr it was made in: OpenMesh 9 meshes have no
  // move constructor, so taking it out (or assigning a StatusOr) copies it.
  const bool from_file = first == "--file";
  const double noise = !from_file && argc > 3 ? std::atof(argv[3]) : 0.0;
  const absl::StatusOr<meshseg::Mesh> read =
      from_file ? meshseg::ReadMesh(argv[2])
                : absl::StatusOr<meshseg::Mesh>(absl::UnknownError("no mesh read"));
  const absl::StatusOr<meshseg::GeneratedPart> part =
      from_file ? absl::StatusOr<meshseg::GeneratedPart>(absl::UnknownError("no part generated"))
                : meshseg::GeneratePart(first, {.voxel_size = std::atof(argv[2]), .noise = noise});
  const absl::Status status = from_file ? read.status() : part.status();
  if (!status.ok()) {
    std::fprintf(stderr, "%s\n", status.ToString().c_str());
    return 1;
  }
  timer.Lap(from_file ? "read" : "generate");
  const meshseg::Mesh& mesh = from_file ? *read : part->mesh;
  std::printf("mesh       %zu vertices, %zu faces\n", mesh.tri.n_vertices(), mesh.tri.n_faces());
  auto field = meshseg::EstimateCurvature(mesh);
  if (!field.ok()) {
    std::fprintf(stderr, "%s\n", field.status().ToString().c_str());
    return 1;
  }
  timer.Lap("curvature");
  auto seg = meshseg::Segment(mesh, *field);
  if (!seg.ok()) {
    std::fprintf(stderr, "%s\n", seg.status().ToString().c_str());
    return 1;
  }
  timer.Lap("segment");
  const auto& e = seg->estimates;
  std::printf("estimates  l_avg %.4g sigma %.4g th_dis %.4g th_nm %.3g deg th_sv %.3g\n",
              e.mean_edge_length, e.noise_sigma, e.distance_tolerance, e.angle_tolerance_deg,
              e.sharp_threshold);
  std::map<std::string, int> by_type;
  for (const auto& r : seg->regions) ++by_type[meshseg::SurfaceTypeName(r.type)];
  std::printf("regions    %zu:", seg->regions.size());
  for (const auto& [type, count] : by_type) std::printf(" %s %d", type.c_str(), count);
  std::printf("\n");
  if (from_file && argc > 3) {
    const auto status = meshseg::WriteColoredPly(mesh.tri, seg->face_labels, argv[3]);
    if (!status.ok()) std::fprintf(stderr, "%s\n", status.ToString().c_str());
  }
  return 0;
}
