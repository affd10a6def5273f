// EstimateExactness() and SegmentExactFacets(): the exact path of the
// segment stage (exact_facets.h), from the mesh to a Segmentation.
#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include "absl/strings/str_cat.h"
#include "meshseg/fit.h"
#include "meshseg/segment.h"
#include "meshseg/status_macros.h"
#include "segment/exact_facets.h"
#include "segment/exact_hypotheses.h"
#include "segment/exact_joint_hypotheses.h"
#include "segment/exact_tolerance.h"
#include "segment/facet_mesh.h"
#include "segment/shared_surfaces.h"

namespace meshseg {
namespace {

using segment_internal::CornersOf;
using segment_internal::ExactRegion;
using segment_internal::FacetMesh;
using segment_internal::OnChord;

// Facets sampled (every k-th) for the share of exact facets.
constexpr int kExactnessSample = 1000;
// ... in multiples of the share an exact mesh may miss.
constexpr double kMaxMissedShare = 5.0;
// Sampled facets tested together (in parallel) before the stop is checked: at
// most this many tests are spent past it.
constexpr std::size_t kExactnessBlock = 32;

// The given tolerance, else the one from the rounding of `mesh`'s own
// coordinates (as read: fm's are moved, and no longer round).
double Tolerance(const TriMesh& mesh, const FacetMesh& fm, std::optional<double> given) {
  if (given) return *given;
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) positions.push_back(ToEigen(mesh.point(v)));
  return segment_internal::ExactTolerance(positions, fm.diagonal,
                                          segment_internal::PlanarityFloor(fm));
}

// The area of `facets` (sorted) that lies on a joint hypothesis of their
// edge-connected pieces (exact_joint_hypotheses.h: JointPieceHypotheses).
double JointlyExplainedArea(const FacetMesh& fm, const std::vector<int>& facets, double tau) {
  double area = 0.0;
  std::vector<char> counted(fm.facet_count(), 0);
  for (const segment_internal::Hypothesis& h : segment_internal::JointPieceHypotheses(
           fm, segment_internal::EdgeConnectedPieces(fm, facets), tau)) {
    for (const int f : h.support) {
      if (!counted[f] && std::binary_search(facets.begin(), facets.end(), f)) {
        counted[f] = 1;
        area += fm.area[f];
      }
    }
  }
  return area;
}

// `mean_edge`: the mean edge length of the mesh.
Exactness Measure(const FacetMesh& fm, double tolerance, double mean_edge) {
  Exactness e;
  e.tolerance = tolerance;
  const int n = fm.facet_count();
  const int stride = std::max(1, n / kExactnessSample);
  // A mesh far from exact is known as such long before the sample ends
  // (each unexplained facet costs the most fits): sampling stops at
  // kMaxMissedShare of it missed.
  const int missed_limit =
      static_cast<int>(kMaxMissedShare * (1.0 - kMinExactShare) * kExactnessSample);
  std::vector<int> sample;
  for (int f = 0; f < n; f += stride) sample.push_back(f);
  // The sampled facets are tested in parallel a block at a time (independent
  // tests), and counted in order, so the stop falls where it would one by one.
  double explained = 0.0, total = 0.0;
  int missed = 0;
  std::vector<int> missed_facets;
  for (std::size_t start = 0; start < sample.size() && missed <= missed_limit;
       start += kExactnessBlock) {
    const std::size_t end = std::min(sample.size(), start + kExactnessBlock);
    std::vector<char> ok(end - start, 0);
    tbb::parallel_for(start, end, [&](std::size_t i) {
      ok[i - start] = segment_internal::ExplainedLocally(fm, sample[i], tolerance);
    });
    for (std::size_t i = start; i < end && missed <= missed_limit; ++i) {
      total += fm.area[sample[i]];
      if (ok[i - start]) {
        explained += fm.area[sample[i]];
      } else {
        ++missed;
        missed_facets.push_back(sample[i]);
      }
    }
  }
  // Sampled facets no local fit explains may still lie, piece by piece, on
  // one surface together (small patches of a face cut apart by other
  // features): the joint hypotheses of the segmentation explain them.
  if (explained < kMinExactShare * total && missed <= missed_limit) {
    explained += JointlyExplainedArea(fm, missed_facets, tolerance);
  }
  e.share = total > 0.0 ? explained / total : 0.0;
  e.resolved_sag = tolerance > 0.0 && fm.diagonal > 0.0
                       ? mean_edge * mean_edge / (8.0 * fm.diagonal * tolerance)
                       : 0.0;
  e.exact = e.share >= kMinExactShare && e.resolved_sag >= kMinResolvedSag;
  return e;
}

// Distances of `corners` to `surface` into rms and max; corners on a chord
// (facet_mesh.h: OnChord within tau) lie under it by its sag, and are left
// out.
void Distances(const FacetMesh& fm, const std::vector<int>& corners, const Surface& surface,
               double tau, double* rms, double* max) {
  double sum2 = 0.0;
  *max = 0.0;
  int count = 0;
  for (const int v : corners) {
    if (OnChord(fm, v, tau)) continue;
    ++count;
    const double d = std::abs(SignedDistance(surface, fm.points[v]));
    sum2 += d * d;
    *max = std::max(*max, d);
  }
  *rms = count == 0 ? 0.0 : std::sqrt(sum2 / count);
}

// The Segmentation of `exact`: regions renumbered by first facet, vertices
// labelled with a facet around them, surfaces in the input's frame.
Segmentation Assemble(const Mesh& mesh, const FacetMesh& fm,
                      const segment_internal::ExactFacets& exact, double tau) {
  const int n_regions = static_cast<int>(exact.regions.size());
  std::vector<int> new_id(n_regions, -1);
  std::vector<int> old_of;
  for (const int old : exact.face_labels) {
    if (old >= 0 && new_id[old] < 0) {
      new_id[old] = static_cast<int>(old_of.size());
      old_of.push_back(old);
    }
  }
  std::vector<ExactRegion> regions;
  for (const int old : old_of) regions.push_back(exact.regions[old]);
  std::vector<int> surface_of_region;
  const std::vector<SharedSurface> shared =
      segment_internal::GroupSharedSurfaces(fm, regions, tau, &surface_of_region);

  Segmentation seg;
  seg.face_labels.resize(exact.face_labels.size());
  for (std::size_t f = 0; f < exact.face_labels.size(); ++f) {
    seg.face_labels[f] = exact.face_labels[f] < 0 ? -1 : new_id[exact.face_labels[f]];
  }
  seg.vertex_labels.assign(mesh.tri.n_vertices(), -1);
  for (std::size_t f = 0; f < seg.face_labels.size(); ++f) {
    for (const int v : fm.corners[f]) {
      if (seg.vertex_labels[v] < 0) seg.vertex_labels[v] = seg.face_labels[f];
    }
  }
  // Each region and each surface on its own facets (independent).
  seg.regions.resize(regions.size());
  tbb::parallel_for(std::size_t{0}, regions.size(), [&](std::size_t r) {
    Region& region = seg.regions[r];
    region.id = static_cast<int>(r);
    region.type = regions[r].type;
    region.surface = segment_internal::Translated(regions[r].surface, fm.origin);
    region.face_count = static_cast<int64_t>(regions[r].facets.size());
    for (const int f : regions[r].facets) region.area += fm.area[f];
    const std::vector<int> corners = CornersOf(fm, regions[r].facets);
    region.vertex_count = static_cast<int64_t>(corners.size());
    Distances(fm, corners, regions[r].surface, tau, &region.rms_distance, &region.max_distance);
    region.surface_id = surface_of_region[r];
  });
  seg.surfaces = shared;
  tbb::parallel_for(std::size_t{0}, shared.size(), [&](std::size_t i) {
    SharedSurface& s = seg.surfaces[i];
    std::vector<int> facets;
    for (const int r : s.regions) {
      facets.insert(facets.end(), regions[r].facets.begin(), regions[r].facets.end());
    }
    Distances(fm, CornersOf(fm, facets), s.surface, tau, &s.rms_distance, &s.max_distance);
    s.surface = segment_internal::Translated(s.surface, fm.origin);
  });
  return seg;
}

}  // namespace

