// The peer reconstruction issue 38 measures ours against: CGAL 5.5's Poisson
// surface reconstruction (Kazhdan et al. 2006, CGAL's
// poisson_surface_reconstruction_delaunay) with jet-fitted normals oriented
// along a minimum spanning tree (Hoppe et al. 1992), as CGAL's own example
// runs it. Bench only: never linked into the product.
//   build/bin/poisson_peer CLOUD.xyz OUT.ply [--given-normals] [--neighbors K]
// Prints the time of each step and the process's peak memory.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/poisson_surface_reconstruction.h>
#include <CGAL/property_map.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "bench/peak_rss.h"
#include "meshseg/point_cloud.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Pwn = std::pair<Point, Vector>;
using PointMap = CGAL::First_of_pair_property_map<Pwn>;
using NormalMap = CGAL::Second_of_pair_property_map<Pwn>;

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

int Fail(const std::string& message) {
  std::fprintf(stderr, "poisson_peer: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return Fail("usage: poisson_peer CLOUD OUT.ply [--given-normals] [--neighbors K]");
  bool given_normals = false;
  int neighbors = 18;  // CGAL's example uses 18 for jet normals and MST
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--given-normals") {
      given_normals = true;
    } else if (arg == "--neighbors" && i + 1 < argc) {
      neighbors = std::atoi(argv[++i]);
    } else {
      return Fail("unknown argument " + arg);
    }
  }
  const auto read = meshseg::ReadPointCloud(argv[1]);
  if (!read.ok()) return Fail(std::string(read.status().message()));
  if (given_normals && !read->has_normals()) return Fail("--given-normals: the cloud has none");
  std::vector<Pwn> points;
  points.reserve(read->points.size());
  for (size_t i = 0; i < read->points.size(); ++i) {
    const auto& p = read->points[i];
    const Eigen::Vector3d n = given_normals ? read->normals[i] : Eigen::Vector3d::Zero();
    points.emplace_back(Point(p.x(), p.y(), p.z()), Vector(n.x(), n.y(), n.z()));
  }
  const auto start = std::chrono::steady_clock::now();
  const auto params = CGAL::parameters::point_map(PointMap()).normal_map(NormalMap());
  if (!given_normals) {
    CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(points, neighbors, params);
    const auto unoriented = CGAL::mst_orient_normals(points, neighbors, params);
    std::printf("normals: %.2f s, %td of %zu points left unoriented and dropped\n", Seconds(start),
                std::distance(unoriented, points.end()), points.size());
    points.erase(unoriented, points.end());
  }
  const double spacing = CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
      points, 6, CGAL::parameters::point_map(PointMap()));
  CGAL::Surface_mesh<Point> output;
  if (!CGAL::poisson_surface_reconstruction_delaunay(points.begin(), points.end(), PointMap(),
                                                     NormalMap(), output, spacing)) {
    return Fail("poisson_surface_reconstruction_delaunay failed");
  }
  const double total = Seconds(start);
  // Written as CGAL made it, so the evaluation sees any open or non-manifold edge.
  if (!CGAL::IO::write_polygon_mesh(argv[2], output, CGAL::parameters::stream_precision(17))) {
    return Fail(std::string("cannot write ") + argv[2]);
  }
  std::printf("wrote %s: %zu faces, %.2f s, peak %.0f MB\n", argv[2],
              static_cast<size_t>(output.number_of_faces()), total, meshseg::bench::PeakRssMiB());
  return 0;
}
