// Timing tool for the remesh stage: for each mesh file, the tessellation
// shape Assess() sees (is it CAD-like?), and the time, size and peak memory
// of IsotropicRemesh at the derived target length.
// Usage: remesh_bench MESH... [--out DIR]  (DIR: write each remesh as PLY)

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "meshseg/mesh.h"
#include "meshseg/remesh.h"
#include "bench/peak_rss.h"

int main(int argc, char** argv) {
  std::vector<std::string> files;
  std::string out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: %s MESH... [--out DIR]\n", argv[0]);
    return 2;
  }
  int failures = 0;
  for (const std::string& file : files) {
    const auto mesh = meshseg::ReadMesh(file);
    if (!mesh.ok()) {
      std::fprintf(stderr, "%s\n", mesh.status().ToString().c_str());
      ++failures;
      continue;
    }
    const meshseg::TessellationShape shape = meshseg::Assess(*mesh);
    std::printf("%s: %zu faces, l_avg %.4g, thin area %.1f%%, median shortest edge %.4g -> %s\n",
                mesh->name.c_str(), mesh->tri.n_faces(), meshseg::MeanEdgeLength(mesh->tri),
                100.0 * shape.thin_area_fraction, shape.median_shortest_edge,
                shape.cad_like ? "CAD-like, remesh" : "scan-like, keep");
    const auto start = std::chrono::steady_clock::now();
    meshseg::RunContext ctx;
    ctx.on_progress = [&](std::string_view, double fraction) {
      std::printf("    %3.0f%% at %.2f s\n", 100.0 * fraction,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    };
    meshseg::RemeshStats stats;
    const auto remeshed =
        meshseg::IsotropicRemesh(*mesh, shape.target_edge_length, {}, ctx, &stats);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!remeshed.ok()) {
      std::fprintf(stderr, "%s\n", remeshed.status().ToString().c_str());
      ++failures;
      continue;
    }
    std::printf("  remesh at %.4g: %zu faces, l_avg %.4g, %.2f s, peak %.1f MiB\n",
                shape.target_edge_length, remeshed->tri.n_faces(),
                meshseg::MeanEdgeLength(remeshed->tri), seconds, meshseg::bench::PeakRssMiB());
    if (stats.small_feature_radius > 0.0) {
      std::printf("  small features of radius %.4g: remeshed at %.4g\n", stats.small_feature_radius,
                  stats.fine_edge_length);
    }
    if (!out_dir.empty()) {
      const std::string path =
          (std::filesystem::path(out_dir) / (std::filesystem::path(file).stem().string() + ".remeshed.ply"))
              .string();
      const auto status = meshseg::WriteMesh(remeshed->tri, path);
      if (!status.ok()) std::fprintf(stderr, "%s\n", status.ToString().c_str());
    }
  }
  return failures == 0 ? 0 : 1;
}
