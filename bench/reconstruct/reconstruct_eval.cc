// Measures a reconstructed mesh against its truth and its cloud, in the
// cloud's point spacings (sp, ReconstructStats::point_spacing): the numbers
// issue 38 asks for, for ours and for the peer (poisson_peer) alike.
//   build/bin/reconstruct_eval MESH TRUTH CLOUD [--samples N] [--visible S]
//                              [--error-ply OUT.ply] [--missing-ply OUT.ply]
// accuracy      area samples of MESH → TRUTH
// completeness  area samples of TRUTH → MESH; "visible" only the samples
//               within S sp (default 3) of a cloud point
// off points    share of MESH's area farther than 3 sp from every cloud point
// far faces     share of MESH's area over 3.5 sp from TRUTH, how much of it is
//               farther than 3 sp from every cloud point, and its height
// topology      open / non-manifold edges and vertices as the file has them,
//               components, total genus of MESH and of TRUTH
// --error-ply   MESH's faces coloured by the distance of their centroid to
//               TRUTH: grey under 1 sp, then one colour each for 1-2, 2-4
//               and over 4 sp (for scripts/render_ply.py)
// --missing-ply TRUTH's faces coloured likewise by the distance of their
//               centroid to MESH, faces farther than S sp from every point
//               in black
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "meshseg/mesh.h"
#include "meshseg/point_cloud.h"
#include "surface_metrics.h"

namespace {

int Fail(const std::string& message) {
  std::fprintf(stderr, "reconstruct_eval: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace meshseg;  // NOLINT: a small tool
  if (argc < 4) return Fail("usage: reconstruct_eval MESH TRUTH CLOUD [--samples N] [--visible S]");
  int samples = 20000;
  double visible = 3.0;
  std::string error_ply, missing_ply;
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--samples") {
      samples = std::atoi(argv[i + 1]);
    } else if (arg == "--visible") {
      visible = std::atof(argv[i + 1]);
    } else if (arg == "--error-ply") {
      error_ply = argv[i + 1];
    } else if (arg == "--missing-ply") {
      missing_ply = argv[i + 1];
    } else {
      return Fail("unknown argument " + arg);
    }
  }
  const auto mesh = ReadMesh(argv[1]);
  if (!mesh.ok()) return Fail(std::string(mesh.status().message()));
  const auto truth = ReadMesh(argv[2]);
  if (!truth.ok()) return Fail(std::string(truth.status().message()));
  const auto cloud = ReadPointCloud(argv[3]);
  if (!cloud.ok()) return Fail(std::string(cloud.status().message()));

  const double sp = test::MedianSpacing(cloud->points);
  const MeshStats stats = MeshStatistics(*mesh);
  const auto mesh_triangles = test::Triangles(mesh->tri);
  const auto truth_triangles = test::Triangles(truth->tri);
  const test::SurfaceDistance to_mesh(mesh_triangles);
  const test::SurfaceDistance to_truth(truth_triangles);
  const mesh_internal::PointIndex cloud_index(cloud->points);
  const auto near_cloud = [&](const Eigen::Vector3d& p, double radius) {
    std::vector<uint32_t> idx;
    std::vector<double> d2;
    cloud_index.Nearest(p, 1, &idx, &d2);
    return d2[0] <= radius * radius;
  };

