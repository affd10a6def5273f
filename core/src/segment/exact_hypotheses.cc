#include "segment/exact_hypotheses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

#include <tbb/parallel_for.h>

#include "segment/energy.h"
#include "segment/facet_on_surface.h"

namespace meshseg::segment_internal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A support is grown and refitted at most this many times.
constexpr int kMaxGrowRounds = 3;

double Dihedral(const FacetMesh& fm, int f, int g) {
  const Eigen::Vector3d& a = fm.normal[f];
  const Eigen::Vector3d& b = fm.normal[g];
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The facets edge-connected to `seed` that meet the criterion for `surface`,
// of data cost 0 on it (energy.h: ExactFacetCost): what a label of that
// surface may explain (the seed's own facets are taken as given), sorted.
std::vector<int> Support(const FacetMesh& fm, const Surface& surface, std::span<const int> seed,
                         double tau, std::vector<char>* mark) {
  std::vector<int> out(seed.begin(), seed.end());
  for (const int f : out) (*mark)[f] = 1;
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (const int g : fm.across[out[k]]) {
      if (g < 0 || (*mark)[g]) continue;
      (*mark)[g] = 1;  // tried; reset below
      if (ExactFacetCost(fm, g, surface, tau) == 0.0) {
        out.push_back(g);
      } else {
        (*mark)[g] = 2;
      }
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (const int g : fm.across[out[k]]) {
      if (g >= 0) (*mark)[g] = 0;
    }
    (*mark)[out[k]] = 0;
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Grows `h` from its support, refitting on what it holds, until it stops
// growing or the refit no longer fits within tau.
void Grow(const FacetMesh& fm, double tau, Hypothesis* h) {
  // Marks of facets tried, all zero between calls (Support resets the ones it
  // sets): one array per thread, so that a hypothesis costs what it touches
  // rather than the size of the mesh.
  thread_local std::vector<char> mark;
  if (mark.size() < fm.corners.size()) mark.assign(fm.corners.size(), 0);
  for (int round = 0; round < kMaxGrowRounds; ++round) {
    std::vector<int> grown = Support(fm, h->surface, h->support, tau, &mark);
    const bool same = grown.size() == h->support.size();
    h->support = std::move(grown);
    if (same && round > 0) break;
    const std::optional<Surface> refit = FitExactly(fm, h->type, h->support, tau);
    if (!refit) break;
    h->surface = *refit;
  }
}

// f and the facets around it over edges at less than kSeedCreaseDeg, until
// they hold `corners` distinct corners (or kMaxSeedFacets facets): in
// rings (breadth first: a compact patch), or smoothest first (the next is
// the one across the flattest edge from the group: along a narrow band
// rather than over into the face beside it, but along the rulings of a
// finely tessellated cylinder, where a ring is better).
std::vector<int> SeedGroup(const FacetMesh& fm, int f, int corners, bool smoothest_first) {
  const double crease = kSeedCreaseDeg * kPi / 180.0;
  std::vector<int> group;
  std::vector<int> seen;
  using Entry = std::pair<double, int>;  // (order key, facet)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> next;
  next.emplace(0.0, f);
  double order = 0.0;
  while (!next.empty()) {
    const int g = next.top().second;
    next.pop();
    if (std::find(group.begin(), group.end(), g) != group.end()) continue;
    group.push_back(g);
    for (const int v : fm.corners[g]) {
      if (std::find(seen.begin(), seen.end(), v) == seen.end()) seen.push_back(v);
    }
    if (static_cast<int>(seen.size()) >= corners || group.size() >= kMaxSeedFacets) break;
    for (const int h : fm.across[g]) {
      if (h < 0 || fm.normal[h].isZero()) continue;
      const double angle = Dihedral(fm, g, h);
      if (angle < crease && std::find(group.begin(), group.end(), h) == group.end()) {
        next.emplace(smoothest_first ? angle : (order += 1.0), h);
      }
    }
  }
  return group;
}

// The seed groups tried, in order: (corners, smoothest first).
std::vector<std::pair<int, bool>> SeedShapes() {
  std::vector<std::pair<int, bool>> shapes;
  for (const int corners : kSeedCorners) {
    shapes.emplace_back(corners, false);
    shapes.emplace_back(corners, true);
  }
  return shapes;
}

// The first curved type that fits `group` exactly with every facet of it on
// the surface, if the group holds evidence for it.
std::optional<Hypothesis> CurvedFit(const FacetMesh& fm, const std::vector<int>& group,
                                    double tau) {
  for (const SurfaceType type :
       {SurfaceType::kCylinder, SurfaceType::kCone, SurfaceType::kSphere, SurfaceType::kTorus}) {
    if (!HoldsEvidence(fm, type, group)) continue;
    const std::optional<Surface> fit = FitExactly(fm, type, group, tau);
    if (!fit) continue;
    if (!std::all_of(group.begin(), group.end(),
                     [&](int g) { return FacetOnSurface(fm, g, *fit, tau); })) {
      continue;
    }
    Hypothesis h{.type = type, .surface = *fit, .support = group};
    std::sort(h.support.begin(), h.support.end());
    return h;
  }
  return std::nullopt;
}

// A cylinder or cone grown from facet f one neighbour at a time, each kept
// only if the group still fits the type exactly with every facet on it: the
// seed of a coarse round (a few strips of 15 degrees or more, rim to rim),
// whose facets meet tangent neighbours (a blend, a flat side) across
// flatter edges than their own, so that rings and smoothest-first groups
// reach over into the next face before they hold a round's evidence. Each
// neighbour of f (or of a facet in f's plane) across a bend is tried as the
// first: two strips fix a cylinder, and a wrong first bend fits nothing
// further.
std::optional<Hypothesis> StripsAt(const FacetMesh& fm, int f, double tau) {
  const double crease = kSeedCreaseDeg * kPi / 180.0;
  // f and the facets in its plane around it, then the bends out of them.
  std::vector<int> flat = {f};
  std::vector<int> bends;
  for (std::size_t k = 0; k < flat.size() && flat.size() < kMaxSeedFacets; ++k) {
    for (const int h : fm.across[flat[k]]) {
      if (h < 0 || fm.normal[h].isZero() || std::find(flat.begin(), flat.end(), h) != flat.end())
        continue;
      const double angle = Dihedral(fm, flat[k], h);
      if (angle < kDistinctNormal) {
        flat.push_back(h);
      } else if (angle < crease && std::find(bends.begin(), bends.end(), h) == bends.end()) {
        bends.push_back(h);
      }
    }
  }
  for (const SurfaceType type : {SurfaceType::kCylinder, SurfaceType::kCone}) {
    for (const int first : bends) {
      std::vector<int> group = flat;
      group.push_back(first);
      std::optional<Surface> fit = FitExactly(fm, type, group, tau);
      if (!fit) continue;
      std::vector<int> tried = group;
      for (std::size_t k = 0; k < group.size() && group.size() < kMaxSeedFacets; ++k) {
        for (const int h : fm.across[group[k]]) {
          if (h < 0 || fm.normal[h].isZero() || Dihedral(fm, group[k], h) >= crease ||
              std::find(tried.begin(), tried.end(), h) != tried.end()) {
            continue;
          }
          tried.push_back(h);
          group.push_back(h);
          const std::optional<Surface> next = FitExactly(fm, type, group, tau);
          // Without evidence yet the fit is one of many through the
          // corners (three rulings lie on cylinders of any tilt): the
          // corners decide; with it, the criterion on every facet.
          if (next && (!HoldsEvidence(fm, type, group) ||
                       std::all_of(group.begin(), group.end(),
                                   [&](int g) { return FacetOnSurface(fm, g, *next, tau); }))) {
            fit = next;
          } else {
            group.pop_back();
          }
        }
      }
      if (!HoldsEvidence(fm, type, group) || !std::all_of(group.begin(), group.end(), [&](int g) {
            return FacetOnSurface(fm, g, *fit, tau);
          })) {
        continue;
      }
      Hypothesis h{.type = type, .surface = *fit, .support = group};
      std::sort(h.support.begin(), h.support.end());
      return h;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Hypothesis> PlaneAt(const FacetMesh& fm, int f, double tau) {
  if (fm.normal[f].isZero()) return std::nullopt;
  Hypothesis h{
      .type = SurfaceType::kPlane, .surface = Plane{fm.Centroid(f), fm.normal[f]}, .support = {f}};
  Grow(fm, tau, &h);
  if (!HoldsEvidence(fm, h.type, h.support)) return std::nullopt;
  return h;
}

std::optional<Hypothesis> CurvedAt(const FacetMesh& fm, int f, double tau) {
  // The seed shapes' fits are independent: they run in parallel, each in the
  // order of the shapes, and a fit is skipped once an earlier shape has
  // fitted (the earliest that fits and holds evidence when grown is the
  // seed's, as if tried one after the other).
  static const std::vector<std::pair<int, bool>> shapes = SeedShapes();
  const int count = static_cast<int>(shapes.size());
  std::vector<std::optional<Hypothesis>> fits(count);
  std::vector<char> tried(count, 0);
  std::atomic<int> first_fit{count};
  auto fit_shape = [&](int i) {
    fits[i] = CurvedFit(fm, SeedGroup(fm, f, shapes[i].first, shapes[i].second), tau);
    tried[i] = 1;
    if (fits[i]) {
      for (int k = first_fit.load(); i < k && !first_fit.compare_exchange_weak(k, i);) {
      }
    }
  };
  tbb::parallel_for(0, count, [&](int i) {
    if (i < first_fit.load()) fit_shape(i);
  });
  for (int i = 0; i < count; ++i) {
    if (!tried[i]) fit_shape(i);  // after an earlier fit that did not hold
    std::optional<Hypothesis>& h = fits[i];
    if (!h) continue;
    Grow(fm, tau, &*h);
    // A narrow seed can leave a simpler type undecided (a cone of a small
    // angle through a few rulings of a cylinder); the grown support decides.
    for (const SurfaceType simpler :
         {SurfaceType::kCylinder, SurfaceType::kCone, SurfaceType::kSphere}) {
      if (Simplicity(simpler) >= Simplicity(h->type)) break;
      if (const std::optional<Surface> fit = FitExactly(fm, simpler, h->support, tau)) {
        h->type = simpler;
        h->surface = *fit;
        Grow(fm, tau, &*h);
        break;
      }
    }
    if (HoldsEvidence(fm, h->type, h->support)) return h;
  }
  if (std::optional<Hypothesis> h = StripsAt(fm, f, tau)) {
    Grow(fm, tau, &*h);
    return h;
  }
  return std::nullopt;
}

void GrowHypothesis(const FacetMesh& fm, double tau, Hypothesis* h) { Grow(fm, tau, h); }

bool ExplainedLocally(const FacetMesh& fm, int f, double tau) {
  if (fm.normal[f].isZero()) return false;
  const Plane plane{fm.Centroid(f), fm.normal[f]};
  for (const int g : fm.across[f]) {
    if (g >= 0 && CornersOnSurface(fm, g, plane, tau)) return true;
  }
  for (const auto& [corners, smoothest_first] : SeedShapes()) {
    if (CurvedFit(fm, SeedGroup(fm, f, corners, smoothest_first), tau)) return true;
  }
  // A facet at its face's border: the facets around a neighbour may fit
  // where its own do not.
  for (const int g : fm.across[f]) {
    if (g < 0 || fm.normal[g].isZero()) continue;
    for (const auto& [corners, smoothest_first] : SeedShapes()) {
      const std::optional<Hypothesis> h =
          CurvedFit(fm, SeedGroup(fm, g, corners, smoothest_first), tau);
      if (h && FacetOnSurface(fm, f, h->surface, tau)) return true;
    }
  }
  return false;
}

}  // namespace meshseg::segment_internal
