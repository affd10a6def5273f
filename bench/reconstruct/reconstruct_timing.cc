// Runs Reconstruct() on a cloud file and prints the time spent in each
// progress stage, the peak memory and the stats; writes the mesh.
//   build/bin/reconstruct_timing CLOUD OUT.ply [name=value ...]
// name=value sets a ReconstructParams field: error_tolerance, leaf_cell_size,
// graph_cut_k, refine_edge_length, projection_radius, outlier_distance,
// off_surface_distance, min_component_fraction, smoothing_iterations,
// use_graph_cut, seed, support_spacings, handle_spacings, leave_unsupported_open,
// sharp_creases.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "bench/peak_rss.h"
#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "meshseg/reconstruct.h"

namespace {

int Fail(const std::string& message) {
  std::fprintf(stderr, "reconstruct_timing: %s\n", message.c_str());
  return 1;
}

// User + system CPU seconds of the process so far.
double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

bool SetParam(const std::string& name, double value, meshseg::ReconstructParams* p) {
  const std::map<std::string, double*> fields = {
      {"error_tolerance", &p->error_tolerance},
      {"leaf_cell_size", &p->leaf_cell_size},
      {"graph_cut_k", &p->graph_cut_k},
      {"refine_edge_length", &p->refine_edge_length},
      {"projection_radius", &p->projection_radius},
      {"outlier_distance", &p->outlier_distance},
      {"off_surface_distance", &p->off_surface_distance},
      {"min_component_fraction", &p->min_component_fraction},
      {"support_spacings", &p->support_spacings},
      {"handle_spacings", &p->handle_spacings},
  };
  if (const auto it = fields.find(name); it != fields.end()) {
    *it->second = value;
    return true;
  }
  if (name == "smoothing_iterations") {
    p->smoothing_iterations = static_cast<int>(value);
  } else if (name == "use_graph_cut") {
    p->use_graph_cut = value != 0.0;
  } else if (name == "leave_unsupported_open") {
    p->leave_unsupported_open = value != 0.0;
  } else if (name == "sharp_creases") {
    p->sharp_creases = value != 0.0;
  } else if (name == "seed") {
    p->seed = static_cast<uint64_t>(value);
  } else {
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  if (argc < 3) return Fail("usage: reconstruct_timing CLOUD OUT.ply [name=value ...]");
  meshseg::ReconstructParams params;
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    const size_t eq = arg.find('=');
    if (eq == std::string::npos ||
        !SetParam(arg.substr(0, eq), std::atof(arg.c_str() + eq + 1), &params)) {
      return Fail("unknown parameter " + arg);
    }
  }
  const auto cloud = meshseg::ReadPointCloud(argv[1]);
  if (!cloud.ok()) return Fail(std::string(cloud.status().message()));
  // Wall and CPU time per stage: from a stage's first report to the next
  // stage's first. CPU time does not depend on what else the machine runs.
  std::map<std::string, std::pair<double, double>> seconds;
  std::string stage;
  Clock::time_point stage_start = Clock::now();
  double stage_cpu = CpuSeconds();
  const Clock::time_point start = stage_start;
  const double start_cpu = stage_cpu;
  const auto close_stage = [&] {
    const Clock::time_point now = Clock::now();
    const double cpu = CpuSeconds();
    if (!stage.empty()) {
      seconds[stage].first += std::chrono::duration<double>(now - stage_start).count();
      seconds[stage].second += cpu - stage_cpu;
    }
    stage_start = now;
    stage_cpu = cpu;
  };
  meshseg::RunContext ctx;
  ctx.on_progress = [&](std::string_view s, double) {
    if (s == stage) return;
    close_stage();
    stage = std::string(s);
  };
  const auto r = meshseg::Reconstruct(*cloud, params, ctx);
  close_stage();
  const Clock::time_point end = stage_start;
  if (!r.ok()) return Fail(std::string(r.status().message()));
  const auto written = meshseg::WriteMesh(r->mesh.tri, argv[2]);
  if (!written.ok()) return Fail(std::string(written.message()));
  for (const auto& [name, s] : seconds) {
    std::printf("  %-36s %7.2f s wall %7.2f s cpu\n", name.c_str(), s.first, s.second);
  }
  const auto& st = r->stats;
  std::printf(
      "total %.2f s wall, %.2f s cpu, peak %.0f MB; %zu points, %lld outliers, h %.6g, supports "
      "%lld, "
      "tets %lld, relabelled %lld, smoothed %lld, dropped components %lld, "
      "refine edge %.6g, unsupported %lld; %zu vertices, %zu faces\n",
      std::chrono::duration<double>(end - start).count(), CpuSeconds() - start_cpu,
      meshseg::bench::PeakRssMiB(), cloud->points.size(), (long long)st.outlier_count,
      st.point_spacing, (long long)st.support_count, (long long)st.tet_count,
      (long long)st.relabelled_count, (long long)st.smoothed_vertex_count,
      (long long)st.dropped_component_count, st.refine_edge_length,
      (long long)st.unsupported_vertex_count, r->mesh.tri.n_vertices(), r->mesh.tri.n_faces());
  std::printf(
      "support: %lld faces removed, %lld handles cut, %lld holes, %lld faces filled (area "
      "%.6g), genus %d -> %d\n",
      (long long)st.unsupported_face_count, (long long)st.handle_cut_count,
      (long long)st.hole_count, (long long)st.filled_face_count, st.filled_area,
      st.genus_before_support, st.genus);
  std::printf(
      "creases: %lld vertices on a crease, %lld moved onto its line, %lld added on it; %lld "
      "stretched edges split\n",
      (long long)st.crease_vertex_count, (long long)st.crease_snapped_count,
      (long long)st.crease_inserted_count, (long long)st.stretched_split_count);
  return 0;
}
