// Scans straight to regions (issue 38 item 6): simulated laser scans of
// generated parts (ScanPart: occlusion, uneven density, range noise,
// optional outliers) through the whole pipeline (RunPipeline on the XYZ
// file, as `meshseg segment` runs it), scored against the scan's truth with
// the tests' majority matching (tests/core/segment/segment_eval.h,
// EvaluatePoints):
//   point accuracy  genuine points labelled with their true surface (points
//                   the pipeline discarded count as wrong; outliers left out)
//   typed           surfaces whose seen area is >= 1 % of the seen area whose
//                   majority region has the true type / how many there are
//   regions         regions of the result / primitives with points
// and at the end, per part over its draws: mean and worst point accuracy,
// draws at >= 95 %, draws with every surface typed, and the surfaces that
// were not (with how many draws).
//   build/bin/scan_regions [parts=a,b,...] [seeds=1,2,3] [points=40000]
//                          [views=4] [noise=0.3] [outliers=0] [normals=0]
//                          [verbose=0] [open=0] [dir=/tmp]
// open=1 leaves the areas no point supports open (meshseg segment --open).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/point_index.h"
#include "meshseg/generate.h"
#include "meshseg/pipeline.h"
#include "meshseg/point_cloud.h"
#include "segment_eval.h"

namespace {

constexpr double kMinSeenShare = 0.01;  // "every surface of >= 1 % of the area"

std::vector<std::string> Split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string s; std::getline(ss, s, ',');) out.push_back(s);
  return out;
}

// Wrong genuine points (region not standing for their primitive, or
// unlabelled) by their distance to the nearest genuine point of another
// primitive, in nominal spacings: < 1, 1-3, >= 3 (an edge band vs whole
// areas in a wrong region).
std::array<int64_t, 3> WrongByEdgeDistance(const meshseg::ScannedPart& scan,
                                           const std::vector<int>& labels,
                                           const std::vector<int>& region_primitive) {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> truth;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (scan.is_outlier[i] || scan.point_primitive[i] < 0) continue;
    const int l = labels[i];
    if (l >= 0 && region_primitive[l] == scan.point_primitive[i]) continue;
    points.push_back(scan.cloud.points[i]);
    truth.push_back(scan.point_primitive[i]);
  }
  std::vector<Eigen::Vector3d> genuine;
  std::vector<int> genuine_truth;
  for (size_t i = 0; i < labels.size(); ++i) {
    if (scan.is_outlier[i] || scan.point_primitive[i] < 0) continue;
    genuine.push_back(scan.cloud.points[i]);
    genuine_truth.push_back(scan.point_primitive[i]);
  }
  const meshseg::mesh_internal::PointIndex index(genuine);
  std::array<int64_t, 3> out = {0, 0, 0};
  std::vector<std::pair<uint32_t, double>> found;
  for (size_t k = 0; k < points.size(); ++k) {
    index.WithinRadius(points[k], 3.0 * scan.spacing, &found);
    double d = 3.0 * scan.spacing;
    for (const auto& [j, d2] : found) {
      if (genuine_truth[j] != truth[k]) {
        d = std::sqrt(d2);
        break;
      }
    }
    ++out[d < scan.spacing ? 0 : d < 3.0 * scan.spacing ? 1 : 2];
  }
  return out;
}

struct Row {
  double accuracy = 0.0;
  int typed = 0, surfaces = 0;
  bool ok = false;
  std::vector<std::string> untyped;  // surfaces >= 1 % of the seen area not of their type
};

