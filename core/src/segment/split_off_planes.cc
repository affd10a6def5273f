#include "segment/split_off_planes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "meshseg/status_macros.h"
#include "segment/absorb_leftovers.h"
#include "segment/alpha_expansion.h"
#include "segment/decide_type.h"
#include "segment/energy.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Candidate directions: the n_i of this many of the region's vertices.
constexpr std::size_t kDirectionSamples = 200;
// Rounds of giving the region's vertices to the nearer surface.
constexpr int kSplitRounds = 3;

struct Split {
  FitResult plane;
  SurfaceType curved_type = SurfaceType::kQuadric;
  FitResult curved;
  std::vector<int> on_plane;
  std::vector<int> rest;
};

// The vertices of `vertices` whose n_i lie within th_nm of the direction
// that the most of them do (the mean of the n_i near one of theirs). The
// raw n_i, not n'_i: on a face narrower than N'(i, W2) every n'_i is bent.
std::vector<int> DominantNormalVertices(const SegmentContext& c, const std::vector<int>& vertices) {
  const double cos_max = std::cos(c.angle_tolerance_deg * kPi / 180.0);
  const std::vector<Eigen::Vector3d>& n = c.curvature->normal;
  const std::vector<int> sample = Sample(vertices);
  std::size_t best_count = 0;
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  for (const int s : Sample(vertices, kDirectionSamples)) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (const int v : sample) {
      if (n[v].dot(n[s]) > cos_max) d += n[v];
    }
    if (!(d.norm() > 0.0)) continue;
    d.normalize();
    const auto count = static_cast<std::size_t>(
        std::count_if(sample.begin(), sample.end(), [&](int v) { return n[v].dot(d) > cos_max; }));
    if (count > best_count) {
      best_count = count;
      best = d;
    }
  }
  std::vector<int> out;
  for (const int v : vertices) {
    if (n[v].dot(best) > cos_max) out.push_back(v);
  }
  return out;
}

constexpr int8_t kOutside = -1;
constexpr int8_t kOnPlane = 0;
constexpr int8_t kOnRest = 1;

// Puts every vertex of `vertices` whose neighbours are all of `vertices`
// and all on the other side on that side (decided on the sides as they
// were). Where the curved fit passes close to the flat face, the noise
// leaves single vertices of the face nearer to it: a small plane disc at
// sigma = 0.15 h kept 100 of its 115 vertices with the plane, but the holes
// left it 21 interior vertices, too few for its interior to tell it from a
// strip (kMinInteriorVertices).
void FillOneVertexHoles(const SegmentContext& c, const std::vector<int>& vertices,
                        std::vector<int8_t>* side) {
  std::vector<int> flip;
  for (const int v : vertices) {
    const auto around = c.graph.Neighbors(v);
    if (!around.empty() && std::all_of(around.begin(), around.end(), [&](int u) {
          return (*side)[u] != kOutside && (*side)[u] != (*side)[v];
        })) {
      flip.push_back(v);
    }
  }
  for (const int v : flip) (*side)[v] = (*side)[v] == kOnPlane ? kOnRest : kOnPlane;
}

// The surface of the region's vertices off the plane: of the region's type
// `type`, or, where that has no valid fit to them, of the limit of it
// (IsLimitOf) that scores least there. A type grown over a flat face across
// a crease bends to meet both (a torus over a conical band and the disc
// beside it); without the face the band may be a limit of it, on which the
// general type's fit degenerates (a torus of unbounded minor radius on a
// cone).
ScoredFit FitRest(const SegmentContext& c, SurfaceType type, std::span<const int> rest) {
  ScoredFit best{.type = type, .fit = FitType(c, type, rest)};
  if (best.fit.ok()) return best;
  for (const SurfaceType limit : kCurvedTypes) {
    if (!IsLimitOf(limit, type)) continue;
    ScoredFit s = ScoreType(c, limit, rest);
    if (s.score < best.score) best = std::move(s);
  }
  return best;
}