  const auto mesh_samples = test::AreaSamples(mesh_triangles, samples);
  const auto truth_samples = test::AreaSamples(truth_triangles, samples);
  std::vector<Eigen::Vector3d> visible_samples;
  for (const auto& p : truth_samples) {
    if (near_cloud(p, visible * sp)) visible_samples.push_back(p);
  }
  int64_t off = 0;
  for (const auto& p : mesh_samples) off += !near_cloud(p, 3.0 * sp);
  const auto accuracy = test::SortedDistances(mesh_samples, to_truth);
  const auto completeness = test::SortedDistances(truth_samples, to_mesh);
  const auto visible_completeness = test::SortedDistances(visible_samples, to_mesh);
  const auto in_sp = [&](const std::vector<double>& d, double q) {
    return test::Quantile(d, q) / sp;
  };
  std::printf("sp %.6g (%zu points)\n", sp, cloud->points.size());
  std::printf(
      "mesh %lld vertices %lld faces; open edges %lld, non-manifold edges %lld, "
      "non-manifold vertices %lld, degenerate faces %lld, components %lld, genus %lld "
      "(truth %lld)\n",
      (long long)stats.vertex_count, (long long)stats.face_count,
      (long long)stats.boundary_edge_count, (long long)stats.non_manifold_edge_count,
      (long long)stats.non_manifold_vertex_count, (long long)stats.degenerate_face_count,
      (long long)stats.component_count, (long long)test::TotalGenus(mesh->tri),
      (long long)test::TotalGenus(truth->tri));
  std::printf("accuracy      p50 %.2f  p95 %.2f  max %.2f sp\n", in_sp(accuracy, 0.5),
              in_sp(accuracy, 0.95), in_sp(accuracy, 1.0));
  std::printf("completeness  p50 %.2f  p95 %.2f  max %.2f sp\n", in_sp(completeness, 0.5),
              in_sp(completeness, 0.95), in_sp(completeness, 1.0));
  std::printf(
      "visible compl p50 %.2f  p95 %.2f  max %.2f sp (%.1f %% of the truth within %.1f sp "
      "of a point)\n",
      in_sp(visible_completeness, 0.5), in_sp(visible_completeness, 0.95),
      in_sp(visible_completeness, 1.0), 100.0 * visible_samples.size() / samples, visible);
  // Faces of `triangles` coloured by the distance of their centroid to `to`.
  const auto write_errors = [&](const TriMesh& tri, const std::vector<test::Triangle>& triangles,
                                const test::SurfaceDistance& to, bool mark_unseen,
                                const std::string& path) {
    std::vector<int> bucket(tri.n_faces());
    tbb::parallel_for(size_t{0}, triangles.size(), [&](size_t f) {
      const auto& t = triangles[f];
      const Eigen::Vector3d c = (t[0] + t[1] + t[2]) / 3.0;
      const double d = to(c) / sp;
      bucket[f] = d < 1.0 ? -1 : d < 2.0 ? 0 : d < 4.0 ? 1 : 2;
      if (mark_unseen && !near_cloud(c, visible * sp)) bucket[f] = 3;
    });
    return WriteColoredPly(tri, bucket, path);
  };
  if (!error_ply.empty()) {
    const auto written = write_errors(mesh->tri, mesh_triangles, to_truth, false, error_ply);
    if (!written.ok()) return Fail(std::string(written.message()));
  }
  if (!missing_ply.empty()) {
    const auto written = write_errors(truth->tri, truth_triangles, to_mesh, true, missing_ply);
    if (!written.ok()) return Fail(std::string(written.message()));
  }
  std::printf("off points    %.2f %% of the mesh area farther than 3 sp from every point\n",
              100.0 * off / samples);
  // Where the mesh is far from the truth (over the 3.5 sp accuracy bar):
  // how much of it lies where no point is (surface the points did not give:
  // patches) and at which height of the truth's bounding box (0 bottom, 1 top).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto v : truth->tri.vertices()) {
    lo = lo.cwiseMin(ToEigen(truth->tri.point(v)));
    hi = hi.cwiseMax(ToEigen(truth->tri.point(v)));
  }
  std::vector<double> far_height;
  int64_t far_off = 0;
  for (const auto& p : mesh_samples) {
    if (to_truth(p) <= 3.5 * sp) continue;
    far_height.push_back((p.z() - lo.z()) / (hi.z() - lo.z()));
    far_off += !near_cloud(p, 3.0 * sp);
  }
  std::sort(far_height.begin(), far_height.end());
  if (!far_height.empty()) {
    std::printf(
        "far faces     %.2f %% of the mesh area over 3.5 sp from the truth; %.1f %% of that "
        "farther than 3 sp from every point; height in the truth's box p10 %.2f p50 %.2f p90 "
        "%.2f\n",
        100.0 * far_height.size() / samples, 100.0 * far_off / far_height.size(),
        test::Quantile(far_height, 0.1), test::Quantile(far_height, 0.5),
        test::Quantile(far_height, 0.9));
  }
  return 0;
}
