#include "segment/give_back_rows.h"

#include <cmath>
#include <limits>
#include <optional>

#include "segment/absorb_leftovers.h"
#include "segment/decide_type.h"
#include "segment/retype_by_interior.h"

namespace meshseg::segment_internal {
namespace {

// Sets taker[v], for the vertices of region `id` its analytic neighbours
// grow back over, to that neighbour: breadth first from the vertices next
// to each, over those within th_dis of its surface (5). Not (6): on the
// rows along a rounded crease n'_i is bent toward both faces. Neighbours
// under kMinRegionVertices take nothing: they are fragments the last
// release frees, not faces that lost rows, and one may be a piece of the
// region's own surface (on a noisy countersink band grown as a torus of
// 928 vertices, a sphere piece of the same band, 50 vertices, would have
// taken 466 of them).
void GrowBack(const SegmentContext& c, const std::vector<int>& labels,
              const std::vector<RegionState>& regions, int id, std::vector<int>* taker) {
  const auto fits = [&](int v, int n) {
    return std::abs(ProjectVertex(c, regions[n].surface, v).distance) < c.tolerance.distance;
  };
  std::vector<int> queue;
  for (const int v : regions[id].vertices) {
    for (const int u : c.graph.Neighbors(v)) {
      const int n = labels[u];
      if (n < 0 || n == id || !regions[n].alive || !IsAnalytic(regions[n].type) ||
          regions[n].vertices.size() < kMinRegionVertices) {
        continue;
      }
      if (fits(v, n)) {
        (*taker)[v] = n;
        queue.push_back(v);
        break;
      }
    }
  }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const int v = queue[k];
    const int n = (*taker)[v];
    for (const int w : c.graph.Neighbors(v)) {
      if (labels[w] != id || (*taker)[w] >= 0 || !fits(w, n)) continue;
      (*taker)[w] = n;
      queue.push_back(w);
    }
  }
}

// True if region `id` has kMinInteriorVertices interior vertices and its
// surface, or its type refitted to them, misses them beyond the noise
// (kMinModelError): the rows it took bent it. The type alone can hide that:
// a small plane disc on top of a conical frustum, at sigma = 0.15 h, grew
// as a sphere of radius 12.4 over the disc and the rows of the cone round
// it, and a flatter sphere meets the disc alone at the noise.
bool RowsBendIt(const SegmentContext& c, const std::vector<int>& labels, int id,
                const RegionState& r) {
  const int ids[] = {id};
  const std::vector<int> interior = InteriorVertices(c, labels, ids, r.vertices);
  if (interior.size() < kMinInteriorVertices) return false;
  const double surface_error =
      ModelErrorOfMeanSquare(c, SquaredDistances(c, r.surface, interior) / interior.size());
  return surface_error > kMinModelError * c.noise_sigma ||
         !FitsAtNoise(c, FitType(c, r.type, interior));
}

struct GiveBack {
  std::vector<int> rest;
  ScoredFit rest_fit;  // score: of the whole region, rows included
};

// Whether region `id` should give back the rows `taker` marks: the best
// type for the rest (a plane, its own or a curved one), with the rows under
// their neighbours' surfaces, against the region's type alone.
std::optional<GiveBack> Weigh(const SegmentContext& c, const std::vector<RegionState>& regions,
                              int id, const std::vector<int>& taker) {
  const RegionState& r = regions[id];
  GiveBack out;
  double rows = 0.0;
  for (const int v : r.vertices) {
    if (taker[v] < 0) {
      out.rest.push_back(v);
    } else {
      const double d = ProjectVertex(c, regions[taker[v]].surface, v).distance;
      rows += d * d;
    }
  }
  if (out.rest.size() == r.vertices.size() || out.rest.size() < kMinRegionVertices) {
    return std::nullopt;
  }
  const std::size_t n = r.vertices.size();
  const FitResult alone = FitType(c, r.type, r.vertices);
  if (!alone.ok()) return std::nullopt;
  const double one = InformationScore(c, SquaredDistances(c, alone.surface, r.vertices) / n, n,
                                      ParameterCount(r.type));
  out.rest_fit.score = std::numeric_limits<double>::infinity();
  std::vector<SurfaceType> types = {SurfaceType::kPlane};
  for (const SurfaceType type : kCurvedTypes) {
    if (ParameterCount(type) <= ParameterCount(r.type)) types.push_back(type);
  }
  if (r.type == SurfaceType::kQuadric) types.push_back(r.type);
  std::vector<ScoredFit> scored;
  for (const SurfaceType type : types) {
    FitResult fit = FitType(c, type, out.rest);
    if (!fit.ok()) continue;
    const double score = InformationScore(
        c, (rows + SquaredDistances(c, fit.surface, out.rest)) / n, n, ParameterCount(type));
    scored.push_back(ScoredFit{.type = type, .fit = std::move(fit), .score = score});
    if (score < out.rest_fit.score) out.rest_fit = scored.back();
  }
  // A type with more parameters than the rest needs can still score best on
  // it: a countersink band at sigma = 0.15 h kept a torus 29 below the
  // cone, its rms 0.140 under the noise (0.152) where the cone's, 0.151,
  // was at it; the torus then grew back over the rows (983 vertices) and won
  // on the interior. The simplest limit of the best type that meets the rest
  // at the noise takes it instead.
  const ScoredFit* simplest = nullptr;
  for (const ScoredFit& s : scored) {
    if (IsLimitOf(s.type, out.rest_fit.type) && FitsAtNoise(c, s.fit) &&
        (simplest == nullptr || ParameterCount(s.type) < ParameterCount(simplest->type))) {
      simplest = &s;
    }
  }
  if (simplest != nullptr) out.rest_fit = *simplest;
  if (!(out.rest_fit.score + kScoreMargin < one)) return std::nullopt;
  return out;
}

}  // namespace

std::vector<int> GiveBackRows(const SegmentContext& c, std::vector<int>* labels,
                              std::vector<RegionState>* regions) {
  std::vector<int> gave;
  if (!(c.noise_sigma > 0.0)) return gave;
  std::vector<int> taker(c.vertex_count(), -1);
  for (int id = 0; id < static_cast<int>(regions->size()); ++id) {
    const RegionState& r = (*regions)[id];
    if (!r.alive || !(IsCurved(r.type) || r.type == SurfaceType::kQuadric) ||
        !RowsBendIt(c, *labels, id, r)) {
      continue;
    }
    GrowBack(c, *labels, *regions, id, &taker);
    const std::optional<GiveBack> g = Weigh(c, *regions, id, taker);
    RegionState& region = (*regions)[id];
    for (const int v : region.vertices) {
      if (g && taker[v] >= 0) (*labels)[v] = taker[v];
      taker[v] = -1;
    }
    if (!g) continue;
    region.type = g->rest_fit.type;
    region.surface = g->rest_fit.fit.surface;
    // The regions after this one are weighed on what they hold now.
    RebuildVertexLists(*labels, regions);
    gave.push_back(id);
  }
  return gave;
}

}  // namespace meshseg::segment_internal
