// Timing tool for `simplify` (issue #33): a generated part (default the 1M-
// face test_piece: --voxel-size 0.21 --noise 0.05) simplified to a share of
// its faces (default 10 %). Prints the time of the simplification alone, the
// Hausdorff distance to the input in h, and how many of the part's sharp
// feature edges (ground truth: mesh edges between two primitives whose
// normals differ by more than kSharpDeg) survive: a sample on such an edge
// is kept when the simplified surface passes within 0.5 h of it and, within
// 1.5 h, has faces facing like each of the two primitives (within 15 deg;
// the primitives' normals oriented like the input's faces there). Printed
// per sharp edge (pair of primitives) and in all.
// Then the simplified mesh is written (--out, default a file in /tmp) and
// segmented by the pipeline (untimed): a true surface is kept when some
// region's faces lie mostly on it (an output face lies on the surface two of
// its corners, which are input vertices, lie on).
// Usage: voxel_simplify_bench [PART] [--voxel-size H] [--noise S] [--share F] [--out OUT.ply]
//          [--crease-deg D] [--max-error-h E]   (E: rms error bound in h, default 0.2; 0 = none)
//          [--time-only]   (print the simplification's time and stop: for A/B timing runs)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "bench/peak_rss.h"
#include "meshseg/fit.h"
#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/voxel.h"

namespace {

using meshseg::ToEigen;

constexpr double kSharpDeg = 30.0;
constexpr double kNearH = 0.5;
constexpr double kRadiusH = 1.5;
constexpr double kFacingDeg = 15.0;

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The true surface of each output face: the primitive two of its corners lie
// on (-1 if none).
std::vector<int> OutputFaceTruth(const meshseg::GeneratedPart& g,
                                 const meshseg::Simplification& s) {
  const meshseg::TriMesh& m = s.mesh.tri;
  std::vector<int> truth(m.n_faces(), -1);
  for (auto f : m.faces()) {
    int p[3], c = 0;
    for (auto v : m.fv_range(f)) p[c++] = g.vertex_primitive[s.input_vertex[v.idx()]];
    truth[f.idx()] = (p[0] == p[1] || p[0] == p[2]) ? p[0] : (p[1] == p[2] ? p[1] : -1);
  }
  return truth;
}

// Segments the simplified mesh written at `path` and prints, per true
// surface, the region whose faces lie mostly on it; true if every surface
// with faces has one.
bool CheckRegions(const meshseg::GeneratedPart& g, const meshseg::Simplification& s,
                  const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  const absl::StatusOr<meshseg::PipelineResult> r = meshseg::RunPipeline(path);
  if (!r.ok()) {
    std::fprintf(stderr, "segment %s: %s\n", path.c_str(),
                 std::string(r.status().message()).c_str());
    return false;
  }
  const std::vector<int> truth = OutputFaceTruth(g, s);
  // faces[region][primitive]
  std::unordered_map<int, std::unordered_map<int, int>> faces;
  std::vector<int> primitive_faces(g.primitives.size(), 0);
  for (size_t f = 0; f < truth.size(); ++f) {
    if (truth[f] < 0) continue;
    ++primitive_faces[truth[f]];
    if (r->face_labels[f] >= 0) ++faces[r->face_labels[f]][truth[f]];
  }
  std::vector<int> kept_by(g.primitives.size(), -1);
  for (const auto& [region, counts] : faces) {
    int best = -1, total = 0;
    for (const auto& [p, n] : counts) {
      total += n;
      if (best < 0 || n > counts.at(best)) best = p;
    }
    if (2 * counts.at(best) > total) kept_by[best] = region;
  }
  int surfaces = 0, kept = 0;
  for (size_t p = 0; p < g.primitives.size(); ++p) {
    if (primitive_faces[p] == 0) continue;
    ++surfaces;
    kept += kept_by[p] >= 0;
    std::printf("  %-20s %6d faces: %s\n", g.primitives[p].name.c_str(), primitive_faces[p],
                kept_by[p] >= 0 ? "kept" : "LOST");
  }
  std::printf(
      "segmentation of the simplified mesh (%.1f s): %zu regions; true "
      "surfaces kept %d of %d\n",
      Seconds(t0), r->regions.size(), kept, surfaces);
  return kept == surfaces;
}

}  // namespace