// Steps 1 and 2 of SplitOffPlanes on region `r`.
std::optional<Split> FindSplit(const SegmentContext& c, const RegionState& r) {
  const std::vector<int> flat = DominantNormalVertices(c, r.vertices);
  if (flat.size() < kMinInteriorVertices) return std::nullopt;
  Split s;
  s.plane = FitType(c, SurfaceType::kPlane, flat);
  if (!s.plane.ok()) return std::nullopt;
  for (const int v : r.vertices) {
    (Fits(c, v, ProjectVertex(c, s.plane.surface, v), c.tolerance) ? s.on_plane : s.rest)
        .push_back(v);
  }
  // The face itself must be flat, near the noise: the rows the tests add
  // along the crease are rounded by the meshing (a small plane disc beside
  // a 69-degree crease, at sigma = 0.15 h: its plane 0.36 to 0.41 sigma off
  // the 52 to 58 vertices the tests give it, up to 78 after the rounds
  // below). The crease and the scores of step 3 decide.
  if (s.on_plane.size() < kMinInteriorVertices ||
      !FitsNearNoise(c, FitType(c, SurfaceType::kPlane, s.on_plane))) {
    return std::nullopt;
  }
  // Fit both, give each vertex to the nearer, kSplitRounds times; then fit
  // both to their final sets.
  // Only the region's entries change; the rest stay kOutside.
  std::vector<int8_t> side(c.vertex_count(), kOutside);
  for (int round = 0;; ++round) {
    if (s.on_plane.size() < kMinInteriorVertices || s.rest.size() < kMinRegionVertices) {
      return std::nullopt;
    }
    s.plane = FitType(c, SurfaceType::kPlane, s.on_plane);
    ScoredFit rest = FitRest(c, r.type, s.rest);
    s.curved_type = rest.type;
    s.curved = std::move(rest.fit);
    if (!s.plane.ok() || !s.curved.ok()) return std::nullopt;
    if (round == kSplitRounds) break;
    for (const int v : r.vertices) {
      side[v] = std::abs(ProjectVertex(c, s.plane.surface, v).distance) <
                        std::abs(ProjectVertex(c, s.curved.surface, v).distance)
                    ? kOnPlane
                    : kOnRest;
    }
    FillOneVertexHoles(c, r.vertices, &side);
    s.on_plane.clear();
    s.rest.clear();
    for (const int v : r.vertices) (side[v] == kOnPlane ? s.on_plane : s.rest).push_back(v);
  }
  if (s.on_plane.size() < kMinRegionVertices) return std::nullopt;
  return s;
}

}  // namespace

absl::StatusOr<std::vector<int>> SplitOffPlanes(const SegmentContext& c,
                                                 std::vector<int>* labels,
                                                 std::vector<RegionState>* regions) {
  std::vector<int> split;
  if (!(c.noise_sigma > 0.0)) return split;
  const std::size_t n_regions = regions->size();
  for (std::size_t id = 0; id < n_regions; ++id) {
    const RegionState& r = (*regions)[id];
    if (!r.alive || !(IsCurved(r.type) || r.type == SurfaceType::kQuadric) ||
        r.vertices.size() < 2 * kMinRegionVertices ||
        !TypeMissesInterior(c, *labels, static_cast<int>(id), r)) {
      continue;
    }
    const std::optional<Split> s = FindSplit(c, r);
    if (!s) continue;
    // Step 3 on copies: the plane joins the labels as a proposal.
    std::vector<int> next_labels = *labels;
    std::vector<RegionState> next = *regions;
    const int plane_id = static_cast<int>(next.size());
    for (const int v : s->on_plane) next_labels[v] = plane_id;
    RegionState& kept = next[id];
    kept.vertices = s->rest;
    kept.type = s->curved_type;
    kept.surface = s->curved.surface;
    // The quadric may have been the mix; the rest may have a type.
    if (kept.type == SurfaceType::kQuadric) {
      const TypedFit typed = DecideCurvedType(c, kept.vertices, c.tolerance);
      if (typed.type != SurfaceType::kQuadric && typed.fraction > c.alpha) {
        kept.type = typed.type;
        kept.surface = typed.fit.surface;
      }
    }
    next.push_back(RegionState{.type = SurfaceType::kPlane,
                               .surface = s->plane.surface,
                               .vertices = s->on_plane,
                               .alive = true});
    MESHSEG_RETURN_IF_ERROR(ExpandRegions(c, &next_labels, &next).status());
    if (!(TotalEnergy(c, next_labels, next) < TotalEnergy(c, *labels, *regions))) continue;
    *labels = std::move(next_labels);
    *regions = std::move(next);
    split.push_back(static_cast<int>(id));
  }
  return split;
}

}  // namespace meshseg::segment_internal
