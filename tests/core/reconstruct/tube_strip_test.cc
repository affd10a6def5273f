#include "reconstruct/tube_strip.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace meshseg::reconstruct_internal {
namespace {

// Two planar bands facing −z: radius 30 to 31 and 9 to 10, with `outer` and
// `inner` vertices round them, leaving the annulus 10 < ρ < 30 open. The
// loops at ρ = 30 and ρ = 10 are returned in the order of their borders.
struct Bands {
  HoleMesh sm;
  std::vector<HoleMesh::Vertex_index> outer_loop, inner_loop;
};

void AddBand(double r0, double r1, int count, HoleMesh* sm) {
  std::vector<HoleMesh::Vertex_index> a, b;
  for (int i = 0; i < count; ++i) {
    const double u = 2 * M_PI * i / count;
    a.push_back(sm->add_vertex(HoleKernel::Point_3(r0 * std::cos(u), r0 * std::sin(u), 0.0)));
    b.push_back(sm->add_vertex(HoleKernel::Point_3(r1 * std::cos(u), r1 * std::sin(u), 0.0)));
  }
  for (int i = 0; i < count; ++i) {
    const int j = (i + 1) % count;
    sm->add_face(a[i], a[j], b[j]);
    sm->add_face(a[i], b[j], b[i]);
  }
}

std::vector<HoleMesh::Vertex_index> BorderAt(const HoleMesh& sm, double radius) {
  for (const auto h : sm.halfedges()) {
    const auto& p = sm.point(sm.target(h));
    if (!sm.is_border(h) || std::abs(std::hypot(p.x(), p.y()) - radius) > 1e-9) continue;
    std::vector<HoleMesh::Vertex_index> loop;
    for (auto g = h;;) {
      loop.push_back(sm.target(g));
      g = sm.next(g);
      if (g == h) return loop;
    }
  }
  return {};
}

Bands MakeBands() {
  Bands out;
  AddBand(30.0, 31.0, 300, &out.sm);  // spacing 0.63
  AddBand(9.0, 10.0, 100, &out.sm);   // spacing 0.63
  out.outer_loop = BorderAt(out.sm, 30.0);
  out.inner_loop = BorderAt(out.sm, 10.0);
  // The inner side runs against its border, from the vertex nearest the
  // outer side's first.
  std::reverse(out.inner_loop.begin(), out.inner_loop.end());
  const size_t first =
      Nearest(Points(out.sm, out.inner_loop), PointOf(out.sm, out.outer_loop[0]));
  std::rotate(out.inner_loop.begin(), out.inner_loop.begin() + first, out.inner_loop.end());
  return out;
}

// Faces of an equilateral mesh of edge `edge` over `area`.
double EquilateralFaces(double area, double edge) {
  return area / (std::sqrt(3.0) / 4.0 * edge * edge);
}

double ShortestEdge(const HoleMesh& sm, const std::vector<HoleMesh::Face_index>& faces) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto f : faces) {
    for (const auto h : CGAL::halfedges_around_face(sm.halfedge(f), sm)) {
      shortest = std::min(shortest, (PointOf(sm, sm.target(h)) - PointOf(sm, sm.source(h))).norm());
    }
  }
  return shortest;
}

// The annulus between circles of 300 and 100 vertices (3 : 1, as the rim
// round a face and the bore opening onto it): the rungs of the shortest
// strip fan in three to one onto the inner circle. As contours the strip
// closes the annulus (a planar annulus with the bands, its two outer loops
// left) no denser than an equilateral mesh of the loops' edge (measured
// 0.87 of its face count) and with no edge under a quarter of it (measured
// shortest: the edge itself). Rows taken along the rungs instead (a mean
// edge apart on each) crowd the fan: 1.71 times the faces, edges down to
// 0.03 of the mean near the inner circle.
TEST(AddContourStrip, AStripFanningOntoAShorterLoopIsNoDenserThanTheMesh) {
  Bands bands = MakeBands();
  const std::vector<Eigen::Vector3d> pa = Points(bands.sm, bands.outer_loop);
  const std::vector<Eigen::Vector3d> pb = Points(bands.sm, bands.inner_loop);
  const double edge = MeanEdge(pa, pb);
  const double area = M_PI * (30.0 * 30.0 - 10.0 * 10.0);
  Added added;
  ASSERT_TRUE(
      AddContourStrip(bands.outer_loop, pa, bands.inner_loop, pb, edge, &bands.sm, &added));
  EXPECT_TRUE(bands.sm.is_valid());
  int borders = 0;
  std::vector<uint8_t> walked(bands.sm.num_halfedges(), 0);
  for (const auto h : bands.sm.halfedges()) {
    if (!bands.sm.is_border(h) || walked[h]) continue;
    ++borders;
    for (auto g = h; !walked[g]; g = bands.sm.next(g)) walked[g] = 1;
  }
  EXPECT_EQ(borders, 2);  // ρ = 31 and ρ = 9
  double strip_area = 0.0;
  for (const auto f : added.faces) {
    const auto h = bands.sm.halfedge(f);
    const Eigen::Vector3d a = PointOf(bands.sm, bands.sm.source(h));
    const Eigen::Vector3d b = PointOf(bands.sm, bands.sm.target(h));
    const Eigen::Vector3d c = PointOf(bands.sm, bands.sm.target(bands.sm.next(h)));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    EXPECT_LT(n.z(), 0.0);  // facing as the bands do, none folded over
    strip_area += 0.5 * n.norm();
  }
  EXPECT_NEAR(strip_area, area, 0.01 * area);  // the polygons' sag aside
  EXPECT_LT(static_cast<double>(added.faces.size()), EquilateralFaces(area, edge));
  EXPECT_GT(ShortestEdge(bands.sm, added.faces), 0.25 * edge);

  // Rows along the rungs, a mean edge apart on each: the fan crowds.
  Bands rows = MakeBands();
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pa, pb);
  std::vector<int> per_rung;
  for (size_t r = 0; r + 1 < strip.size(); ++r) {
    const double length = (pb[strip[r].second % pb.size()] - pa[strip[r].first % pa.size()]).norm();
    per_rung.push_back(static_cast<int>(std::ceil(length / edge)));
  }
  const auto at = [&](size_t r, double t) {
    const Eigen::Vector3d& p = pa[strip[r].first % pa.size()];
    return Eigen::Vector3d(p + t * (pb[strip[r].second % pb.size()] - p));
  };
  Added crowded;
  ASSERT_TRUE(AddStrip(rows.outer_loop, rows.inner_loop, strip, at, per_rung, &rows.sm, &crowded));
  EXPECT_GT(static_cast<double>(crowded.faces.size()), 1.5 * EquilateralFaces(area, edge));
  EXPECT_LT(ShortestEdge(rows.sm, crowded.faces), 0.1 * edge);
}

}  // namespace
}  // namespace meshseg::reconstruct_internal
