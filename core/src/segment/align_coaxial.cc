#include "segment/align_coaxial.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "segment/decide_type.h"
#include "segment/region_graph.h"

namespace meshseg::segment_internal {
namespace {

// A cylinder or cone region's vertices for the fit: those that meet (5)
// and (6) for its surface, sub-sampled.
struct Member {
  SurfaceType type = SurfaceType::kCylinder;
  std::vector<Eigen::Vector3d> points;
  double mean_rho = 0.0;  // mean distance of the points from the region's axis
  double cost = 0.0;      // Σ d² of the points to the region's own coaxial fit
};

// Fitted members: their surfaces and Σ d² over all their points.
struct GroupFit {
  std::vector<FitResult> fits;
  double cost = 0.0;
};

std::optional<Member> MakeMember(const SegmentContext& c, const RegionState& r) {
  if (!r.alive || (r.type != SurfaceType::kCylinder && r.type != SurfaceType::kCone)) {
    return std::nullopt;
  }
  const std::optional<AxisLine> axis = AxisOf(r.surface);
  if (!axis) return std::nullopt;
  Member m;
  m.type = r.type;
  for (const int v : Sample(MeasuredVertices(c, FittingVertices(c, r.surface, r.vertices)))) {
    m.points.push_back(c.position(v));
  }
  if (m.points.size() < 6) return std::nullopt;
  for (const Eigen::Vector3d& p : m.points) {
    const Eigen::Vector3d d = p - axis->point;
    m.mean_rho += (d - d.dot(axis->direction) * axis->direction).norm();
  }
  m.mean_rho /= static_cast<double>(m.points.size());
  return m;
}

// FitCoaxial of `members` from `axis`; nullopt if it is invalid.
std::optional<GroupFit> FitGroup(const std::vector<const Member*>& members, const AxisLine& axis) {
  std::vector<CoaxialMember> input;
  for (const Member* m : members) {
    input.push_back({m->type, {.points = m->points, .normals = {}, .weights = {}}});
  }
  GroupFit g{.fits = FitCoaxial(input, axis.point, axis.direction)};
  for (std::size_t j = 0; j < members.size(); ++j) {
    if (!g.fits[j].ok()) return std::nullopt;
    g.cost += std::pow(g.fits[j].rms_distance, 2) * static_cast<double>(members[j]->points.size());
  }
  return g;
}

Eigen::Vector3d Centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

// The member of every cylinder and cone region with its fit alone (none
// where that fit is invalid).
std::vector<std::optional<Member>> MakeMembers(const SegmentContext& c,
                                               const std::vector<RegionState>& regions) {
  std::vector<std::optional<Member>> members(regions.size());
  for (std::size_t id = 0; id < regions.size(); ++id) {
    members[id] = MakeMember(c, regions[id]);
    if (!members[id]) continue;
    const std::optional<GroupFit> alone = FitGroup({&*members[id]}, *AxisOf(regions[id].surface));
    if (alone) {
      members[id]->cost = alone->cost;
    } else {
      members[id].reset();
    }
  }
  return members;
}

struct Pair {
  int a = 0, b = 0;
  double cos_angle = 0.0;  // between their axes
};

// Adjacent members with NearlyCoaxial surfaces, the closest axes first.
std::vector<Pair> CandidatePairs(const SegmentContext& c, const std::vector<int>& labels,
                                 const std::vector<RegionState>& regions,
                                 const std::vector<std::optional<Member>>& members) {
  std::vector<Pair> pairs;
  for (const RegionArc& arc : BuildRegionGraph(c, labels, regions)) {
    if (!members[arc.a] || !members[arc.b]) continue;
    const Surface& sa = regions[arc.a].surface;
    const Surface& sb = regions[arc.b].surface;
    const Eigen::Vector3d middle =
        0.5 * (Centroid(members[arc.a]->points) + Centroid(members[arc.b]->points));
    if (!NearlyCoaxial(sa, sb, middle,
                       std::min(members[arc.a]->mean_rho, members[arc.b]->mean_rho))) {
      continue;
    }
    pairs.push_back({arc.a, arc.b, std::abs(AxisOf(sa)->direction.dot(AxisOf(sb)->direction))});
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const Pair& x, const Pair& y) { return x.cos_angle > y.cos_angle; });
  return pairs;
}

}  // namespace

double ResidualVariance(const SegmentContext& c, double cost, double points, double values) {
  return std::max(cost / std::max(1.0, points - values),
                  std::pow(kVarianceFloor * c.mean_edge_length, 2));
}

bool NearlyCoaxial(const Surface& a, const Surface& b, const Eigen::Vector3d& middle,
                   double radius) {
  const AxisLine la = *AxisOf(a);
  const AxisLine lb = *AxisOf(b);
  if (std::abs(la.direction.dot(lb.direction)) < std::cos(kCoaxialMaxAngleDeg * M_PI / 180.0)) {
    return false;
  }
  const Eigen::Vector3d pa = la.point + (middle - la.point).dot(la.direction) * la.direction;
  const Eigen::Vector3d d = pa - lb.point;
  return (d - d.dot(lb.direction) * lb.direction).norm() <= kCoaxialMaxOffset * radius;
}