Row OneScan(const std::string& part, uint64_t seed, const meshseg::ScanParams& base,
            const meshseg::PipelineParams& pipeline, const std::string& dir, bool verbose) {
  meshseg::ScanParams params = base;
  params.seed = seed;
  Row row;
  const auto scan = meshseg::ScanPart(part, params);
  if (!scan.ok()) {
    std::printf("%-14s %4lu  scan failed: %s\n", part.c_str(), static_cast<unsigned long>(seed),
                std::string(scan.status().message()).c_str());
    return row;
  }
  const std::string path = dir + "/scan_regions_" + part + "_" + std::to_string(seed) + ".xyz";
  if (const auto st = meshseg::WritePointCloud(scan->cloud, path); !st.ok()) {
    std::printf("%s\n", std::string(st.message()).c_str());
    return row;
  }
  const auto start = std::chrono::steady_clock::now();
  const auto r = meshseg::RunPipeline(path, pipeline);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::filesystem::remove(path);
  if (!r.ok()) {
    std::printf("%-14s %4lu  pipeline failed: %s\n", part.c_str(), static_cast<unsigned long>(seed),
                std::string(r.status().message()).c_str());
    return row;
  }
  const meshseg::testing::Evaluation e =
      meshseg::testing::EvaluatePoints(*scan, r->point_labels, static_cast<int>(r->regions.size()));
  double seen = 0.0;
  for (const double a : scan->primitive_seen_area) seen += a;
  std::vector<long> genuine_points(scan->part.primitives.size(), 0);
  for (size_t i = 0; i < scan->point_primitive.size(); ++i) {
    if (!scan->is_outlier[i] && scan->point_primitive[i] >= 0) {
      ++genuine_points[scan->point_primitive[i]];
    }
  }
  std::string misses;
  int with_points = 0;
  for (const auto& s : e.primitives) {
    ++with_points;
    if (scan->primitive_seen_area[s.primitive] < kMinSeenShare * seen) continue;
    ++row.surfaces;
    const bool typed = s.region >= 0 && r->regions[s.region].type == s.true_type;
    row.typed += typed;
    if (!typed) row.untyped.push_back(s.name);
    if (!typed || verbose) {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "\n      %s %s (%.1f %% of seen area, %ld points): %s region %d (%ld faces, "
                    "rms %.3g), %.3f right",
                    typed ? "  " : "!!", s.name.c_str(),
                    100.0 * scan->primitive_seen_area[s.primitive] / seen,
                    genuine_points[s.primitive],
                    s.region >= 0 ? meshseg::SurfaceTypeName(r->regions[s.region].type) : "no",
                    s.region,
                    s.region >= 0 ? static_cast<long>(r->regions[s.region].face_count) : 0L,
                    s.region >= 0 ? r->regions[s.region].rms_distance : 0.0, s.covered);
      misses += buf;
      if (verbose) {  // where the rest of its points went
        std::map<int, int64_t> to;
        int64_t n = 0;
        for (size_t i = 0; i < r->point_labels.size(); ++i) {
          if (scan->point_primitive[i] != s.primitive || scan->is_outlier[i]) continue;
          ++n;
          ++to[r->point_labels[i]];
        }
        for (const auto& [region, count] : to) {
          if (region == s.region || count < 0.01 * n) continue;
          const int p = region >= 0 ? e.region_primitive[region] : -1;
          std::snprintf(buf, sizeof buf, " | %.3f in region %d (%s, of %s)",
                        static_cast<double>(count) / n, region,
                        region >= 0 ? meshseg::SurfaceTypeName(r->regions[region].type) : "-",
                        p >= 0 ? scan->part.primitives[p].name.c_str() : "-");
          misses += buf;
        }
      }
    }
  }
  int64_t unlabelled = 0, genuine = 0;
  for (size_t i = 0; i < r->point_labels.size(); ++i) {
    if (scan->is_outlier[i]) continue;
    ++genuine;
    unlabelled += r->point_labels[i] < 0;
  }
  row.accuracy = e.area_fraction;
  row.ok = true;
  const std::array<int64_t, 3> wrong =
      WrongByEdgeDistance(*scan, r->point_labels, e.region_primitive);
  const double g = static_cast<double>(std::max<int64_t>(1, genuine));
  std::printf("%-14s %4lu %7zu %5.1f %7.2f %8.2f %5.2f %5.2f %5.2f %5d/%-3d %4zu/%-3d %7.1f%s\n",
              part.c_str(), static_cast<unsigned long>(seed), scan->cloud.points.size(),
              100.0 * scan->seen_area_fraction, 100.0 * unlabelled / g, 100.0 * e.area_fraction,
              100.0 * wrong[0] / g, 100.0 * wrong[1] / g, 100.0 * wrong[2] / g, row.typed,
              row.surfaces, r->regions.size(), with_points, seconds, misses.c_str());
  std::fflush(stdout);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> arg = {
      {"parts", "test_piece,small_block,plate_boss,stepped_shaft"},
      {"seeds", "1,2,3"},
      {"points", "40000"},
      {"views", "4"},
      {"noise", "0.3"},
      {"outliers", "0"},
      {"normals", "0"},
      {"verbose", "0"},
      {"open", "0"},
      {"dir", "/tmp"}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const size_t eq = a.find('=');
    if (eq == std::string::npos || !arg.count(a.substr(0, eq))) {
      std::fprintf(stderr, "scan_regions: unknown argument %s\n", a.c_str());
      return 1;
    }
    arg[a.substr(0, eq)] = a.substr(eq + 1);
  }
  meshseg::ScanParams params;
  params.points = std::stoll(arg["points"]);
  params.views = std::stoi(arg["views"]);
  params.noise = std::stod(arg["noise"]);
  params.outliers = std::stod(arg["outliers"]);
  params.normals = arg["normals"] == "1";
  meshseg::PipelineParams pipeline;
  pipeline.reconstruct.leave_unsupported_open = arg["open"] == "1";
  std::printf("%d views, range noise %g spacings, outliers %g\n", params.views, params.noise,
              params.outliers);
  std::printf("%-14s %4s %7s %5s %7s %8s %5s %5s %5s %9s %8s %7s\n", "part", "seed", "points",
              "seen%", "unlab%", "point%", "w<1", "w1-3", "w>=3", "typed", "regions", "time s");
  int runs = 0, met = 0;
  double worst = 1.0;
  std::string summary;
  for (const std::string& part : Split(arg["parts"])) {
    int part_runs = 0, part_accurate = 0, part_typed = 0;
    double part_worst = 1.0, part_sum = 0.0;
    std::map<std::string, int> untyped;
    for (const std::string& seed : Split(arg["seeds"])) {
      const Row row =
          OneScan(part, std::stoull(seed), params, pipeline, arg["dir"], arg["verbose"] == "1");
      ++runs;
      ++part_runs;
      const double accuracy = row.ok ? row.accuracy : 0.0;
      worst = std::min(worst, accuracy);
      part_worst = std::min(part_worst, accuracy);
      part_sum += accuracy;
      part_accurate += accuracy >= 0.95;
      part_typed += row.ok && row.typed == row.surfaces;
      met += row.ok && row.accuracy >= 0.95 && row.typed == row.surfaces;
      for (const std::string& name : row.untyped) ++untyped[name];
    }
    char buf[256];
    std::snprintf(buf, sizeof buf, "%-14s %5.2f %5.2f %5d/%-3d %5d/%-3d", part.c_str(),
                  100.0 * part_sum / std::max(1, part_runs), 100.0 * part_worst, part_accurate,
                  part_runs, part_typed, part_runs);
    summary += buf;
    for (const auto& [name, count] : untyped) summary += " " + name + " x" + std::to_string(count);
    summary += "\n";
  }
  std::printf("\n%-14s %5s %5s %9s %9s %s\n%s", "part", "mean%", "worst", ">=95%", "typed",
              "surfaces not of their type (scans)", summary.c_str());
  std::printf(
      "%d of %d scans meet both bars (>= 95 %% of points, every surface typed); worst "
      "point accuracy %.2f %%\n",
      met, runs, 100.0 * worst);
  return 0;
}
