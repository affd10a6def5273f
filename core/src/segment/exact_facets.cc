#include "segment/exact_facets.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>
#include <tuple>
#include <utility>

#include <tbb/parallel_for.h>

#include "meshseg/fit.h"
#include "meshseg/status_macros.h"
#include "segment/energy.h"
#include "segment/exact_fit.h"
#include "segment/exact_hypotheses.h"
#include "segment/exact_joint_hypotheses.h"
#include "segment/exact_seed_walk.h"
#include "segment/exact_tolerance.h"
#include "segment/facet_on_surface.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;

double Dihedral(const FacetMesh& fm, int f, int g) {
  return std::atan2(fm.normal[f].cross(fm.normal[g]).norm(), fm.normal[f].dot(fm.normal[g]));
}

// The edge-connected pieces of `facets` (sorted).
std::vector<std::vector<int>> Pieces(const FacetMesh& fm, const std::vector<int>& facets) {
  std::vector<std::vector<int>> pieces;
  std::vector<char> seen(facets.size(), 0);
  auto index = [&](int g) {
    const auto it = std::lower_bound(facets.begin(), facets.end(), g);
    return it != facets.end() && *it == g ? static_cast<int>(it - facets.begin()) : -1;
  };
  for (std::size_t i = 0; i < facets.size(); ++i) {
    if (seen[i]) continue;
    seen[i] = 1;
    std::vector<int> piece = {facets[i]};
    for (std::size_t k = 0; k < piece.size(); ++k) {
      for (const int g : fm.across[piece[k]]) {
        const int j = g < 0 ? -1 : index(g);
        if (j < 0 || seen[j]) continue;
        seen[j] = 1;
        piece.push_back(g);
      }
    }
    std::sort(piece.begin(), piece.end());
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The lazy greedy cover (exact_facets.h; energy.h: E with exact vertices):
// returns the owner region of each facet (-1 = none) and appends the
// regions.
std::vector<int> Claim(const FacetMesh& fm, const std::vector<Hypothesis>& hypotheses,
                       std::vector<ExactRegion>* regions) {
  std::vector<int> owner(fm.facet_count(), -1);
  std::vector<int> stamp(fm.points.size(), -1);
  int stamp_id = 0;
  auto free_corners = [&](const Hypothesis& h) {
    ++stamp_id;
    std::size_t count = 0;
    for (const int f : h.support) {
      if (owner[f] >= 0) continue;
      for (const int v : fm.corners[f]) {
        if (stamp[v] != stamp_id) stamp[v] = stamp_id, ++count;
      }
    }
    return count;
  };
  // (corners newly explained, simpler first, earlier first): exact_facets.h.
  using Entry = std::tuple<std::size_t, int, int>;
  std::priority_queue<Entry> queue;
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    queue.emplace(free_corners(hypotheses[i]), -Simplicity(hypotheses[i].type),
                  -static_cast<int>(i));
  }
  while (!queue.empty()) {
    const auto [key, simplicity, minus_index] = queue.top();
    queue.pop();
    const Hypothesis& h = hypotheses[-minus_index];
    const std::size_t now = free_corners(h);
    if (now < key) {
      if (now > 0) queue.emplace(now, simplicity, minus_index);
      continue;
    }
    // A label lowers E iff its cost per corner is below that of leaving the
    // corners unexplained (always so for a surface holding evidence:
    // (p / 2) ln n / n <= 7 / (2 e) < c_out / 2; none for no corners).
    if (!(ExactPricePerCorner(h.type, now) < kExactOutlierCost)) continue;
    std::vector<int> free;
    for (const int f : h.support) {
      if (owner[f] < 0) free.push_back(f);
    }
    // A joint hypothesis's evidence is held by its pieces together.
    const bool joint_evidence = h.joint && HoldsEvidence(fm, h.type, free);
    for (std::vector<int>& piece : Pieces(fm, free)) {
      if (!joint_evidence && !HoldsEvidence(fm, h.type, piece)) continue;
      const int id = static_cast<int>(regions->size());
      for (const int f : piece) owner[f] = id;
      regions->push_back({.type = h.type, .surface = h.surface, .facets = std::move(piece)});
    }
  }
  return owner;
}

// The largest dihedral angle between edge neighbours inside one curved
// region: the tessellation's angular step.
double AngularStep(const FacetMesh& fm, const std::vector<int>& owner,
                   const std::vector<ExactRegion>& regions) {
  double step = 0.0;
  for (const ExactRegion& r : regions) {
    if (r.type == SurfaceType::kPlane) continue;
    for (const int f : r.facets) {
      for (const int g : fm.across[f]) {
        if (g >= 0 && owner[g] == owner[f]) step = std::max(step, Dihedral(fm, f, g));
      }
    }
  }
  return step > 0.0 ? step : kDefaultAngularStep;
}

// A facet no hypothesis took whose corners all lie on the surface of a
// region across one of its edges (within tau, or on a chord of it) joins
// that region: it fails the chord criterion there (a sliver spanning a rim)
// but holds no evidence of a surface of its own, its corners fixing only
// its own plane. Of several such neighbours, the one sharing the most edges
// with it; repeated while facets join.
void JoinNeighbours(const FacetMesh& fm, double tau, std::vector<int>* owner,
                    std::vector<ExactRegion>* regions) {
  const int n = fm.facet_count();
  for (bool joined = true; joined;) {
    joined = false;
    for (int f = 0; f < n; ++f) {
      if ((*owner)[f] >= 0 || fm.normal[f].isZero()) continue;
      int best = -1, best_edges = 0;
      for (const int g : fm.across[f]) {
        const int r = g < 0 ? -1 : (*owner)[g];
        if (r < 0 || (*regions)[r].type == SurfaceType::kFreeform) continue;
        const int edges = static_cast<int>(
            std::count_if(fm.across[f].begin(), fm.across[f].end(),
                          [&](int h) { return h >= 0 && (*owner)[h] == r; }));
        if (edges <= best_edges) continue;
        const Surface& surface = (*regions)[r].surface;
        const bool on = std::all_of(fm.corners[f].begin(), fm.corners[f].end(), [&](int v) {
          return std::abs(SignedDistance(surface, fm.points[v])) <= tau ||
                 ChordOnSurface(fm, v, surface, tau);
        });
        if (on) best = r, best_edges = edges;
      }
      if (best < 0) continue;
      (*owner)[f] = best;
      (*regions)[best].facets.push_back(f);
      joined = true;
    }
  }
  for (ExactRegion& r : *regions) std::sort(r.facets.begin(), r.facets.end());
}

// The largest distance of the corners of `facets` from `surface` (0 for a
// corner on a chord of it, test (1) of facet_on_surface.h).
double FarthestCorner(const FacetMesh& fm, const std::vector<int>& facets, const Surface& surface,
                      double tau) {
  double farthest = 0.0;
  for (const int f : facets) {
    for (const int v : fm.corners[f]) {
      const double d = std::abs(SignedDistance(surface, fm.points[v]));
      if (d > tau && ChordOnSurface(fm, v, surface, tau)) continue;
      farthest = std::max(farthest, d);
    }
  }
  return farthest;
}

// A piece of facets no hypothesis took (edge-connected) without a vertex of
// its own, every corner also a corner of a region found, fills a gap
// between faces found: the tessellator put no vertex inside the face it
// belongs to, so nothing in the file fixes that face apart from its
// boundary, which the neighbours hold. Boundary vertices lie on a B-rep
// edge's curve, which lies on each face's surface only within the edge's
// tolerance, coarser than the file's rounding (in real CAD exports up to
// about 1e-5 of the part's diagonal).
// Such a piece joins the neighbouring region whose surface explains every
// facet of it (facet_on_surface.h) at the smallest tolerance, if that
// tolerance is within kLoosestExact of the diagonal, the loosest an exact
// file's vertices can be off their surfaces (exact_tolerance.h); a face of
// its own lies farther off every neighbour's surface and stays apart.
void JoinGapPieces(const FacetMesh& fm, double tau, std::vector<int>* owner,
                   std::vector<ExactRegion>* regions) {
  const int n = fm.facet_count();
  std::vector<char> found_corner(fm.points.size(), 0);
  std::vector<int> leftover;
  for (int f = 0; f < n; ++f) {
    if ((*owner)[f] >= 0) {
      for (const int v : fm.corners[f]) found_corner[v] = 1;
    } else if (!fm.normal[f].isZero()) {
      leftover.push_back(f);
    }
  }
  const double loosest = kLoosestExact * fm.diagonal;
  for (const std::vector<int>& piece : Pieces(fm, leftover)) {
    const bool own_vertex = std::any_of(piece.begin(), piece.end(), [&](int f) {
      return std::any_of(fm.corners[f].begin(), fm.corners[f].end(),
                         [&](int v) { return !found_corner[v]; });
    });
    if (own_vertex) continue;
    std::vector<int> neighbours;
    for (const int f : piece) {
      for (const int g : fm.across[f]) {
        if (g >= 0 && (*owner)[g] >= 0) neighbours.push_back((*owner)[g]);
      }
    }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    int best = -1;
    double best_tolerance = loosest;
    for (const int r : neighbours) {
      const Surface& surface = (*regions)[r].surface;
      const double tolerance = std::max(tau, FarthestCorner(fm, piece, surface, tau));
      if (tolerance > best_tolerance) continue;
      const bool on = std::all_of(piece.begin(), piece.end(),
                                  [&](int f) { return FacetOnSurface(fm, f, surface, tolerance); });
      if (on) best = r, best_tolerance = tolerance;
    }
    if (best < 0) continue;
    for (const int f : piece) (*owner)[f] = best;
    std::vector<int>& facets = (*regions)[best].facets;
    facets.insert(facets.end(), piece.begin(), piece.end());
    std::sort(facets.begin(), facets.end());
  }
}

// Facets no hypothesis took: pieces over edges no sharper than `step`; a
// piece of one facet is a plane, a larger one FREEFORM unless every corner
// of it lies within `tau` of one plane: a flat face tessellated into a few
// facets (a rectangle's two triangles between two fillets) is that plane,
// as its single facet would be.
void FreeformRegions(const FacetMesh& fm, double step, double tau, std::vector<int>* owner,
                     std::vector<ExactRegion>* regions) {
  const int n = fm.facet_count();
  for (int f = 0; f < n; ++f) {
    if ((*owner)[f] >= 0 || fm.normal[f].isZero()) continue;
    const int id = static_cast<int>(regions->size());
    std::vector<int> piece = {f};
    (*owner)[f] = id;
    for (std::size_t k = 0; k < piece.size(); ++k) {
      for (const int g : fm.across[piece[k]]) {
        if (g < 0 || (*owner)[g] >= 0 || fm.normal[g].isZero() ||
            Dihedral(fm, piece[k], g) > step) {
          continue;
        }
        (*owner)[g] = id;
        piece.push_back(g);
      }
    }
    std::sort(piece.begin(), piece.end());
    ExactRegion region{
        .type = SurfaceType::kPlane, .surface = Plane{fm.Centroid(f), fm.normal[f]}, .facets = {}};
    const std::optional<Surface> flat =
        piece.size() > 1 ? FitExactly(fm, SurfaceType::kPlane, piece, tau) : std::nullopt;
    if (flat) {
      region.surface = *flat;
    } else if (piece.size() > 1) {
      region.type = SurfaceType::kFreeform;
      std::vector<Eigen::Vector3d> points, normals;
      for (const int g : piece) {
        points.push_back(fm.Centroid(g));
        normals.push_back(fm.normal[g]);
      }
      const FitResult quadric = FitQuadric({.points = points, .normals = normals, .weights = {}});
      region.surface = quadric.ok() ? quadric.surface : Surface{Quadric{}};
    }
    region.facets = std::move(piece);
    regions->push_back(std::move(region));
  }
  // A degenerate facet joins the region of a neighbour.
  for (int f = 0; f < n; ++f) {
    if ((*owner)[f] >= 0) continue;
    for (const int g : fm.across[f]) {
      if (g >= 0 && (*owner)[g] >= 0) {
        (*owner)[f] = (*owner)[g];
        (*regions)[(*owner)[g]].facets.push_back(f);
        break;
      }
    }
    if ((*owner)[f] < 0) {
      (*owner)[f] = static_cast<int>(regions->size());
      regions->push_back(
          ExactRegion{.type = SurfaceType::kPlane, .surface = Plane{}, .facets = {f}});
    }
  }
}

}  // namespace

