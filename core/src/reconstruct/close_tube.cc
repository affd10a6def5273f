#include "reconstruct/close_tube.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "reconstruct/split_at_cap.h"
#include "reconstruct/tube_rims.h"
#include "reconstruct/tube_strip.h"

namespace meshseg::reconstruct_internal {
namespace {

using Sm = HoleMesh;

// Loops whose strip search (loop vertices × loop vertices) is larger than
// this are left to their discs.
constexpr size_t kMaxStripCells = 4'000'000;
// Rows of the tube between its rims: enough for the loop's mean edge length
// along the longest rung's arc, within these bounds.
constexpr int kMinRows = 2;
// Arcs that bend (deeper below their chords than the loops' mean edge
// length, the resolution of a curvature across the rims) must bend as the
// seen surface does at each rim: its curvature within this fraction of the
// arcs' mean curvature.
constexpr double kCurvatureTolerance = 0.5;
// Below this turning angle (radians) a rung's arc is taken as straight.
constexpr double kStraightAngle = 1e-3;

// The cubic Hermite curve from `a` leaving along `da` to `b` arriving
// against `db` (b's own outgoing direction), with the tangent length of the
// circular arc that turns by the angle θ between da and −db over the chord c:
// 4 tan(θ/4) R with R = c / (2 sin(θ/2)) (three times the Bézier control
// distance of an arc), c when straight. Also gives the arc's length.
struct Rung {
  Eigen::Vector3d a, b, da, db;
  // depth: below the chord; curvature: 1 / the arc's radius
  double chord = 0.0, tangent = 0.0, arc = 0.0, depth = 0.0, curvature = 0.0;

  Rung(const Eigen::Vector3d& a_in, const Eigen::Vector3d& b_in, const Eigen::Vector3d& da_in,
       const Eigen::Vector3d& db_in)
      : a(a_in), b(b_in), da(da_in), db(db_in) {
    chord = (b - a).norm();
    const double theta = std::acos(std::clamp(-da.dot(db), -1.0, 1.0));
    if (theta < kStraightAngle) {
      tangent = arc = chord;
    } else {
      const double radius = chord / (2.0 * std::sin(0.5 * theta));
      tangent = 4.0 * std::tan(0.25 * theta) * radius;
      arc = theta * radius;
      depth = radius * (1.0 - std::cos(0.5 * theta));
      curvature = 1.0 / radius;
    }
  }

  Eigen::Vector3d At(double t) const {
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * a + (t3 - 2 * t2 + t) * tangent * da + (3 * t2 - 2 * t3) * b -
           (t3 - t2) * tangent * db;
  }
};

int Rows(double longest, double edge) {
  return std::clamp(static_cast<int>(std::ceil(longest / edge)), kMinRows, kMaxRows);
}

}  // namespace

bool CloseTube(HoleMesh::Halfedge_index a, HoleMesh::Halfedge_index b, double sign, bool bend,
               HoleMesh* sm) {
  const Rim rim_a = RimOf(*sm, a, sign);
  Rim rim_b = RimOf(*sm, b, sign);
  const std::vector<Sm::Vertex_index>& loop_a = rim_a.loop;
  std::vector<Sm::Vertex_index>& loop_b = rim_b.loop;
  const size_t m = loop_a.size(), n = loop_b.size();
  if (m * n > kMaxStripCells) return false;
  for (const auto v : loop_a) {
    if (std::find(loop_b.begin(), loop_b.end(), v) != loop_b.end()) return false;
  }
  const std::vector<Eigen::Vector3d>& out_a = rim_a.out;
  std::vector<Eigen::Vector3d>& out_b = rim_b.out;
  const Rim rim_b_border = rim_b;
  // An oriented strip runs along one rim's border and against the other's,
  // starting at the vertex of b nearest a's first.
  std::reverse(loop_b.begin(), loop_b.end());
  std::reverse(out_b.begin(), out_b.end());
  const std::vector<Eigen::Vector3d> pa = Points(*sm, loop_a);
  std::vector<Eigen::Vector3d> pb = Points(*sm, loop_b);
  const size_t first = Nearest(pb, pa[0]);
  std::rotate(loop_b.begin(), loop_b.begin() + first, loop_b.end());
  std::rotate(out_b.begin(), out_b.begin() + first, out_b.end());
  std::rotate(pb.begin(), pb.begin() + first, pb.end());
  const std::vector<std::pair<size_t, size_t>> strip = ShortestStrip(pa, pb);
  const size_t rungs = strip.size() - 1;  // the last is the first again
  std::vector<Rung> rung;
  const double edge = MeanEdge(pa, pb);
  double longest = 0.0;
  for (size_t r = 0; r < rungs; ++r) {
    const auto [i, j] = strip[r];
    rung.emplace_back(pa[i % m], pb[j % n], out_a[i % m], out_b[j % n]);
    longest = std::max(longest, rung.back().arc);
  }
  // The arcs must bend as the seen surface does at each rim, unless they
  // are straight within the resolution of that curvature.
  double arc_depth = 0.0, arc_curvature = 0.0;
  for (const Rung& r : rung) {
    arc_depth += r.depth;
    arc_curvature += r.curvature;
  }
  arc_depth /= static_cast<double>(rungs);
  arc_curvature /= static_cast<double>(rungs);
  const double tolerance = kCurvatureTolerance * arc_curvature;
  const auto off_arcs = [&](double seen) { return std::abs(seen - arc_curvature) > tolerance; };
  const auto curved = [&](double seen) { return std::abs(seen) > tolerance; };
  if (arc_depth > edge && (off_arcs(rim_a.curvature) || off_arcs(rim_b.curvature))) {
    // Straight walls at both rims (flatter than the arcs by the same
    // tolerance) run on to the face between them.
    if (curved(rim_a.curvature) || curved(rim_b.curvature)) return false;
    return SplitAtCap(rim_a, rim_b_border, sign, bend, sm);
  }
  // Rings across the arcs a mean edge apart along the longest, each as
  // dense as the loops (tube_strip.h): the longer rim's rungs fan in onto
  // the shorter one.
  Added added;
  const bool ok = AddContourStrip(
      loop_a, pa, loop_b, pb, strip, [&](size_t r, double t) { return rung[r].At(t); },
      Rows(longest, edge), edge, sm, &added);
  if (!ok) TakeBack(added, sm);
  return ok;
}

}  // namespace meshseg::reconstruct_internal