Exactness EstimateExactness(const Mesh& mesh, std::optional<double> tolerance) {
  // The sampled tests read the chord vertices of the facets near their
  // samples only: found as read.
  const FacetMesh fm =
      segment_internal::BuildFacetMesh(mesh.tri, segment_internal::ChordVertices::kOnFirstUse);
  return Measure(fm, Tolerance(mesh.tri, fm, tolerance), MeanEdgeLength(mesh.tri));
}

absl::StatusOr<Segmentation> SegmentExactFacets(const Mesh& mesh, const SegmentParams& params,
                                                const RunContext& ctx) {
  if (mesh.tri.n_faces() == 0) {
    return absl::InvalidArgumentError(absl::StrCat("segment: \"", mesh.name, "\" has no faces"));
  }
  if (params.exact_tolerance &&
      !(*params.exact_tolerance > 0.0 && std::isfinite(*params.exact_tolerance))) {
    return absl::InvalidArgumentError(
        absl::StrCat("segment: exact_tolerance must be > 0, got ", *params.exact_tolerance));
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("segment"));
  const FacetMesh fm = segment_internal::BuildFacetMesh(mesh.tri);
  const double tau = Tolerance(mesh.tri, fm, params.exact_tolerance);
  MESHSEG_ASSIGN_OR_RETURN(const segment_internal::ExactFacets exact,
                           segment_internal::SegmentFacets(fm, tau, ctx));
  Segmentation seg = Assemble(mesh, fm, exact, tau);
  seg.estimates.mean_edge_length = MeanEdgeLength(mesh.tri);
  seg.estimates.noise_sigma = 0.0;
  seg.estimates.distance_tolerance = tau;
  seg.estimates.angle_tolerance_deg = exact.angular_step * 180.0 / 3.14159265358979323846;
  seg.estimates.path = SegmentationPath::kExactFacets;
  seg.estimates.exact_tolerance = tau;  // exact_share: measured by the caller
  ctx.Progress("segment", 1.0);
  return seg;
}

}  // namespace meshseg
