#include "segment/exact_joint_hypotheses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <utility>
#include <variant>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "meshseg/fit.h"
#include "segment/exact_fit.h"
#include "segment/facet_on_surface.h"

namespace meshseg::segment_internal {
namespace {

// Axes closer than this (radians, and in the diagonal's units) may be one:
// a coarse filter before the exact joint fit, which decides.
constexpr double kCoaxialAngle = 1e-2;
constexpr double kCoaxialOffset = 1e-2;

struct Axis {
  Eigen::Vector3d point;
  Eigen::Vector3d direction;  // unit
};

std::optional<Axis> BandAxis(const Surface& surface) {
  if (const auto* c = std::get_if<Cylinder>(&surface)) {
    return Axis{c->axis_origin, c->axis_direction.normalized()};
  }
  if (const auto* c = std::get_if<Cone>(&surface)) {
    return Axis{c->apex, c->axis_direction.normalized()};
  }
  return std::nullopt;
}

bool Coaxial(const Axis& a, const Axis& b, double diagonal) {
  const double angle =
      std::atan2(a.direction.cross(b.direction).norm(), std::abs(a.direction.dot(b.direction)));
  if (!(angle <= kCoaxialAngle)) return false;
  const Eigen::Vector3d w = b.point - a.point;
  return (w - w.dot(a.direction) * a.direction).norm() <= kCoaxialOffset * diagonal;
}

// True if some corner of `facets` lies off `surface` (beyond tau).
bool Departs(const FacetMesh& fm, const std::vector<int>& facets, const Surface& surface,
             double tau) {
  return std::any_of(facets.begin(), facets.end(),
                     [&](int f) { return !CornersOnSurface(fm, f, surface, tau); });
}

std::vector<int> Union(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

// A sphere, else a torus, fitted exactly to `facets` with every facet on it.
std::optional<Hypothesis> RevolvedFit(const FacetMesh& fm, const std::vector<int>& facets,
                                      double tau) {
  for (const SurfaceType type : {SurfaceType::kSphere, SurfaceType::kTorus}) {
    if (!HoldsEvidence(fm, type, facets)) continue;
    const std::optional<Surface> fit = FitExactly(fm, type, facets, tau);
    if (!fit || !std::all_of(facets.begin(), facets.end(),
                             [&](int f) { return FacetOnSurface(fm, f, *fit, tau); })) {
      continue;
    }
    return Hypothesis{.type = type, .surface = *fit, .support = facets};
  }
  return std::nullopt;
}

}  // namespace

std::vector<Hypothesis> RevolvedBandHypotheses(const FacetMesh& fm,
                                               const std::vector<Hypothesis>& hypotheses,
                                               double tau) {
  std::vector<int> bands;
  std::vector<Axis> axis(hypotheses.size());
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    if (const std::optional<Axis> a = BandAxis(hypotheses[i].surface)) {
      axis[i] = *a;
      bands.push_back(static_cast<int>(i));
    }
  }
  if (bands.size() < 3) return {};
  // (facet, band) for every facet of every band's support, sorted.
  std::vector<std::pair<int, int>> band_at;
  for (const int b : bands) {
    for (const int f : hypotheses[b].support) band_at.emplace_back(f, b);
  }
  tbb::parallel_sort(band_at.begin(), band_at.end());  // distinct pairs: one order
  // Coaxial bands across an edge of each band's support (each band on its own).
  std::vector<std::vector<int>> next(hypotheses.size());
  tbb::parallel_for(std::size_t{0}, bands.size(), [&](std::size_t i) {
    const int b = bands[i];
    const std::vector<int>& support = hypotheses[b].support;
    for (const int f : support) {
      for (const int g : fm.across[f]) {
        if (g < 0 || std::binary_search(support.begin(), support.end(), g)) continue;
        auto [lo, hi] =
            std::equal_range(band_at.begin(), band_at.end(), std::make_pair(g, -1),
                             [](const auto& x, const auto& y) { return x.first < y.first; });
        for (auto it = lo; it != hi; ++it) {
          if (it->second != b && Coaxial(axis[b], axis[it->second], fm.diagonal)) {
            next[b].push_back(it->second);
          }
        }
      }
    }
    std::sort(next[b].begin(), next[b].end());
    next[b].erase(std::unique(next[b].begin(), next[b].end()), next[b].end());
  });
  // The widest bands first; a band inside a joint hypothesis found seeds no
  // other.
  std::stable_sort(bands.begin(), bands.end(), [&](int a, int b) {
    return hypotheses[a].support.size() > hypotheses[b].support.size();
  });
  std::vector<char> explained(fm.facet_count(), 0);
  std::vector<Hypothesis> out;
  for (const int i : bands) {
    const std::vector<int>& support_i = hypotheses[i].support;
    if (std::all_of(support_i.begin(), support_i.end(), [&](int f) { return explained[f]; })) {
      continue;
    }
    int tries = 0;
    std::optional<Hypothesis> found;
    for (const int j : next[i]) {
      if (found || tries >= kMaxBandChains) break;
      std::vector<int> thirds = Union(next[i], next[j]);
      for (const int k : thirds) {
        if (k == i || k == j) continue;
        if (tries >= kMaxBandChains) break;
        const Hypothesis& a = hypotheses[i];
        const Hypothesis& b = hypotheses[j];
        const Hypothesis& c = hypotheses[k];
        // Three bands on three surfaces: four circles at least.
        if (!Departs(fm, b.support, a.surface, tau) || !Departs(fm, c.support, a.surface, tau) ||
            !Departs(fm, c.support, b.surface, tau) || !Departs(fm, a.support, b.surface, tau) ||
            !Departs(fm, a.support, c.surface, tau) || !Departs(fm, b.support, c.surface, tau)) {
          continue;
        }
        ++tries;
        found = RevolvedFit(fm, Union(Union(a.support, b.support), c.support), tau);
        if (found) break;
      }
    }
    if (!found) continue;
    GrowHypothesis(fm, tau, &*found);
    for (const int f : found->support) explained[f] = 1;
    out.push_back(*std::move(found));
  }
  return out;
}

std::vector<Hypothesis> JointPieceHypotheses(const FacetMesh& fm,
                                             std::vector<std::vector<int>> pieces, double tau) {
  std::erase_if(pieces, [](const std::vector<int>& p) { return p.size() < kMinJointPieceFacets; });
  std::stable_sort(pieces.begin(), pieces.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  if (pieces.size() > kMaxJointPieces) pieces.resize(kMaxJointPieces);
  const int count = static_cast<int>(pieces.size());
  auto all_on = [&](const std::vector<int>& facets, const Surface& surface) {
    return std::all_of(facets.begin(), facets.end(),
                       [&](int f) { return FacetOnSurface(fm, f, surface, tau); });
  };
  std::vector<char> used(count, 0);
  std::vector<Hypothesis> out;
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count && !used[a]; ++b) {
      if (used[b]) continue;
      const std::vector<int> pair = Union(pieces[a], pieces[b]);
      for (const SurfaceType type : {SurfaceType::kCylinder, SurfaceType::kCone,
                                     SurfaceType::kSphere, SurfaceType::kTorus}) {
        if (!HoldsEvidence(fm, type, pair)) continue;
        const std::optional<Surface> fit = FitExactly(fm, type, pair, tau);
        if (!fit || !all_on(pair, *fit)) continue;
        Hypothesis h{.type = type, .surface = *fit, .support = pair, .joint = true};
        used[a] = used[b] = 1;
        for (int c = 0; c < count; ++c) {
          if (used[c] || !all_on(pieces[c], *fit)) continue;
          used[c] = 1;
          h.support = Union(h.support, pieces[c]);
        }
        // Grown over the facets around its pieces on it (those a small
        // hypothesis took, a flat pair of facets between two rulings).
        GrowHypothesis(fm, tau, &h);
        out.push_back(std::move(h));
        break;
      }
    }
  }
  return out;
}

}  // namespace meshseg::segment_internal