std::vector<std::vector<int>> EdgeConnectedPieces(const FacetMesh& fm,
                                                  const std::vector<int>& facets) {
  return Pieces(fm, facets);
}

absl::StatusOr<ExactFacets> SegmentFacets(const FacetMesh& fm, double tau, const RunContext& ctx) {
  MESHSEG_ASSIGN_OR_RETURN(std::vector<Hypothesis> hypotheses, SeedHypotheses(fm, tau, ctx));
  for (Hypothesis& h : RevolvedBandHypotheses(fm, hypotheses, tau))
    hypotheses.push_back(std::move(h));
  ExactFacets out;
  std::vector<int> owner = Claim(fm, hypotheses, &out.regions);
  // Pieces left by every seed may lie on one surface together: if so, the
  // cover is made again with their joint hypotheses.
  std::vector<int> left;
  for (int f = 0; f < fm.facet_count(); ++f) {
    if (owner[f] < 0 && !fm.normal[f].isZero()) left.push_back(f);
  }
  if (std::vector<Hypothesis> joint = JointPieceHypotheses(fm, Pieces(fm, left), tau);
      !joint.empty()) {
    for (Hypothesis& h : joint) hypotheses.push_back(std::move(h));
    out.regions.clear();
    owner = Claim(fm, hypotheses, &out.regions);
  }
  MESHSEG_RETURN_IF_ERROR(ctx.CheckStop("segment"));
  out.angular_step = AngularStep(fm, owner, out.regions);
  // Each analytic region refitted on all of its corners (independent fits).
  tbb::parallel_for(std::size_t{0}, out.regions.size(), [&](std::size_t i) {
    ExactRegion& r = out.regions[i];
    if (const std::optional<Surface> refit = FitExactly(fm, r.type, r.facets, tau)) {
      r.surface = *refit;
    }
  });
  JoinNeighbours(fm, tau, &owner, &out.regions);
  JoinGapPieces(fm, tau, &owner, &out.regions);
  FreeformRegions(fm, out.angular_step, tau, &owner, &out.regions);
  out.face_labels = std::move(owner);
  return out;
}

}  // namespace meshseg::segment_internal
