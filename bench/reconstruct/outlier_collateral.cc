// Outlier flags of Reconstruct() (reconstruct/outliers.h) against the truth
// of generated scans: genuine points discarded (collateral) and outliers
// kept, per part and draw. Outliers within 2 h of a genuine point lie in the
// scan's own noise band and are counted apart.
//   build/bin/outlier_collateral [points=20000] [outliers=0.05] [noise=0.1]
//                                [seeds=3] [normals=0] [parts=a,b,...]
//   build/bin/outlier_collateral cloud=FILE   (flagged fraction of a cloud)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/point_index.h"
#include "meshseg/generate.h"
#include "meshseg/point_cloud.h"
#include "meshseg/reconstruct.h"
#include "reconstruct/outliers.h"

namespace {

using meshseg::mesh_internal::PointIndex;
namespace ri = meshseg::reconstruct_internal;

struct Flagged {
  ri::Outliers outliers;
  double h = 0.0;
};

// The flags Reconstruct() computes with default parameters.
Flagged Flag(const meshseg::PointCloud& cloud) {
  const PointIndex index(cloud.points);
  Flagged f;
  f.outliers = ri::OutliersOfCloud(cloud.points, cloud.normals, index, {});
  f.h = f.outliers.spacing;
  return f;
}

int OneCloud(const std::string& path) {
  const auto cloud = meshseg::ReadPointCloud(path);
  if (!cloud.ok()) {
    std::fprintf(stderr, "outlier_collateral: %s\n", std::string(cloud.status().message()).c_str());
    return 1;
  }
  const Flagged f = Flag(*cloud);
  const auto count = std::count(f.outliers.flags.begin(), f.outliers.flags.end(), 1);
  std::printf("%s: %zu points, flagged %ld (%.2f %%); h %.4g, noise %.3g h, band %.3g h\n",
              path.c_str(), cloud->points.size(), static_cast<long>(count),
              100.0 * static_cast<double>(count) / static_cast<double>(cloud->points.size()), f.h,
              f.outliers.noise / f.h, f.outliers.band / f.h);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> arg = {
      {"points", "20000"}, {"outliers", "0.05"}, {"noise", "0.1"}, {"seeds", "3"},
      {"normals", "0"},    {"parts", ""},        {"cloud", ""}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const size_t eq = a.find('=');
    if (eq == std::string::npos || !arg.count(a.substr(0, eq))) {
      std::fprintf(stderr, "outlier_collateral: unknown argument %s\n", a.c_str());
      return 1;
    }
    arg[a.substr(0, eq)] = a.substr(eq + 1);
  }
  if (!arg["cloud"].empty()) return OneCloud(arg["cloud"]);
  std::vector<std::string> parts;
  if (arg["parts"].empty()) {
    parts = meshseg::PartNames();
    std::erase(parts, "test_piece_large");
  } else {
    std::stringstream ss(arg["parts"]);
    for (std::string p; std::getline(ss, p, ',');) parts.push_back(p);
  }
  double worst = 0.0, worst_far_kept = 0.0;
  for (const std::string& part : parts) {
    for (int seed = 1; seed <= std::atoi(arg["seeds"].c_str()); ++seed) {
      meshseg::ScanParams sp;
      sp.points = std::atoll(arg["points"].c_str());
      sp.outliers = std::atof(arg["outliers"].c_str());
      sp.noise = std::atof(arg["noise"].c_str());
      sp.normals = arg["normals"] != "0";
      sp.seed = static_cast<uint64_t>(seed);
      const auto scan = meshseg::ScanPart(part, sp);
      if (!scan.ok()) {
        std::fprintf(stderr, "%s\n", std::string(scan.status().message()).c_str());
        return 1;
      }
      const auto& pts = scan->cloud.points;
      const Flagged f = Flag(scan->cloud);
      const std::vector<uint8_t>& flags = f.outliers.flags;
      std::vector<Eigen::Vector3d> genuine;
      for (size_t i = 0; i < pts.size(); ++i) {
        if (!scan->is_outlier[i]) genuine.push_back(pts[i]);
      }
      const PointIndex genuine_index(genuine);
      int64_t n_gen = 0, discarded = 0, n_far = 0, kept_far = 0, n_near = 0, kept_near = 0;
      double farthest_kept = 0.0;
      for (size_t i = 0; i < pts.size(); ++i) {
        if (!scan->is_outlier[i]) {
          ++n_gen;
          discarded += flags[i];
          continue;
        }
        const double d = (genuine[genuine_index.Closest(pts[i])] - pts[i]).norm() / f.h;
        if (d > 2.0) {
          ++n_far;
          kept_far += !flags[i];
          if (!flags[i]) farthest_kept = std::max(farthest_kept, d);
        } else {
          ++n_near;
          kept_near += !flags[i];
        }
      }
      const double collateral = 100.0 * static_cast<double>(discarded) / static_cast<double>(n_gen);
      worst = std::max(worst, collateral);
      const double far_kept =
          n_far ? 100.0 * static_cast<double>(kept_far) / static_cast<double>(n_far) : 0.0;
      worst_far_kept = std::max(worst_far_kept, far_kept);
      std::printf(
          "%-14s seed %d: h %.4g, noise %.3g h, band %.3g h; genuine discarded %.2f %%; "
          "outliers > 2 h off kept %lld of %lld (farthest %.1f h), within 2 h kept %lld of %lld\n",
          part.c_str(), seed, f.h, f.outliers.noise / f.h, f.outliers.band / f.h, collateral,
          static_cast<long long>(kept_far), static_cast<long long>(n_far), farthest_kept,
          static_cast<long long>(kept_near), static_cast<long long>(n_near));
    }
  }
  std::printf("worst: genuine discarded %.2f %%, outliers > 2 h off kept %.2f %%\n", worst,
              worst_far_kept);
  return 0;
}
