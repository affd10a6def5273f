#include "segment/segment_internal.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Below this many vertices a filter runs on the calling thread (a parallel
// loop costs more than it saves).
constexpr std::size_t kParallelFilter = 4096;

// A third of the area of every face around each vertex.
std::vector<double> VertexAreas(const TriMesh& mesh) {
  std::vector<double> area(mesh.n_vertices(), 0.0);
  for (const auto fh : mesh.faces()) {
    const double third = mesh.calc_face_area(fh) / 3.0;
    for (auto it = mesh.cfv_iter(fh); it.is_valid(); ++it) area[it->idx()] += third;
  }
  return area;
}

// True if `torus` is a spindle torus (tube radius above the major radius)
// and some of `points` lie within r - R of its axis, where its two sheets
// meet in a cusp. Such a fit bends a flat disc with a small step to its rim
// (a plane annulus with the first rows of the convex round along its outer
// rim: R 6.5, r 88); no machined surface has that shape.
bool ReachesSpindleCusp(const Torus& torus, std::span<const Eigen::Vector3d> points) {
  const double inner = torus.minor_radius - torus.major_radius;
  if (!(inner > 0.0)) return false;
  return std::any_of(points.begin(), points.end(), [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - torus.center;
    return (d - d.dot(torus.axis_direction) * torus.axis_direction).norm() < inner;
  });
}

}  // namespace

SegmentContext MakeSegmentContext(const TriMesh& mesh, const CurvatureField& curvature,
                                  const SegmentEstimates& estimates, double alpha,
                                  const RunContext& run) {
  SegmentContext c;
  // Both read only the mesh, each in its own order: made side by side, the
  // same values.
  tbb::parallel_invoke([&] { c.graph = BuildVertexGraph(mesh); },
                       [&] { c.vertex_area = VertexAreas(mesh); });
  c.curvature = &curvature;
  c.mean_edge_length = estimates.mean_edge_length;
  c.noise_sigma = estimates.noise_sigma;
  c.tolerance.distance = estimates.distance_tolerance;
  c.tolerance.cos_angle = std::cos(estimates.angle_tolerance_deg * kPi / 180.0);
  c.angle_tolerance_deg = estimates.angle_tolerance_deg;
  c.alpha = alpha;
  c.run = &run;
  return c;
}

std::vector<int> Sample(std::span<const int> vertices, std::size_t max_count) {
  if (vertices.size() <= max_count) return {vertices.begin(), vertices.end()};
  const std::size_t stride = (vertices.size() + max_count - 1) / max_count;
  std::vector<int> out;
  out.reserve(vertices.size() / stride + 1);
  for (std::size_t k = 0; k < vertices.size(); k += stride) out.push_back(vertices[k]);
  return out;
}

std::size_t MeasuredCount(const SegmentContext& c, std::span<const int> vertices) {
  if (c.measured.empty()) return vertices.size();
  return static_cast<std::size_t>(
      std::count_if(vertices.begin(), vertices.end(), [&](int v) { return c.measured[v] != 0; }));
}

std::vector<int> MeasuredVertices(const SegmentContext& c, std::span<const int> vertices) {
  std::vector<int> out;
  out.reserve(vertices.size());
  for (const int v : vertices) {
    if (c.Measured(v)) out.push_back(v);
  }
  return out;
}

FitResult FitType(const SegmentContext& c, SurfaceType type, std::span<const int> vertices) {
  std::vector<int> measured;
  if (!c.measured.empty()) {
    measured = MeasuredVertices(c, vertices);
    if (!measured.empty()) vertices = measured;
  }
  const std::vector<int> sample = Sample(vertices);
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> weights;
  points.reserve(sample.size());
  normals.reserve(sample.size());
  weights.reserve(sample.size());
  for (const int v : sample) {
    points.push_back(c.position(v));
    normals.push_back(c.curvature->smooth_normal[v]);
    weights.push_back(c.vertex_area[v] + 1e-12);
  }
  FitResult fit = FitOfType(type, {.points = points, .normals = normals, .weights = weights});
  if (const auto* torus = std::get_if<Torus>(&fit.surface);
      torus != nullptr && fit.ok() && ReachesSpindleCusp(*torus, points)) {
    fit.valid = false;
  }
  return fit;
}

double FitFraction(const SegmentContext& c, const Surface& surface, std::span<const int> vertices,
                   const Tolerance& tol) {
  // The alpha test asks how much of the evidence the surface explains: the
  // measured vertices (FitType).
  std::vector<int> measured;
  if (!c.measured.empty()) {
    measured = MeasuredVertices(c, vertices);
    if (!measured.empty()) vertices = measured;
  }
  const std::vector<int> sample = Sample(vertices);
  if (sample.empty()) return 0.0;
  std::size_t fit = 0;
  for (const int v : sample) {
    if (Fits(c, v, ProjectVertex(c, surface, v), tol)) ++fit;
  }
  return static_cast<double>(fit) / sample.size();
}

