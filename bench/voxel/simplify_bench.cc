// Timing tool for `simplify` (issue #33): a generated part (default the 1M-
// face test_piece: --voxel-size 0.21 --noise 0.05) simplified to a share of
// its faces (default 10 %). Prints the time of the simplification alone, the
// Hausdorff distance to the input in h, and how many of the part's sharp
// feature edges (ground truth: mesh edges between two primitives whose
// normals differ by more than kSharpDeg) survive: a sample on such an edge
// is kept when the simplified surface passes within 0.5 h of it and, within
// 1.5 h, has faces facing like each of the two primitives (within 15 deg).
// With --segment OUT.ply the simplified mesh is written for `meshseg
// segment` to check that every region survives.
// Usage: voxel_simplify_bench [PART] [--voxel-size H] [--noise S] [--share F] [--segment OUT.ply]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "meshseg/fit.h"
#include "meshseg/generate.h"
#include "meshseg/voxel.h"
#include "bench/peak_rss.h"

namespace {

using meshseg::ToEigen;

constexpr double kSharpDeg = 30.0;
constexpr double kNearH = 0.5;
constexpr double kRadiusH = 1.5;
constexpr double kFacingDeg = 15.0;

// CPU seconds of this process so far (user + system): on a shared machine
// the wall time of a one-thread step says more about the neighbours.
double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::string part = "test_piece", out;
  meshseg::GenerateParams gen{.voxel_size = 0.21, .noise = 0.05};
  double share = 0.1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--voxel-size" && i + 1 < argc)
      gen.voxel_size = std::stod(argv[++i]);
    else if (a == "--noise" && i + 1 < argc)
      gen.noise = std::stod(argv[++i]);
    else if (a == "--share" && i + 1 < argc)
      share = std::stod(argv[++i]);
    else if (a == "--segment" && i + 1 < argc)
      out = argv[++i];
    else
      part = a;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const absl::StatusOr<meshseg::GeneratedPart> g = meshseg::GeneratePart(part, gen);
  if (!g.ok()) {
    std::fprintf(stderr, "%s\n", std::string(g.status().message()).c_str());
    return 1;
  }
  const double h = g->voxel_size;
  const meshseg::TriMesh& in = g->mesh.tri;
  std::printf("%s: %zu faces, h %g, noise %g h (generated in %.1f s)\n", part.c_str(), in.n_faces(),
              h, gen.noise, Seconds(t0));
  const int64_t target = static_cast<int64_t>(share * in.n_faces());
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu1 = CpuSeconds();
  const absl::StatusOr<meshseg::Simplification> s =
      meshseg::Simplify(in, {.target_faces = target, .measure_hausdorff = false});
  const double simplify_s = Seconds(t1);
  const double simplify_cpu = CpuSeconds() - cpu1;
  if (!s.ok()) {
    std::fprintf(stderr, "%s\n", std::string(s.status().message()).c_str());
    return 1;
  }
  const auto t2 = std::chrono::steady_clock::now();
  const meshseg::HausdorffDistance hd = meshseg::Hausdorff(in, s->mesh.tri);
  const double hausdorff_s = Seconds(t2);
  std::printf(
      "simplify: %zu -> %zu faces in %.2f s wall, %.2f s CPU; Hausdorff %.3f h (in->out %.3f h, "
      "out->in %.3f h, "
      "%.2f s); peak RSS %.0f MiB\n",
      in.n_faces(), s->mesh.tri.n_faces(), simplify_s, simplify_cpu, hd.Max() / h,
      hd.input_to_output / h, hd.output_to_input / h, hausdorff_s, meshseg::bench::PeakRssMiB());

  // Sharp feature edges of the ground truth, sampled at edge midpoints.
  const meshseg::TriMesh& sm = s->mesh.tri;
  std::vector<Eigen::Vector3d> centroid(sm.n_faces()), normal(sm.n_faces());
  for (auto f : sm.faces()) {
    centroid[f.idx()] = ToEigen(sm.calc_face_centroid(f));
    normal[f.idx()] = ToEigen(sm.calc_face_normal(f));
  }
  // Faces by cell of a grid of (kRadiusH + 3) h: a face whose triangle
  // comes within kRadiusH h of p has its centroid in p's cell or next door
  // (triangles are at most ~3 h from their centroid at this share).
  const double cell = (kRadiusH + 3.0) * h;
  const auto key = [&](const Eigen::Vector3d& q, int dx, int dy, int dz) {
    const int64_t x = static_cast<int64_t>(std::floor(q.x() / cell)) + dx;
    const int64_t y = static_cast<int64_t>(std::floor(q.y() / cell)) + dy;
    const int64_t z = static_cast<int64_t>(std::floor(q.z() / cell)) + dz;
    return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791);
  };
  std::unordered_map<int64_t, std::vector<int>> grid;
  for (size_t f = 0; f < centroid.size(); ++f)
    grid[key(centroid[f], 0, 0, 0)].push_back(static_cast<int>(f));
  int samples = 0, kept = 0;
  const double cos_facing = std::cos(kFacingDeg * std::numbers::pi / 180.0);
  for (auto e : in.edges()) {
    if (in.is_boundary(e)) continue;
    const int pa = g->face_primitive[in.face_handle(in.halfedge_handle(e, 0)).idx()];
    const int pb = g->face_primitive[in.face_handle(in.halfedge_handle(e, 1)).idx()];
    if (pa < 0 || pb < 0 || pa == pb) continue;
    const Eigen::Vector3d p = ToEigen(in.calc_edge_midpoint(e));
    const Eigen::Vector3d na = meshseg::Project(g->primitives[pa].surface, p).normal;
    const Eigen::Vector3d nb = meshseg::Project(g->primitives[pb].surface, p).normal;
    if (std::acos(std::clamp(na.dot(nb), -1.0, 1.0)) * 180.0 / std::numbers::pi < kSharpDeg)
      continue;
    ++samples;
    bool near = false, faces_a = false, faces_b = false;
    std::vector<int> candidates;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(p, dx, dy, dz));
          if (it != grid.end())
            candidates.insert(candidates.end(), it->second.begin(), it->second.end());
        }
      }
    }
    for (const int f : candidates) {
      if ((centroid[f] - p).norm() > cell) continue;
      auto it = sm.cfv_iter(meshseg::TriMesh::FaceHandle(static_cast<int>(f)));
      const Eigen::Vector3d a = ToEigen(sm.point(*it++)), b = ToEigen(sm.point(*it++)),
                            c = ToEigen(sm.point(*it));
      const double d = std::sqrt(meshseg::SquaredDistanceToTriangle(p, a, b, c));
      if (d <= kNearH * h) near = true;
      if (d > kRadiusH * h) continue;
      faces_a |= normal[f].dot(na) >= cos_facing;
      faces_b |= normal[f].dot(nb) >= cos_facing;
    }
    kept += near && faces_a && faces_b;
  }
  std::printf("sharp feature edge samples kept: %d of %d (%.2f %%)\n", kept, samples,
              samples > 0 ? 100.0 * kept / samples : 100.0);
  if (!out.empty()) {
    if (!meshseg::WriteMesh(sm, out).ok()) return 1;
    std::printf("wrote %s\n", out.c_str());
  }
  return 0;
}
