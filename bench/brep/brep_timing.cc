// Wall time, CPU time and peak memory of the brep stage (WriteStep: surfaces,
// edges, faces, sewing, solid, STEP file) on a generated part segmented by
// its ground truth, with surfaces refitted on the noisy vertices, and the
// STEP file read back and checked.
// Usage: brep_timing PART [VOXEL_SIZE [NOISE]] [-o OUT.step]
//   PART e.g. test_piece_large (about 1M faces at its default voxel size);
//   NOISE in multiples of the voxel size (default 0.05, the level).
// Prints one line per step (wall and CPU seconds, peak resident set), the
// stage's report and what the file read back holds.
//        brep_timing --check FILE.step MESH
// Prints what a STEP file (e.g. written by `meshseg brep`) read back holds,
// and its volume against the volume MESH encloses.

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/peak_rss.h"
#include "ground_truth_regions.h"
#include "meshseg/brep.h"
#include "meshseg/generate.h"
#include "meshseg/mesh.h"
#include "meshseg/topology.h"
#include "step_checks.h"

namespace {

double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

class Timer {
 public:
  void Report(const char* step) {
    const auto now = std::chrono::steady_clock::now();
    const double cpu = CpuSeconds();
    std::printf("%-10s %8.2f s wall %8.2f s cpu  peak %8.1f MiB\n", step,
                std::chrono::duration<double>(now - wall_).count(), cpu - cpu_,
                meshseg::bench::PeakRssMiB());
    std::fflush(stdout);
    wall_ = now;
    cpu_ = cpu;
  }

 private:
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  double cpu_ = CpuSeconds();
};

int Fail(const absl::Status& s) {
  std::fprintf(stderr, "%s\n", s.ToString().c_str());
  return 1;
}

// Prints what the STEP file at `path` holds, against `mesh`'s volume.
int ReadBack(const std::string& path, const meshseg::TriMesh& mesh) {
  absl::StatusOr<meshseg::testing::StepModel> model = meshseg::testing::ReadStep(path);
  if (!model.ok()) return Fail(model.status());
  const meshseg::testing::ShapeFacts facts = meshseg::testing::FactsOf(model->shape);
  const double mesh_volume = meshseg::testing::EnclosedVolume(mesh);
  std::printf(
      "read back  valid %d, %d solids, %d shells, %d faces, %d free edges, volume %.6g "
      "(mesh %.6g, %+.3f %%)\n",
      facts.valid, facts.solids, facts.shells, facts.faces, facts.free_edges, facts.volume,
      mesh_volume, 100.0 * (facts.volume - mesh_volume) / mesh_volume);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string out = "/tmp/brep_timing.step";
  for (size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] == "-o") {
      out = args[i + 1];
      args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + i + 2);
      break;
    }
  }
  if (args.size() == 3 && args[0] == "--check") {
    absl::StatusOr<meshseg::Mesh> mesh = meshseg::ReadMesh(args[2]);
    if (!mesh.ok()) return Fail(mesh.status());
    return ReadBack(args[1], mesh->tri);
  }
  if (args.empty()) {
    std::fprintf(stderr,
                 "usage: %s PART [VOXEL_SIZE [NOISE]] [-o OUT.step]\n"
                 "       %s --check FILE.step MESH\n",
                 argv[0], argv[0]);
    return 2;
  }
  const double voxel = args.size() > 1 ? std::atof(args[1].c_str()) : 0.0;
  const double noise = args.size() > 2 ? std::atof(args[2].c_str()) : 0.05;
  Timer timer;
  absl::StatusOr<meshseg::GeneratedPart> part =
      meshseg::GeneratePart(args[0], {.voxel_size = voxel, .noise = noise});
  if (!part.ok()) return Fail(part.status());
  timer.Report("generate");
  std::printf("mesh       %zu vertices, %zu faces, h %.4g\n", part->mesh.tri.n_vertices(),
              part->mesh.tri.n_faces(), part->voxel_size);
  const meshseg::testing::TruthSegmentation truth = meshseg::testing::TruthOf(*part);
  timer.Report("truth+fit");
  absl::StatusOr<meshseg::Topology> topo =
      meshseg::ExtractTopology(part->mesh, truth.face_labels, truth.regions);
  if (!topo.ok()) return Fail(topo.status());
  timer.Report("topology");
  absl::StatusOr<meshseg::BrepReport> report = meshseg::WriteStep(
      part->mesh, truth.face_labels, truth.regions, *topo, out, {.noise_sigma = part->noise});
  if (!report.ok()) return Fail(report.status());
  timer.Report("brep");
  std::printf("report     %d/%d faces, %d solids, valid %d, volume %.6g, %d failures\n",
              report->face_count, report->patch_count, report->solid_count, report->valid,
              report->volume, static_cast<int>(report->failures.size()));
  for (const meshseg::BrepFaceFailure& f : report->failures) {
    std::printf("  region %d patch %d: %s\n", f.region, f.patch, f.reason.c_str());
  }
  return ReadBack(out, part->mesh.tri);
}
