// Segment(): checks the params, derives the tolerances, then runs
// ALGORITHMS.md S1 steps 2-3 with S2's leftover absorption and face labels,
// in order.
#include "meshseg/segment.h"

#include <cmath>
#include <optional>

#include <Eigen/Geometry>

#include "absl/strings/str_cat.h"
#include "meshseg/status_macros.h"
#include "segment/absorb_leftovers.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/drop_regions.h"
#include "segment/energy.h"
#include "segment/estimate_noise.h"
#include "segment/finalize_regions.h"
#include "segment/initial_segmentation.h"
#include "segment/kept_prices.h"
#include "segment/merge_regions.h"
#include "segment/refit_to_interior.h"
#include "segment/retype_by_interior.h"
#include "segment/retype_coaxial_bands.h"
#include "segment/retype_regions.h"
#include "segment/segment_internal.h"
#include "segment/split_off_planes.h"

namespace meshseg {
namespace {

absl::Status ValidateParams(const SegmentParams& p) {
  if (!(p.distance_tolerance > 0.0) || !std::isfinite(p.distance_tolerance)) {
    return absl::InvalidArgumentError(
        absl::StrCat("segment: distance_tolerance must be > 0, got ", p.distance_tolerance));
  }
  if (p.angle_tolerance_deg &&
      (!(*p.angle_tolerance_deg > 0.0) || !(*p.angle_tolerance_deg < 90.0))) {
    return absl::InvalidArgumentError(absl::StrCat(
        "segment: angle_tolerance_deg must be in (0, 90), got ", *p.angle_tolerance_deg));
  }
  if (!(p.alpha > 0.0) || !(p.alpha <= 1.0)) {
    return absl::InvalidArgumentError(absl::StrCat("segment: alpha must be in (0, 1], got ", p.alpha));
  }
  if (p.exact_tolerance && !(*p.exact_tolerance > 0.0 && std::isfinite(*p.exact_tolerance))) {
    return absl::InvalidArgumentError(
        absl::StrCat("segment: exact_tolerance must be > 0, got ", *p.exact_tolerance));
  }
  if (p.point_noise && !(*p.point_noise >= 0.0 && std::isfinite(*p.point_noise))) {
    return absl::InvalidArgumentError(
        absl::StrCat("segment: point_noise must be >= 0, got ", *p.point_noise));
  }
  return absl::OkStatus();
}

// The merges and the drops that lower the energy (merge_regions.h,
// drop_regions.h) in turn until no drop does: a drop can leave the pieces
// a fragment kept apart to merge, and a merge refused for a drop waits for
// that drop. Returns how many moves were made.
absl::StatusOr<int> MergeAndDrop(const segment_internal::SegmentContext& c,
                                 std::vector<int>* labels,
                                 std::vector<segment_internal::RegionState>* regions,
                                 segment_internal::KeptPrices* prices) {
  int moves = 0;
  for (;;) {
    MESHSEG_ASSIGN_OR_RETURN(const int merged,
                             segment_internal::MergeRegions(c, labels, regions, prices));
    MESHSEG_ASSIGN_OR_RETURN(const int dropped,
                             segment_internal::DropRegions(c, labels, regions, prices));
    moves += merged + dropped;
    if (dropped == 0) return moves;
  }
}

// MergeAndDrop, then ALGORITHMS.md S1's type decision (step 2.5) for the
// general quadrics left.
absl::Status Merge(const segment_internal::SegmentContext& c, std::vector<int>* labels,
                   std::vector<segment_internal::RegionState>* regions,
                   segment_internal::KeptPrices* prices) {
  MESHSEG_RETURN_IF_ERROR(MergeAndDrop(c, labels, regions, prices).status());
  segment_internal::RetypeQuadrics(c, regions);
  return absl::OkStatus();
}

// PEARL's alternation (Isack & Boykov, IJCV 2012) over the moves of E
// (energy.h): the retypes proposed (a narrow band the type its interior
// tells, priced with the expansion it enables; a band beside a turned face
// its cone and its sphere on that face's axis, each priced so; a curved
// region the surface of its own type its interior fits, priced with the
// expansion too; a plane its plane no longer fits; a curved region its type
// misses; a band beside a turned face the cone on that face's axis; a curved
// type its simpler limit; retype_by_interior.h, retype_coaxial_bands.h,
// refit_to_interior.h, retype_regions.h), the
// merges and the drops, each made iff it lowers E, then the expansion with
// re-estimation over the boundaries they changed; repeated until no move is
// made (each move lowers E, so it ends; kMaxImproveRounds guards against a
// cycle of moves whose gains are rounding). The expansion can shrink a
// region to a sliver or a strip whose vertices cost less on its
// neighbours' surfaces (between a countersink and its plane, along a
// groove), which the next round drops,
// and it gives a plane retyped on part of its arc the rest, whose type the
// next round proposes again.
constexpr int kMaxImproveRounds = 16;
absl::Status Improve(const segment_internal::SegmentContext& c, std::vector<int>* labels,
                     std::vector<segment_internal::RegionState>* regions,
                     segment_internal::KeptPrices* prices) {
  for (int round = 0; round < kMaxImproveRounds; ++round) {
    // The retype by the interior first: it is priced with the expansion it
    // enables, at the expansion's fixed point the last round (or step) left.
    MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> by_interior,
                             segment_internal::RetypeByInterior(c, labels, regions, prices));
    // A band beside a turned face, its cone and its sphere on that face's
    // axis each priced with its expansion, at the same fixed point.
    MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> coaxial,
                             segment_internal::PlaceCoaxialBands(c, labels, regions));
    // The same for a surface its own interior fits (refit_to_interior.h).
    MESHSEG_ASSIGN_OR_RETURN(const std::vector<int> to_interior,
                             segment_internal::RefitToInterior(c, labels, regions, prices));
    // Only the regions changed since a proposal last made no move on them
    // are asked it again (KeptPrices::Refused).
    std::size_t moves =
        by_interior.size() + coaxial.size() + to_interior.size() +
        segment_internal::RetypeBentPlanes(c, regions, prices).size() +
        segment_internal::RetypeInaccurateCurved(c, regions, prices).size() +
        segment_internal::RetypeCoaxialBands(c, *labels, regions).size() +
        static_cast<std::size_t>(segment_internal::RetypeToSimplerLimits(c, regions, prices));
    MESHSEG_ASSIGN_OR_RETURN(const int merged, MergeAndDrop(c, labels, regions, prices));
    segment_internal::RetypeQuadrics(c, regions);
    moves += static_cast<std::size_t>(merged);
    if (moves == 0) return absl::OkStatus();
    MESHSEG_RETURN_IF_ERROR(segment_internal::ExpandRegions(c, labels, regions).status());
  }
  return absl::OkStatus();
}