std::vector<int> FittingVertices(const SegmentContext& c, const Surface& surface,
                                 std::span<const int> vertices) {
  const auto fits = [&](int v) { return Fits(c, v, ProjectVertex(c, surface, v), c.tolerance); };
  std::vector<int> out;
  if (vertices.size() < kParallelFilter) {
    for (const int v : vertices) {
      if (fits(v)) out.push_back(v);
    }
    return out;
  }
  // Each vertex's test on its own (it reads only the surface and the
  // vertex), then the fitting ones kept in order: the same list.
  std::vector<uint8_t> keep(vertices.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) keep[k] = fits(vertices[k]);
                    });
  out.reserve(static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1)));
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    if (keep[k]) out.push_back(vertices[k]);
  }
  return out;
}

std::vector<int> PieceHoldingSeed(const SegmentContext& c, std::span<const int> vertices,
                                  std::span<const int> seed) {
  // piece[v]: -1 in the set (or the seed) and not reached yet. The seed is
  // walked over too: the fit's vertices around it are one piece with it
  // even where noise leaves them apart from each other.
  std::unordered_map<int, int> piece;
  for (const int v : vertices) piece[v] = -1;
  for (const int v : seed) piece[v] = -1;
  // Walks from x over the set, and over up to kPieceBridge vertices outside
  // it: a vertex the fit misses by noise does not cut the piece.
  std::vector<std::pair<int, int>> stack;  // vertex, steps outside the set
  std::unordered_map<int, int> outside;    // vertex outside -> fewest steps
  int pieces = 0;
  for (const std::span<const int> start : {vertices, seed}) {
    for (const int v : start) {
      if (piece[v] != -1) continue;
      piece[v] = pieces;
      stack.assign(1, {v, 0});
      outside.clear();
      while (!stack.empty()) {
        const auto [x, steps] = stack.back();
        stack.pop_back();
        for (const int y : c.graph.Neighbors(x)) {
          const auto it = piece.find(y);
          if (it != piece.end()) {
            if (it->second != -1) continue;
            it->second = pieces;
            stack.push_back({y, 0});
          } else if (steps < kPieceBridge) {
            const auto [o, fresh] = outside.try_emplace(y, steps + 1);
            if (!fresh && o->second <= steps + 1) continue;
            o->second = steps + 1;
            stack.push_back({y, steps + 1});
          }
        }
      }
      ++pieces;
    }
  }
  if (pieces <= 1) return {vertices.begin(), vertices.end()};
  std::vector<int> held(pieces, 0);
  for (const int v : seed) ++held[piece[v]];
  const int best = static_cast<int>(std::max_element(held.begin(), held.end()) - held.begin());
  std::vector<int> out;
  for (const int v : vertices) {
    if (piece[v] == best) out.push_back(v);
  }
  return out;
}

double SquaredDistances(const SegmentContext& c, const Surface& surface,
                        std::span<const int> vertices) {
  double sum = 0.0;
  for (const int v : vertices) {
    const double d = ProjectVertex(c, surface, v).distance;
    sum += d * d;
  }
  return sum;
}

bool CurvedField(const SegmentContext& c, std::span<const int> vertices) {
  if (vertices.empty()) return false;
  int positive = 0;
  Eigen::Matrix3d directions = Eigen::Matrix3d::Zero();
  for (const int v : vertices) {
    positive += c.curvature->kappa_max[v] > 0.0;
    const Eigen::Vector3d& d = c.curvature->dir_max[v];
    directions.noalias() += d * d.transpose();
  }
  const double n = static_cast<double>(vertices.size());
  const double sign_share = std::max(positive, static_cast<int>(vertices.size()) - positive) / n;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(directions / n,
                                                             Eigen::EigenvaluesOnly);
  return sign_share >= kCurvedSignShare && eigen.eigenvalues()(2) >= kCurvedDirection;
}

void RebuildVertexLists(const std::vector<int>& labels, std::vector<RegionState>* regions) {
  for (RegionState& r : *regions) r.vertices.clear();
  for (std::size_t v = 0; v < labels.size(); ++v) {
    if (labels[v] >= 0) (*regions)[labels[v]].vertices.push_back(static_cast<int>(v));
  }
}

std::vector<int> RegionsAround(const SegmentContext& c, const std::vector<int>& labels,
                               const std::vector<RegionState>& regions, int id) {
  std::vector<int> out;
  for (const int v : regions[id].vertices) {
    for (const int u : c.graph.Neighbors(v)) {
      if (labels[u] >= 0 && labels[u] != id) out.push_back(labels[u]);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

int ReleaseRegions(const std::function<bool(int id, const RegionState& r)>& release,
                   std::vector<int>* labels, std::vector<RegionState>* regions) {
  std::vector<int> ids;
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    if ((*regions)[id].alive && release(id, (*regions)[id])) ids.push_back(id);
  }
  for (const int id : ids) {
    RegionState& r = (*regions)[id];
    for (const int v : r.vertices) (*labels)[v] = -1;
    r.vertices.clear();
    r.alive = false;
  }
  return static_cast<int>(ids.size());
}

void MergeInto(int into, int from, std::vector<int>* labels, std::vector<RegionState>* regions) {
  RegionState& a = (*regions)[into];
  RegionState& b = (*regions)[from];
  for (const int v : b.vertices) (*labels)[v] = into;
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  std::sort(a.vertices.begin(), a.vertices.end());
  b.vertices.clear();
  b.alive = false;
}

}  // namespace meshseg::segment_internal