int main(int argc, char** argv) {
  std::string part = "test_piece", out = "/tmp/voxel_simplify_bench.ply";
  meshseg::GenerateParams gen{.voxel_size = 0.21, .noise = 0.05};
  double share = 0.1;
  bool time_only = false;
  // The face target with an error bound (rms distance of a collapse's
  // merged planes, --max-error-h, default 0.2 h): both together are how a
  // user asks for "this many faces, but never worse than this".
  meshseg::SimplifyParams params{.max_error = 0.2, .measure_hausdorff = false};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--voxel-size" && i + 1 < argc)
      gen.voxel_size = std::stod(argv[++i]);
    else if (a == "--noise" && i + 1 < argc)
      gen.noise = std::stod(argv[++i]);
    else if (a == "--share" && i + 1 < argc)
      share = std::stod(argv[++i]);
    else if (a == "--crease-deg" && i + 1 < argc)
      params.crease_deg = std::stod(argv[++i]);
    else if (a == "--max-error-h" && i + 1 < argc)
      params.max_error = std::stod(argv[++i]);  // scaled by h below
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--time-only")
      time_only = true;
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
  params.target_faces = static_cast<int64_t>(share * in.n_faces());
  params.max_error *= h;
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu1 = meshseg::bench::CpuSeconds();
  const absl::StatusOr<meshseg::Simplification> s = meshseg::Simplify(in, params);
  const double simplify_s = Seconds(t1);
  const double simplify_cpu = meshseg::bench::CpuSeconds() - cpu1;
  if (!s.ok()) {
    std::fprintf(stderr, "%s\n", std::string(s.status().message()).c_str());
    return 1;
  }
  if (time_only) {
    std::printf("simplify: %zu -> %zu faces in %.2f s wall, %.2f s CPU; peak RSS %.0f MiB\n",
                in.n_faces(), s->mesh.tri.n_faces(), simplify_s, simplify_cpu,
                meshseg::bench::PeakRssMiB());
    return 0;
  }
  const auto t2 = std::chrono::steady_clock::now();
  const meshseg::HausdorffDistance hd = meshseg::Hausdorff(in, s->mesh.tri);
  const double hausdorff_s = Seconds(t2);
  std::printf(
      "simplify: %zu -> %zu faces in %.2f s wall, %.2f s CPU; "
      "Hausdorff %.3f h (in->out %.3f h, "
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
  std::map<std::string, std::pair<int, int>> by_edge;  // kept and sampled, per pair of surfaces
  const double cos_facing = std::cos(kFacingDeg * std::numbers::pi / 180.0);
  for (auto e : in.edges()) {
    if (in.is_boundary(e)) continue;
    const int pa = g->face_primitive[in.face_handle(in.halfedge_handle(e, 0)).idx()];
    const int pb = g->face_primitive[in.face_handle(in.halfedge_handle(e, 1)).idx()];
    if (pa < 0 || pb < 0 || pa == pb) continue;
    const Eigen::Vector3d p = ToEigen(in.calc_edge_midpoint(e));
    // The surfaces' normals oriented like the input's faces (a bore's
    // cylinder normal points away from its axis, the mesh's into it).
    const auto oriented = [&](int prim, int side) {
      const Eigen::Vector3d n = meshseg::Project(g->primitives[prim].surface, p).normal;
      const Eigen::Vector3d face =
          ToEigen(in.calc_face_normal(in.face_handle(in.halfedge_handle(e, side))));
      return n.dot(face) < 0.0 ? Eigen::Vector3d(-n) : n;
    };
    const Eigen::Vector3d na = oriented(pa, 0), nb = oriented(pb, 1);
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
    auto& [pair_kept, pair_samples] = by_edge[g->primitives[std::min(pa, pb)].name + " / " +
                                              g->primitives[std::max(pa, pb)].name];
    pair_kept += near && faces_a && faces_b;
    ++pair_samples;
  }
  double worst_edge = 100.0;
  for (const auto& [pair, counts] : by_edge) {
    const double share_kept = 100.0 * counts.first / counts.second;
    worst_edge = std::min(worst_edge, share_kept);
    std::printf("  sharp edge %-32s %5d of %5d samples kept (%.1f %%)\n", pair.c_str(),
                counts.first, counts.second, share_kept);
  }
  std::printf(
      "sharp feature edge samples kept: %d of %d (%.2f %%); %zu sharp "
      "edges, worst %.1f %%\n",
      kept, samples, samples > 0 ? 100.0 * kept / samples : 100.0, by_edge.size(), worst_edge);
  if (!meshseg::WriteMesh(sm, out).ok()) return 1;
  return CheckRegions(*g, *s, out) ? 0 : 1;
}
