#include "segment/finalize_regions.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "segment/align_coaxial.h"
#include "segment/decide_type.h"
#include "segment/face_labels.h"
#include "segment/tangent_rounds.h"

namespace meshseg::segment_internal {

namespace {

constexpr int kInlierRounds = 2;
constexpr double kMinInlierShare = 0.5;

// Renumbers the regions by first face, derives the missing vertex labels
// from incident faces and measures every region.
Segmentation Assemble(const SegmentContext& c, const TriMesh& mesh,
                      const std::vector<int>& face_old, const std::vector<int>& labels,
                      const std::vector<RegionState>& regions) {
  const int n_regions = static_cast<int>(regions.size());
  std::vector<int> new_id(n_regions, -1);
  Segmentation seg;
  for (const int old : face_old) {
    if (old < 0 || new_id[old] >= 0) continue;
    new_id[old] = static_cast<int>(seg.regions.size());
    Region region;
    region.id = new_id[old];
    region.type = regions[old].type;
    region.surface = regions[old].surface;
    seg.regions.push_back(region);
  }
  // Face areas each on its own (independent), summed per region in face
  // order as before.
  const int n_faces = static_cast<int>(face_old.size());
  std::vector<double> face_area(n_faces, 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n_faces, 8192), [&](const auto& r) {
    for (int f = r.begin(); f < r.end(); ++f) {
      if (face_old[f] >= 0) face_area[f] = mesh.calc_face_area(TriMesh::FaceHandle(f));
    }
  });
  seg.face_labels.resize(face_old.size());
  for (int f = 0; f < n_faces; ++f) {
    const int id = face_old[f] < 0 ? -1 : new_id[face_old[f]];
    seg.face_labels[f] = id;
    if (id < 0) continue;
    seg.regions[id].face_count += 1;
    seg.regions[id].area += face_area[f];
  }
  const int n = c.vertex_count();
  seg.vertex_labels.assign(n, -1);
  for (int v = 0; v < n; ++v) {
    const int old = labels[v];
    if (old >= 0 && new_id[old] >= 0) {
      seg.vertex_labels[v] = new_id[old];
      continue;
    }
    for (auto it = mesh.cvf_iter(TriMesh::VertexHandle(v)); it.is_valid(); ++it) {
      if (seg.face_labels[it->idx()] >= 0) {
        seg.vertex_labels[v] = seg.face_labels[it->idx()];
        break;
      }
    }
  }
  // Geometric distance of every vertex to its region's surface.
  std::vector<double> dist(n, 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 2048), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      const int id = seg.vertex_labels[v];
      if (id >= 0) dist[v] = std::abs(ProjectVertex(c, seg.regions[id].surface, v).distance);
    }
  });
  std::vector<double> sum2(seg.regions.size(), 0.0);
  for (int v = 0; v < n; ++v) {
    const int id = seg.vertex_labels[v];
    if (id < 0) continue;
    Region& region = seg.regions[id];
    region.vertex_count += 1;
    sum2[id] += dist[v] * dist[v];
    region.max_distance = std::max(region.max_distance, dist[v]);
  }
  for (Region& region : seg.regions) {
    if (region.vertex_count > 0) {
      region.rms_distance = std::sqrt(sum2[region.id] / region.vertex_count);
    }
  }
  return seg;
}

// The fit of `type` to a region's `vertices`, refitted on those that meet
// (5) and (6) for it while they are at least kMinInlierShare of the region.
// Leftover absorption can hand a region vertices of a small face it could
// not tell apart: at sigma = 0.15 h the cone of a frustum took the
// 183-face plane disc on top of it, and its half-angle came out 29.7
// degrees for 20.6.
FitResult InlierFit(const SegmentContext& c, SurfaceType type, const std::vector<int>& vertices) {
  FitResult fit = FitType(c, type, vertices);
  std::vector<int> inliers;
  for (int round = 0; round < kInlierRounds && fit.ok(); ++round) {
    inliers = FittingVertices(c, fit.surface, vertices);
    if (inliers.size() == vertices.size() ||
        inliers.size() < kMinInlierShare * static_cast<double>(vertices.size())) {
      break;
    }
    FitResult refit = FitType(c, type, inliers);
    if (!refit.ok()) break;
    fit = std::move(refit);
  }
  return fit;
}

}  // namespace

Segmentation FinalizeRegions(const SegmentContext& c, const TriMesh& mesh, std::vector<int> labels,
                             std::vector<RegionState> regions) {
  const int n_regions = static_cast<int>(regions.size());
  tbb::parallel_for(0, n_regions, [&](int id) {
    RegionState& r = regions[id];
    if (!r.alive || r.vertices.empty()) return;
    FitResult fit = InlierFit(c, r.type, r.vertices);
    if (!fit.ok()) {
      if (const std::optional<ScoredFit> other = TypeThatFitsInstead(c, r)) {
        r.type = other->type;
        fit = InlierFit(c, r.type, r.vertices);
      }
    }
    // The inliers can leave a curved fit flat where the fit to all of the
    // region (priced by RetypeToSimplerLimits) was not: a small plane disc at
    // sigma = 0.15 h, grown as a sphere of radius 28.7 over it and its rim
    // rows, 128.0 over the disc alone, would be reported so.
    if (fit.ok() && IsCurved(r.type) &&
        NearlyFlat(c, fit.surface, fit.rms_distance, r.vertices, c.tolerance)) {
      FitResult plane = InlierFit(c, SurfaceType::kPlane, r.vertices);
      if (plane.ok()) {
        r.type = SurfaceType::kPlane;
        fit = std::move(plane);
      }
    }
    if (fit.ok()) r.surface = fit.surface;
  });
  FitRoundsTangentToPlanes(c, labels, &regions);
  MergeCoaxialCylinders(c, AlignCoaxialRegions(c, labels, &regions), &labels, &regions);
  return Assemble(c, mesh, FaceLabels(c, mesh, labels, regions), labels, regions);
}

Segmentation FinalizeFaceRegions(const SegmentContext& c, const TriMesh& mesh,
                                 const std::vector<int>& face_labels,
                                 const std::vector<RegionState>& regions) {
  return Assemble(c, mesh, face_labels, std::vector<int>(c.vertex_count(), -1), regions);
}

}  // namespace meshseg::segment_internal
