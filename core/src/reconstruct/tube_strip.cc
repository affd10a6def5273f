#include "reconstruct/tube_strip.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <CGAL/boost/graph/Euler_operations.h>

#include "reconstruct/seen_planes.h"

namespace meshseg::reconstruct_internal {

using Kernel = HoleKernel;
using Sm = HoleMesh;

Eigen::Vector3d PointOf(const Sm& sm, Sm::Vertex_index v) {
  const auto& p = sm.point(v);
  return {p.x(), p.y(), p.z()};
}

std::vector<Eigen::Vector3d> Points(const Sm& sm, const std::vector<Sm::Vertex_index>& loop) {
  std::vector<Eigen::Vector3d> p;
  for (const auto v : loop) p.push_back(PointOf(sm, v));
  return p;
}

double MeanEdge(const std::vector<Eigen::Vector3d>& pa, const std::vector<Eigen::Vector3d>& pb) {
  return (LoopPerimeter(pa) + LoopPerimeter(pb)) / static_cast<double>(pa.size() + pb.size());
}

size_t Nearest(const std::vector<Eigen::Vector3d>& p, const Eigen::Vector3d& q) {
  size_t nearest = 0;
  for (size_t j = 1; j < p.size(); ++j) {
    if ((p[j] - q).squaredNorm() < (p[nearest] - q).squaredNorm()) nearest = j;
  }
  return nearest;
}

std::vector<std::pair<size_t, size_t>> ShortestStrip(const std::vector<Eigen::Vector3d>& a,
                                                     const std::vector<Eigen::Vector3d>& b) {
  const size_t m = a.size(), n = b.size();
  const auto at = [n](size_t i, size_t j) { return i * (n + 1) + j; };
  std::vector<double> cost((m + 1) * (n + 1), std::numeric_limits<double>::infinity());
  cost[0] = 0.0;
  for (size_t i = 0; i <= m; ++i) {
    for (size_t j = 0; j <= n; ++j) {
      if (i == 0 && j == 0) continue;
      const double rung = (a[i % m] - b[j % n]).norm();
      double best = std::numeric_limits<double>::infinity();
      if (i > 0) best = cost[at(i - 1, j)];
      if (j > 0) best = std::min(best, cost[at(i, j - 1)]);
      cost[at(i, j)] = best + rung;
    }
  }
  std::vector<std::pair<size_t, size_t>> path{{m, n}};
  for (size_t i = m, j = n; i > 0 || j > 0;) {
    if (j == 0 || (i > 0 && cost[at(i - 1, j)] <= cost[at(i, j - 1)])) {
      --i;
    } else {
      --j;
    }
    path.emplace_back(i, j);
  }
  std::reverse(path.begin(), path.end());
  return path;
}

void TakeBack(const Added& added, Sm* sm) {
  for (auto f = added.faces.rbegin(); f != added.faces.rend(); ++f) {
    CGAL::Euler::remove_face(sm->halfedge(*f), *sm);
  }
  for (const auto v : added.vertices) {
    if (!sm->is_removed(v)) sm->remove_vertex(v);
  }
}

bool AddStrip(const std::vector<Sm::Vertex_index>& side_a,
              const std::vector<Sm::Vertex_index>& side_b,
              const std::vector<std::pair<size_t, size_t>>& strip,
              const std::function<Eigen::Vector3d(size_t, double)>& at,
              const std::vector<int>& rows, Sm* sm, Added* added) {
  const size_t m = side_a.size(), n = side_b.size(), rungs = strip.size() - 1;
  std::vector<size_t> first(rungs);
  for (size_t r = 0; r < rungs; ++r) {
    first[r] = added->vertices.size();
    for (int k = 1; k < rows[r]; ++k) {
      const Eigen::Vector3d p = at(r, static_cast<double>(k) / rows[r]);
      added->vertices.push_back(sm->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    }
  }
  const auto vertex = [&](size_t r, int k) {
    r %= rungs;
    if (k == 0) return side_a[strip[r].first % m];
    if (k == rows[r]) return side_b[strip[r].second % n];
    return added->vertices[first[r] + k - 1];
  };
  bool ok = true;
  const auto add = [&](Sm::Vertex_index u, Sm::Vertex_index v, Sm::Vertex_index w) {
    if (!ok || u == v || v == w || w == u) return;
    const auto f = sm->add_face(u, v, w);
    if (f == Sm::null_face()) {
      ok = false;
    } else {
      added->faces.push_back(f);
    }
  };
  for (size_t r = 0; r < rungs && ok; ++r) {
    const int here = rows[r], next = rows[(r + 1) % rungs];
    for (int i = 0, j = 0; i < here || j < next;) {
      if (j == next || (i < here && (i + 1) * next < (j + 1) * here)) {
        add(vertex(r, i), vertex(r + 1, j), vertex(r, i + 1));
        ++i;
      } else {
        add(vertex(r, i), vertex(r + 1, j), vertex(r + 1, j + 1));
        ++j;
      }
    }
  }
  return ok;
}

namespace {

// `count` points evenly spaced by arc length round the closed polygon `q`,
// the first at q[0].
std::vector<Eigen::Vector3d> Resampled(const std::vector<Eigen::Vector3d>& q, size_t count) {
  const double perimeter = LoopPerimeter(q);
  std::vector<Eigen::Vector3d> out;
  double walked = 0.0;  // length of q before segment k
  size_t k = 0;
  for (size_t i = 0; i < count; ++i) {
    const double at = perimeter * static_cast<double>(i) / static_cast<double>(count);
    double length = (q[(k + 1) % q.size()] - q[k]).norm();
    while (k + 1 < q.size() && walked + length < at) {
      walked += length;
      ++k;
      length = (q[(k + 1) % q.size()] - q[k]).norm();
    }
    const double t = length > 0 ? std::clamp((at - walked) / length, 0.0, 1.0) : 0.0;
    out.push_back(q[k] + t * (q[(k + 1) % q.size()] - q[k]));
  }
  return out;
}

}  // namespace

bool AddContourStrip(const std::vector<Sm::Vertex_index>& side_a,
                     const std::vector<Eigen::Vector3d>& pa,
                     const std::vector<Sm::Vertex_index>& side_b,
                     const std::vector<Eigen::Vector3d>& pb, double edge, Sm* sm, Added* added) {
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pa, pb);
  const size_t rungs = strip.size() - 1;  // the last is the first again
  double mean = 0.0;
  for (size_t r = 0; r < rungs; ++r) {
    mean += (pb[strip[r].second % pb.size()] - pa[strip[r].first % pa.size()]).norm();
  }
  mean /= static_cast<double>(rungs);
  const auto straight = [&](size_t r, double t) {
    const Eigen::Vector3d& p = pa[strip[r].first % pa.size()];
    return Eigen::Vector3d(p + t * (pb[strip[r].second % pb.size()] - p));
  };
  const int steps = std::clamp(static_cast<int>(std::ceil(mean / edge)), 1, kMaxRows);
  return AddContourStrip(side_a, pa, side_b, pb, strip, straight, steps, edge, sm, added);
}

bool AddContourStrip(const std::vector<Sm::Vertex_index>& side_a,
                     const std::vector<Eigen::Vector3d>& pa,
                     const std::vector<Sm::Vertex_index>& side_b,
                     const std::vector<Eigen::Vector3d>& pb,
                     const std::vector<std::pair<size_t, size_t>>& strip,
                     const std::function<Eigen::Vector3d(size_t, double)>& at, int steps,
                     double edge, Sm* sm, Added* added) {
  const size_t rungs = strip.size() - 1;
  std::vector<Sm::Vertex_index> side = side_a;
  std::vector<Eigen::Vector3d> points = pa;
  for (int k = 1; k <= steps; ++k) {
    std::vector<Sm::Vertex_index> ring = side_b;
    std::vector<Eigen::Vector3d> on_ring = pb;
    if (k < steps) {
      std::vector<Eigen::Vector3d> along;
      for (size_t r = 0; r < rungs; ++r) along.push_back(at(r, static_cast<double>(k) / steps));
      const auto count = static_cast<size_t>(
          std::max(3.0, std::round(LoopPerimeter(along) / edge)));
      on_ring = Resampled(along, count);
      ring.clear();
      for (const Eigen::Vector3d& p : on_ring) {
        ring.push_back(sm->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
        added->vertices.push_back(ring.back());
      }
    }
    const std::vector<std::pair<size_t, size_t>> between = ShortestStrip(points, on_ring);
    const auto unused = [](size_t, double) { return Eigen::Vector3d(Eigen::Vector3d::Zero()); };
    if (!AddStrip(side, ring, between, unused, std::vector<int>(between.size() - 1, 1), sm,
                  added)) {
      return false;
    }
    side = std::move(ring);
    points = std::move(on_ring);
  }
  return true;
}

}  // namespace meshseg::reconstruct_internal
