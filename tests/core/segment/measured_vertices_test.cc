// Unmeasured vertices (SegmentParams::measured): the vertices of a patch
// that closes an unscanned area neither pay nor propose. Their data cost is
// 0 under every label, fits and label costs ignore them, and on a whole
// part a bulging patch on a plane makes no region of its own but takes the
// plane's label; an empty mask segments as every vertex measured.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "meshseg/curvature.h"
#include "meshseg/generate.h"
#include "meshseg/segment.h"
#include "segment/energy.h"
#include "sheet_context.h"

namespace meshseg::segment_internal {
namespace {

using testing::AllVertices;
using testing::BuildFlatSide;
using testing::Sheet;

// The vertices of the flat side (y = 0, x in [-30, 30], z in [-5, 5]) with
// |x| < 5: a patch of 9 x 11 = 99 of its 671 vertices.
std::vector<int> MiddleOfFlatSide(const Sheet& s) {
  std::vector<int> patch;
  for (int v = 0; v < s.c.vertex_count(); ++v) {
    if (std::abs(s.c.position(v).x()) < 5.0) patch.push_back(v);
  }
  return patch;
}

// Raises `patch` off the side by up to 3 (a parabola over |x| < 5), as a
// faired closing patch may bulge.
void Bulge(Sheet* s, const std::vector<int>& patch) {
  for (const int v : patch) {
    const double x = s->c.position(v).x() / 5.0;
    s->c.graph.positions[v].y() += 3.0 * (1.0 - x * x);
  }
}

// Marks `patch` unmeasured, every other vertex measured.
void Unmeasure(Sheet* s, const std::vector<int>& patch) {
  s->c.measured.assign(s->c.vertex_count(), 1);
  for (const int v : patch) s->c.measured[v] = 0;
}

TEST(UnmeasuredVertex, CostsNothingUnderEveryLabel) {
  Sheet s;
  BuildFlatSide(&s);
  const std::vector<int> patch = MiddleOfFlatSide(s);
  Unmeasure(&s, patch);
  // A plane 1 (over 4 th_dis) off the side: an outlier to every vertex.
  const Surface off = Plane{.point = Eigen::Vector3d(0, 1, 0), .normal = Eigen::Vector3d::UnitY()};
  const int inside = patch.front();
  const int outside = 0;  // a corner, x = -30
  EXPECT_EQ(VertexCost(s.c, inside, off), 0.0);
  EXPECT_EQ(OutlierCost(s.c, inside), 0.0);
  EXPECT_GT(VertexCost(s.c, outside, off), 0.0);
  EXPECT_GT(OutlierCost(s.c, outside), 0.0);
  // The label cost counts the measured vertices only: the patch alone is
  // free, the whole side costs what its 572 measured vertices do.
  const std::vector<int> all = AllVertices(s);
  const RegionState side{.type = SurfaceType::kPlane, .surface = off, .vertices = all};
  const RegionState patch_only{.type = SurfaceType::kPlane, .surface = off, .vertices = patch};
  EXPECT_EQ(MeasuredCount(s.c, all), all.size() - patch.size());
  EXPECT_DOUBLE_EQ(LabelCost(s.c, side), LabelCost(s.c, SurfaceType::kPlane, 572));
  EXPECT_EQ(LabelCost(s.c, patch_only), 0.0);
}

TEST(UnmeasuredVertex, IsNotFitted) {
  Sheet s;
  BuildFlatSide(&s);
  const std::vector<int> patch = MiddleOfFlatSide(s);
  Bulge(&s, patch);
  const std::vector<int> all = AllVertices(s);
  // Measured, the bulge pulls the plane off the side (the premise).
  const FitResult pulled = FitType(s.c, SurfaceType::kPlane, all);
  ASSERT_TRUE(pulled.ok());
  EXPECT_GT(std::abs(std::get<Plane>(pulled.surface).point.y()), 0.1);
  // Unmeasured, the plane is the side's to the rounding.
  Unmeasure(&s, patch);
  const FitResult fit = FitType(s.c, SurfaceType::kPlane, all);
  ASSERT_TRUE(fit.ok());
  for (const int v : all) {
    if (!s.c.Measured(v)) continue;
    EXPECT_NEAR(SignedDistance(fit.surface, s.c.position(v)), 0.0, 1e-9);
  }
}

// The alpha test is on the evidence: a plane region whose patch bulges off
// it, the patch unmeasured, passes it as if the patch were not there.
TEST(UnmeasuredVertex, IsNotCountedByTheAlphaTest) {
  Sheet s;
  BuildFlatSide(&s);
  const std::vector<int> patch = MiddleOfFlatSide(s);
  Bulge(&s, patch);
  const std::vector<int> all = AllVertices(s);
  const Surface side = Plane{.point = Eigen::Vector3d::Zero(), .normal = Eigen::Vector3d::UnitY()};
  // Measured, the bulge's vertices beyond th_dis fail it (the premise).
  EXPECT_LT(FitFraction(s.c, side, all, s.c.tolerance), 0.9);
  Unmeasure(&s, patch);
  EXPECT_EQ(FitFraction(s.c, side, all, s.c.tolerance), 1.0);
}

// `name` at 0.05 h (draw 7) with a bulge on its largest plane: the
// vertices of that primitive within `radius` h of a vertex near its centre
// pushed out along the plane's normal by up to `height` h, smoothly to 0
// at the rim. Returns the bulge's vertices and the plane's primitive id.
struct Bulged {
  GeneratedPart part;
  std::vector<int> patch;
  int plane = -1;
};
Bulged BulgeLargestPlane(const std::string& name, double radius, double height) {
  Bulged b;
  absl::StatusOr<GeneratedPart> part = GeneratePart(name, {.noise = 0.05, .seed = 7});
  EXPECT_TRUE(part.ok()) << part.status();
  if (!part.ok()) return b;
  b.part = *std::move(part);
  const TriMesh& tri = b.part.mesh.tri;
  std::map<int, int> plane_vertices;
  for (std::size_t v = 0; v < b.part.vertex_primitive.size(); ++v) {
    const int p = b.part.vertex_primitive[v];
    if (p >= 0 && std::holds_alternative<Plane>(b.part.primitives[p].surface)) ++plane_vertices[p];
  }
  b.plane = std::max_element(plane_vertices.begin(), plane_vertices.end(), [](auto x, auto y) {
              return x.second < y.second;
            })->first;
  const Plane& plane = std::get<Plane>(b.part.primitives[b.plane].surface);
  // The plane's vertex farthest from its other primitives' vertices: the
  // centre of the largest disc on it.
  std::vector<Eigen::Vector3d> on, off;
  std::vector<int> on_ids;
  for (const auto vh : tri.vertices()) {
    const auto& p = tri.point(vh);
    const Eigen::Vector3d x(p[0], p[1], p[2]);
    if (b.part.vertex_primitive[vh.idx()] == b.plane) {
      on.push_back(x);
      on_ids.push_back(vh.idx());
    } else {
      off.push_back(x);
    }
  }
  double best = -1.0;
  Eigen::Vector3d centre;
  for (std::size_t k = 0; k < on.size(); k += 7) {
    double nearest = HUGE_VAL;
    for (std::size_t j = 0; j < off.size(); j += 3) {
      nearest = std::min(nearest, (on[k] - off[j]).norm());
    }
    if (nearest > best) best = nearest, centre = on[k];
  }
  const double h = b.part.voxel_size;
  EXPECT_GT(best, (radius + 3.0) * h) << "no disc for the bulge on " << name;
  TriMesh& mesh = b.part.mesh.tri;
  for (std::size_t k = 0; k < on.size(); ++k) {
    const double d = (on[k] - centre).norm() / (radius * h);
    if (d >= 1.0) continue;
    const double lift = height * h * (1.0 - d * d) * (1.0 - d * d);
    const Eigen::Vector3d x = on[k] + lift * plane.normal;
    mesh.set_point(TriMesh::VertexHandle(on_ids[k]), TriMesh::Point(x.x(), x.y(), x.z()));
    b.patch.push_back(on_ids[k]);
  }
  return b;
}

// Region ids of `seg` with most of their vertices in `patch`, and the share
// of `patch` labelled `region`.
struct PatchLabels {
  std::vector<int> own_regions;
  double share_in(int region, const std::vector<int>& patch, const Segmentation& seg) const {
    long in = 0;
    for (const int v : patch) in += seg.vertex_labels[v] == region;
    return static_cast<double>(in) / static_cast<double>(patch.size());
  }
};
PatchLabels LabelsOfPatch(const Segmentation& seg, const std::vector<int>& patch) {
  std::map<int, long> in_patch, total;
  for (const int v : patch) ++in_patch[seg.vertex_labels[v]];
  for (const int l : seg.vertex_labels) ++total[l];
  PatchLabels out;
  for (const auto& [l, n] : in_patch) {
    if (l >= 0 && 2 * n > total[l]) out.own_regions.push_back(l);
  }
  return out;
}

// The region most of the plane's vertices outside `patch` are labelled.
int PlaneRegion(const Bulged& b, const Segmentation& seg) {
  std::vector<uint8_t> in_patch(seg.vertex_labels.size(), 0);
  for (const int v : b.patch) in_patch[v] = 1;
  std::map<int, long> count;
  for (std::size_t v = 0; v < seg.vertex_labels.size(); ++v) {
    if (b.part.vertex_primitive[v] == b.plane && !in_patch[v]) ++count[seg.vertex_labels[v]];
  }
  return std::max_element(count.begin(), count.end(), [](auto x, auto y) {
           return x.second < y.second;
         })->first;
}

// A bulge of radius 8 h and height 2 h on stepped_shaft's largest plane
// (beside its cylinders): measured, it is data and makes a region of its
// own (the premise); unmeasured, it makes none and at least 95 % of it
// takes the plane's label, and the segmentation has fewer regions.
TEST(UnmeasuredPatch, MakesNoRegionOfItsOwn) {
  Bulged b = BulgeLargestPlane("stepped_shaft", /*radius=*/8.0, /*height=*/2.0);
  ASSERT_FALSE(b.patch.empty());
  absl::StatusOr<CurvatureField> field = EstimateCurvature(b.part.mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  absl::StatusOr<Segmentation> as_data = Segment(b.part.mesh, *field);
  ASSERT_TRUE(as_data.ok()) << as_data.status();
  EXPECT_FALSE(LabelsOfPatch(*as_data, b.patch).own_regions.empty());

  SegmentParams params;
  params.measured.assign(b.part.mesh.tri.n_vertices(), 1);
  for (const int v : b.patch) params.measured[v] = 0;
  absl::StatusOr<Segmentation> masked = Segment(b.part.mesh, *field, params);
  ASSERT_TRUE(masked.ok()) << masked.status();
  const PatchLabels labels = LabelsOfPatch(*masked, b.patch);
  EXPECT_TRUE(labels.own_regions.empty());
  EXPECT_GE(labels.share_in(PlaneRegion(b, *masked), b.patch, *masked), 0.95);
  EXPECT_LT(masked->regions.size(), as_data->regions.size());
}

// Every vertex measured, given as a full mask or as the empty one, is one
// segmentation.
TEST(MeasuredMask, EmptyIsEveryVertexMeasured) {
  absl::StatusOr<GeneratedPart> part = GeneratePart("small_block", {.noise = 0.05, .seed = 7});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<CurvatureField> field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  absl::StatusOr<Segmentation> empty = Segment(part->mesh, *field);
  SegmentParams params;
  params.measured.assign(part->mesh.tri.n_vertices(), 1);
  absl::StatusOr<Segmentation> full = Segment(part->mesh, *field, params);
  ASSERT_TRUE(empty.ok()) << empty.status();
  ASSERT_TRUE(full.ok()) << full.status();
  EXPECT_EQ(empty->vertex_labels, full->vertex_labels);
  EXPECT_EQ(empty->face_labels, full->face_labels);
  ASSERT_EQ(empty->regions.size(), full->regions.size());
  for (std::size_t r = 0; r < empty->regions.size(); ++r) {
    EXPECT_EQ(empty->regions[r].type, full->regions[r].type);
    EXPECT_EQ(empty->regions[r].rms_distance, full->regions[r].rms_distance);
  }
}

TEST(MeasuredMask, OfTheWrongSizeIsRefused) {
  absl::StatusOr<GeneratedPart> part = GeneratePart("small_block", {.seed = 7});
  ASSERT_TRUE(part.ok()) << part.status();
  absl::StatusOr<CurvatureField> field = EstimateCurvature(part->mesh);
  ASSERT_TRUE(field.ok()) << field.status();
  SegmentParams params;
  params.measured.assign(part->mesh.tri.n_vertices() - 1, 1);
  const absl::StatusOr<Segmentation> seg = Segment(part->mesh, *field, params);
  EXPECT_EQ(seg.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(seg.status().message().find("measured mask"), std::string::npos);
}

}  // namespace
}  // namespace meshseg::segment_internal
