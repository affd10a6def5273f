#include "segment/round_arc.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace meshseg::segment_internal {
namespace {

// Fewest vertices on the arc (a cylinder's 5 values and one more) and
// beyond each line of contact (a plane's 3) that a fit is made from.
constexpr std::size_t kMinArcVertices = 6;
constexpr std::size_t kMinFaceVertices = 3;

// The round's cross-section: its axis, its radius and, in each face, the
// direction from the line of contact away from the arc.
struct ArcFrame {
  Eigen::Vector3d centre;
  Eigen::Vector3d axis;
  double radius = 0.0;
  std::array<Eigen::Vector3d, 2> away;
};

ArcFrame FrameOf(const Cylinder& round, const std::array<Plane, 2>& planes) {
  ArcFrame f{.centre = round.axis_origin,
             .axis = round.axis_direction.normalized(),
             .radius = round.radius,
             .away = {}};
  // From the axis to each line of contact: along the face's normal, toward
  // the face.
  std::array<Eigen::Vector3d, 2> contact;
  for (int i = 0; i < 2; ++i) {
    Eigen::Vector3d u = -PlaneSide(planes[i], f.centre) * planes[i].normal.normalized();
    contact[i] = (u - u.dot(f.axis) * f.axis).normalized();
  }
  // In face i, square to its contact direction and turned from the other's.
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector3d& u = contact[i];
    const Eigen::Vector3d& other = contact[1 - i];
    f.away[i] = -(other - other.dot(u) * u).normalized();
  }
  return f;
}

struct ArcSets {
  std::vector<int> arc;
  std::vector<int> inside;  // RoundOnArc::inside
  std::array<std::vector<int>, 2> beyond;  // each face's line of contact
};

// Sorts `values`, which holds runs starting at `starts` (ascending, the
// first 0): each run sorted unless it already is (a region's vertices
// usually are), then the runs merged. A sorted list of numbers is unique,
// so this is the list std::sort gives, in about linear time.
void SortRuns(const std::vector<std::size_t>& starts, std::vector<int>* values) {
  std::vector<std::size_t> bounds = starts;
  bounds.push_back(values->size());
  const auto at = [&](std::size_t k) { return values->begin() + static_cast<std::ptrdiff_t>(k); };
  for (std::size_t r = 0; r + 1 < bounds.size(); ++r) {
    if (!std::is_sorted(at(bounds[r]), at(bounds[r + 1]))) {
      std::sort(at(bounds[r]), at(bounds[r + 1]));
    }
    if (r > 0) std::inplace_merge(at(0), at(bounds[r]), at(bounds[r + 1]));
  }
}

// The vertices of `ids` sorted by their direction from the axis: between
// the two lines of contact (the arc; kept within the extent along the axis
// of region `round_id` and within th_dis of the round), or beyond one of
// them (kept if they meet (5) and (6) for that face's plane).
ArcSets SortByPosition(const SegmentContext& c, const std::vector<RegionState>& regions,
                       int round_id, std::span<const int> ids, const ArcFrame& f,
                       const std::array<Plane, 2>& planes) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const int v : regions[round_id].vertices) {
    const double along = (c.position(v) - f.centre).dot(f.axis);
    lo = std::min(lo, along);
    hi = std::max(hi, along);
  }
  ArcSets sets;
  // Where each region's vertices start in each set: every set is a run per
  // region, each run in its region's order.
  std::array<std::vector<std::size_t>, 4> runs;
  const auto sets_of = [&sets]() {
    return std::array<std::vector<int>*, 4>{&sets.arc, &sets.inside, &sets.beyond[0],
                                            &sets.beyond[1]};
  };
  for (const int id : ids) {
    for (int k = 0; k < 4; ++k) runs[k].push_back(sets_of()[k]->size());
    for (const int v : regions[id].vertices) {
      if (!c.Measured(v)) continue;  // a closing patch says nothing of the arc
      const Eigen::Vector3d d = c.position(v) - f.centre;
      const double along = d.dot(f.axis);
      const Eigen::Vector3d q = d - along * f.axis;
      const bool beyond[2] = {q.dot(f.away[0]) > 0.0, q.dot(f.away[1]) > 0.0};
      if (!beyond[0] && !beyond[1]) {
        if (id == round_id) sets.inside.push_back(v);
        if (along >= lo && along <= hi && std::abs(q.norm() - f.radius) < c.tolerance.distance) {
          sets.arc.push_back(v);
        }
        continue;
      }
      for (int i = 0; i < 2; ++i) {
        if (beyond[i]) sets.beyond[i].push_back(v);
      }
    }
  }
  for (int k = 0; k < 4; ++k) SortRuns(runs[k], sets_of()[k]);
  for (int i = 0; i < 2; ++i) sets.beyond[i] = FittingVertices(c, planes[i], sets.beyond[i]);
  return sets;
}

}  // namespace

int PlaneSide(const Plane& plane, const Eigen::Vector3d& p) {
  return (p - plane.point).dot(plane.normal) >= 0.0 ? 1 : -1;
}

RoundOnArc FitRoundOnArc(const SegmentContext& c, const std::vector<RegionState>& regions,
                         int round_id, std::array<int, 2> face_ids, const Cylinder& tangent) {
  RoundOnArc out;
  out.planes = {std::get<Plane>(regions[face_ids[0]].surface),
                std::get<Plane>(regions[face_ids[1]].surface)};
  const int ids[] = {round_id, face_ids[0], face_ids[1]};
  Cylinder round = tangent;
  for (int turn = 0; turn < kMaxArcTurns; ++turn) {
    ArcSets sets =
        SortByPosition(c, regions, round_id, ids, FrameOf(round, out.planes), out.planes);
    if (turn > 0 && sets.arc == out.arc) {
      out.inside = std::move(sets.inside);
      break;
    }
    out.round.valid = false;
    if (sets.arc.size() < kMinArcVertices || sets.beyond[0].size() < kMinFaceVertices ||
        sets.beyond[1].size() < kMinFaceVertices) {
      return out;
    }
    for (int i = 0; i < 2; ++i) {
      const FitResult plane = FitType(c, SurfaceType::kPlane, sets.beyond[i]);
      if (!plane.ok()) return out;
      out.planes[i] = std::get<Plane>(plane.surface);
    }
    const std::array<int, 2> sides = {PlaneSide(out.planes[0], round.axis_origin),
                                      PlaneSide(out.planes[1], round.axis_origin)};
    std::vector<Eigen::Vector3d> points;
    for (const int v : Sample(sets.arc)) points.push_back(c.position(v));
    out.round = FitCylinderTangentToPlanes({.points = points, .normals = {}, .weights = {}},
                                           out.planes[0], out.planes[1], sides, round.radius);
    if (!out.round.ok()) return out;
    round = std::get<Cylinder>(out.round.surface);
    out.arc = std::move(sets.arc);
    out.inside = std::move(sets.inside);
  }
  return out;
}

}  // namespace meshseg::segment_internal