// Each region a surface of its own (the scan path does not join them).
void OwnSurfaces(Segmentation* seg) {
  for (Region& r : seg->regions) {
    r.surface_id = r.id;
    seg->surfaces.push_back({.id = r.id,
                             .type = r.type,
                             .surface = r.surface,
                             .regions = {r.id},
                             .rms_distance = r.rms_distance,
                             .max_distance = r.max_distance});
  }
}

// Segment, with l_avg = MeanEdgeLength(mesh.tri) given if the caller
// already measured it (else summed here, where the seeded path needs it).
// On a scan (not an exact tessellation) it runs eight steps. Every move of
// steps 4-8 is made iff it lowers the one energy E (energy.h; PEARL with
// label costs); steps 1-3 make the proposals E starts from.
//  1. Grow: seeds 000/002's regions, the surfaces proposed (S1 step 2).
//  2. Absorb: small quadric regions released, every vertex given a region
//     (S2's leftover absorption).
//  3. Evidence share: f, how many independent samples the residuals are
//     worth, measured once on the regions grown (E's label and boundary
//     costs are in its units).
//  4. Merge: merges and drops while E falls; general quadrics typed (S1
//     step 2.5).
//  5. Expand: alpha-expansion with re-estimation (alpha_expansion.h)
//     places every boundary where E is least. A round grown on a narrow
//     band has a tube radius the band does not fix within the noise; the
//     expansion moves a boundary by at most a band per sweep and refits
//     between sweeps, so the round's surface follows the rows it keeps, and
//     a surface grown bent over rows of a neighbour's face (a sphere over a
//     flat top and a ring of the cone below) gives them back the same way.
//  6. Improve: PEARL's alternation (Improve above) of every priced move,
//     retypes, merges and drops, then the expansion, until no move lowers E.
//     A narrow band's type is put to E by its interior (the outer rows are
//     the creases'), priced with the expansion it enables, and a cone or a
//     sphere on a turned neighbour's axis with the 2 parameters its own
//     vertices estimate (energy.h, "Shared parameters").
//  7. Split off planes: a flat face a curved region absorbed is born as a
//     plane of its own, kept iff E with the expansion falls
//     (split_off_planes.h).
//  8. Improve again: the pieces the split leaves, joined, dropped or
//     retyped by the same moves.
absl::StatusOr<Segmentation> SegmentWithEdgeLength(const Mesh& mesh,
                                                   const CurvatureField& curvature,
                                                   const SegmentParams& params,
                                                   const RunContext& ctx,
                                                   std::optional<double> mean_edge_length) {
  using namespace segment_internal;
  MESHSEG_RETURN_IF_ERROR(ValidateParams(params));
  if (mesh.tri.n_faces() == 0) {
    return absl::InvalidArgumentError(absl::StrCat("segment: \"", mesh.name, "\" has no faces"));
  }
  if (!params.measured.empty() && params.measured.size() != mesh.tri.n_vertices()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "segment: measured mask has ", params.measured.size(), " vertices, mesh \"", mesh.name,
        "\" has ", mesh.tri.n_vertices()));
  }
  if (curvature.sharp.size() != mesh.tri.n_vertices()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "segment: curvature field has ", curvature.sharp.size(), " vertices, mesh \"", mesh.name,
        "\" has ", mesh.tri.n_vertices()));
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("segment"));
  if (params.exact != ExactMode::kNever) {
    const Exactness exactness = params.exact == ExactMode::kAuto
                                    ? EstimateExactness(mesh, params.exact_tolerance)
                                    : Exactness{};
    if (params.exact == ExactMode::kAlways || exactness.exact) {
      MESHSEG_ASSIGN_OR_RETURN(Segmentation seg, SegmentExactFacets(mesh, params, ctx));
      seg.estimates.exact_share = exactness.share;
      return seg;
    }
  }
  const SegmentEstimates estimates = EstimateNoise(
      curvature, mean_edge_length ? *mean_edge_length : MeanEdgeLength(mesh.tri), params);
  SegmentContext c = MakeSegmentContext(mesh.tri, curvature, estimates, params.alpha, ctx);
  c.on_facets = params.on_facets;
  c.measured = params.measured;
  c.unit_scale = DataUnitScale(estimates, params.point_noise);

  std::vector<int> labels(c.vertex_count(), -1);
  std::vector<RegionState> regions;
  // 1. Grow.
  MESHSEG_RETURN_IF_ERROR(GrowInitialRegions(c, &labels, &regions));
  ctx.Progress("segment", 0.6);
  // 2. Absorb.
  ReleaseSmallQuadrics(c, &labels, &regions);
  MESHSEG_RETURN_IF_ERROR(AbsorbLeftovers(c, &labels, &regions));
  ctx.Progress("segment", 0.7);
  // 3. Evidence share.
  c.evidence_share = EvidenceShare(c, labels, regions);
  // Merge and drop prices (and refused proposals), kept from each step for
  // the next.
  KeptPrices kept_prices;
  // 4. Merge.
  MESHSEG_RETURN_IF_ERROR(Merge(c, &labels, &regions, &kept_prices));
  // 5. Expand.
  MESHSEG_RETURN_IF_ERROR(ExpandRegions(c, &labels, &regions).status());
  // 6. Improve.
  MESHSEG_RETURN_IF_ERROR(Improve(c, &labels, &regions, &kept_prices));
  // 7. Split off planes.
  MESHSEG_RETURN_IF_ERROR(SplitOffPlanes(c, &labels, &regions).status());
  // 8. Improve again.
  MESHSEG_RETURN_IF_ERROR(Improve(c, &labels, &regions, &kept_prices));
  ctx.Progress("segment", 0.9);
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("segment"));
  Segmentation seg = FinalizeRegions(c, mesh.tri, std::move(labels), std::move(regions));
  seg.estimates = estimates;
  OwnSurfaces(&seg);
  ctx.Progress("segment", 1.0);
  return seg;
}

}  // namespace

absl::StatusOr<Segmentation> Segment(const Mesh& mesh, const CurvatureField& curvature,
                                     const SegmentParams& params, const RunContext& ctx) {
  return SegmentWithEdgeLength(mesh, curvature, params, ctx, std::nullopt);
}

absl::StatusOr<Segmentation> Segment(const Mesh& mesh, const CurvatureField& curvature,
                                     double mean_edge_length, const SegmentParams& params,
                                     const RunContext& ctx) {
  if (!(mean_edge_length > 0.0) || !std::isfinite(mean_edge_length)) {
    return absl::InvalidArgumentError(
        absl::StrCat("segment: mean edge length of \"", mesh.name, "\" is ", mean_edge_length,
                     ", must be finite and > 0"));
  }
  return SegmentWithEdgeLength(mesh, curvature, params, ctx, mean_edge_length);
}

}  // namespace meshseg