std::vector<std::vector<int>> AlignCoaxialRegions(const SegmentContext& c,
                                                  const std::vector<int>& labels,
                                                  std::vector<RegionState>* regions) {
  const int n = static_cast<int>(regions->size());
  const std::vector<std::optional<Member>> members = MakeMembers(c, *regions);
  const std::vector<Pair> pairs = CandidatePairs(c, labels, *regions, members);

  // Groups: the regions of each, its joint fit (none for a region alone)
  // and its Σ d².
  std::vector<int> group(n);
  std::iota(group.begin(), group.end(), 0);
  std::vector<std::vector<int>> group_regions(n);
  std::vector<std::optional<GroupFit>> group_fit(n);
  std::vector<double> group_cost(n, 0.0);
  for (int id = 0; id < n; ++id) {
    group_regions[id] = {id};
    if (members[id]) group_cost[id] = members[id]->cost;
  }
  for (const Pair& pair : pairs) {
    const int ga = group[pair.a];
    const int gb = group[pair.b];
    if (ga == gb) continue;
    std::vector<int> joined = group_regions[ga];
    joined.insert(joined.end(), group_regions[gb].begin(), group_regions[gb].end());
    std::vector<const Member*> joined_members;
    double alone_cost = 0.0;
    double values = 0.0;
    std::size_t points = 0;
    for (const int id : joined) {
      joined_members.push_back(&*members[id]);
      alone_cost += members[id]->cost;
      values += members[id]->type == SurfaceType::kCone ? 6.0 : 5.0;
      points += members[id]->points.size();
    }
    // Start from the axis of the member with the most points.
    const int start = *std::max_element(joined.begin(), joined.end(), [&](int x, int y) {
      return members[x]->points.size() < members[y]->points.size();
    });
    const AxisLine axis = group_fit[group[start]]
                              ? *AxisOf(group_fit[group[start]]->fits[0].surface)
                              : *AxisOf((*regions)[start].surface);
    std::optional<GroupFit> fit = FitGroup(joined_members, axis);
    if (!fit) continue;
    const double variance = ResidualVariance(c, alone_cost, static_cast<double>(points), values);
    const double rise = fit->cost - group_cost[ga] - group_cost[gb];
    const bool joint_at_noise = std::all_of(fit->fits.begin(), fit->fits.end(),
                                            [&](const FitResult& f) { return FitsAtNoise(c, f); });
    if (!(rise <= kCoaxialChiSquare * variance) && !joint_at_noise) continue;
    for (const int id : group_regions[gb]) group[id] = ga;
    group_regions[ga] = joined;
    group_regions[gb].clear();
    group_cost[ga] = fit->cost;
    group_fit[ga] = std::move(fit);
    group_fit[gb].reset();
  }
  std::vector<std::vector<int>> groups;
  for (int g = 0; g < n; ++g) {
    if (!group_fit[g]) continue;
    for (std::size_t j = 0; j < group_regions[g].size(); ++j) {
      (*regions)[group_regions[g][j]].surface = group_fit[g]->fits[j].surface;
    }
    groups.push_back(group_regions[g]);
  }
  return groups;
}

int MergeCoaxialCylinders(const SegmentContext& c, const std::vector<std::vector<int>>& groups,
                          std::vector<int>* labels, std::vector<RegionState>* regions) {
  std::set<std::pair<int, int>> adjacent;
  for (const RegionArc& arc : BuildRegionGraph(c, *labels, *regions)) {
    adjacent.insert({arc.a, arc.b});
  }
  const auto cylinder = [&](int id) { return std::get_if<Cylinder>(&(*regions)[id].surface); };
  int merges = 0;
  for (const std::vector<int>& group : groups) {
    // Largest first, so that each piece merges into the largest one it matches.
    std::vector<int> order = group;
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      return (*regions)[x].vertices.size() > (*regions)[y].vertices.size();
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
      const int into = order[i];
      if (!(*regions)[into].alive || (*regions)[into].type != SurfaceType::kCylinder) continue;
      bool grew = false;
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        const int from = order[j];
        const RegionState& other = (*regions)[from];
        if (!other.alive || other.type != SurfaceType::kCylinder ||
            !adjacent.contains({std::min(into, from), std::max(into, from)}) ||
            !(std::abs(cylinder(into)->radius - cylinder(from)->radius) < c.tolerance.distance)) {
          continue;
        }
        MergeInto(into, from, labels, regions);
        grew = true;
        ++merges;
      }
      if (!grew) continue;
      // The radius of least squares about the shared axis.
      Cylinder& merged = std::get<Cylinder>((*regions)[into].surface);
      const std::vector<int> fitting =
          MeasuredVertices(c, FittingVertices(c, merged, (*regions)[into].vertices));
      if (fitting.empty()) continue;
      double sum = 0.0;
      for (const int v : fitting) {
        const Eigen::Vector3d d = c.position(v) - merged.axis_origin;
        sum += (d - d.dot(merged.axis_direction) * merged.axis_direction).norm();
      }
      merged.radius = sum / static_cast<double>(fitting.size());
    }
  }
  return merges;
}

}  // namespace meshseg::segment_internal
