// Timing tool for the `subdiv` stage (issue #35): a Loop subdivision surface
// fitted to a dense smooth mesh. Default input: a tube of radius 1 around a
// trefoil (scale 2: bending at radii >= 2.9), 2000 x 250 vertices = 1M
// faces, noise 0.05 h along the normal; or any mesh file given. Fits a
// control mesh of --faces faces (default 20000) and prints the time of each
// step (decimation, quasi-interpolation, each fit round: the stage's
// progress marks), the total, the peak resident memory and the rms distance
// data -> limit surface. Target (issue #35): <= 30 s, <= 2 GB.
// Also prints the distance from the limit surface's vertices back to the
// nearest input vertex (rms, max): flaps of the limit surface where no data
// point is show there, not in the data -> limit rms.
// --guard F sets SubdivParams::data_guard_fraction, --no-creases turns
// SubdivParams::tag_creases off (to compare).
// Usage: subdiv_fit_bench [IN] [--faces N] [--along N --around N] [--guard F] [--no-creases]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "bench/peak_rss.h"
#include "meshseg/mesh.h"
#include "meshseg/subdiv.h"
#include "mesh/point_index.h"

namespace {

using Clock = std::chrono::steady_clock;

// CPU seconds of this process so far (user + system): on a shared machine
// the wall time says more about the neighbours.
double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double Seconds(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Eigen::Vector3d Trefoil(double t) {
  const double w = 2.0 + std::cos(3 * t);
  return 2.0 * Eigen::Vector3d(w * std::cos(2 * t), w * std::sin(2 * t), std::sin(3 * t));
}

// The noisy tube (tests/core/subdiv/shapes.h's KnotTube at this size).
absl::StatusOr<meshseg::Mesh> Tube(int along, int around) {
  const double h = 2 * std::numbers::pi / around;  // about the mean edge, radius 1
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.05 * h);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < along; ++i) {
    const double t = 2 * std::numbers::pi * i / along;
    const Eigen::Vector3d tan = (Trefoil(t + 1e-6) - Trefoil(t - 1e-6)).normalized();
    const Eigen::Vector3d u = Eigen::Vector3d::UnitZ().cross(tan).normalized();
    const Eigen::Vector3d v = tan.cross(u);
    for (int j = 0; j < around; ++j) {
      const double phi = 2 * std::numbers::pi * (j + 0.5 * (i % 2)) / around;
      const Eigen::Vector3d n = std::cos(phi) * u + std::sin(phi) * v;
      vertices.push_back(Trefoil(t) + (1.0 + noise(rng)) * n);
    }
  }
  for (int i = 0; i < along; ++i) {
    for (int j = 0; j < around; ++j) {
      const int i1 = (i + 1) % along, j1 = (j + 1) % around;
      const int p = i * around + j, q = i * around + j1, r = i1 * around + j, s = i1 * around + j1;
      faces.push_back({p, r, q});
      faces.push_back({q, r, s});
    }
  }
  return meshseg::BuildMesh(std::move(vertices), faces, "trefoil tube");
}

}  // namespace

int main(int argc, char** argv) {
  std::string input;
  int64_t target = 20000;
  int along = 2000, around = 250;
  meshseg::SubdivParams params;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--faces" && i + 1 < argc) {
      target = std::atoll(argv[++i]);
    } else if (a == "--along" && i + 1 < argc) {
      along = std::atoi(argv[++i]);
    } else if (a == "--around" && i + 1 < argc) {
      around = std::atoi(argv[++i]);
    } else if (a == "--guard" && i + 1 < argc) {
      params.data_guard_fraction = std::atof(argv[++i]);
    } else if (a == "--no-creases") {
      params.tag_creases = false;
    } else {
      input = a;
    }
  }
  const auto t0 = Clock::now();
  absl::StatusOr<meshseg::Mesh> mesh =
      input.empty() ? Tube(along, around) : meshseg::ReadMesh(input);
  if (!mesh.ok()) {
    std::fprintf(stderr, "%s\n", std::string(mesh.status().message()).c_str());
    return 1;
  }
  std::printf("input %s: %zu faces, %zu vertices, read/built in %.2f s, peak %.0f MiB\n",
              input.empty() ? "trefoil tube" : input.c_str(), mesh->tri.n_faces(),
              mesh->tri.n_vertices(), Seconds(t0), meshseg::bench::PeakRssMiB());
  params.target_faces = target;
  meshseg::RunContext ctx;
  const auto t1 = Clock::now();
  const double cpu0 = CpuSeconds();
  double mark = 0.0;
  ctx.on_progress = [&](std::string_view, double f) {
    // The stage's marks: 0.4 decimation done, 0.5 quasi-interpolation, then
    // 0.5 + 0.5 (round + 1) / rounds.
    if (f >= 0.4 && mark < 0.4) {
      std::printf("  decimation done at %.2f s (cpu %.2f s)\n", Seconds(t1), CpuSeconds() - cpu0);
    }
    if (f >= 0.5 && f > mark && mark >= 0.4) {
      std::printf("  %.2f at %.2f s (cpu %.2f s)\n", f, Seconds(t1), CpuSeconds() - cpu0);
    }
    std::fflush(stdout);
    mark = std::max(mark, f);
  };
  absl::StatusOr<meshseg::SubdivFit> fit = meshseg::FitSubdivisionSurface(*mesh, params, ctx);
  const double seconds = Seconds(t1);
  const double cpu = CpuSeconds() - cpu0;
  if (!fit.ok()) {
    std::fprintf(stderr, "%s\n", std::string(fit.status().message()).c_str());
    return 1;
  }
  std::printf(
      "fit: %zu control faces, %zu creases, %zu corners in %.2f s (cpu %.2f s); peak %.0f MiB; "
      "rms %.4g max %.4g (model units); rms per round:",
      fit->control.faces.size(), fit->control.creases.size(), fit->control.corners.size(), seconds,
      cpu, meshseg::bench::PeakRssMiB(), fit->rms_distance, fit->max_distance);
  for (double r : fit->rms_per_round) std::printf(" %.4g", r);
  std::printf("\n");
  std::vector<Eigen::Vector3d> input_points;
  for (auto v : mesh->tri.vertices()) input_points.push_back(meshseg::ToEigen(mesh->tri.point(v)));
  const meshseg::mesh_internal::PointIndex index(input_points);
  double back_rms = 0.0, back_max = 0.0;
  std::vector<uint32_t> nearest;
  std::vector<double> dist2;
  for (const Eigen::Vector3d& p : fit->limit_vertices) {
    index.Nearest(p, 1, &nearest, &dist2);
    back_rms += dist2[0];
    back_max = std::max(back_max, std::sqrt(dist2[0]));
  }
  back_rms = std::sqrt(back_rms / std::max<size_t>(1, fit->limit_vertices.size()));
  std::printf("limit surface -> nearest input vertex: rms %.4g max %.4g\n", back_rms, back_max);
  return 0;
}
