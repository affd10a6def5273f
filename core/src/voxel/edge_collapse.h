// The collapse loop of Simplify(): Garland-Heckbert quadric error metrics
// (Garland & Heckbert 1997, area-weighted face planes) over an edge heap
// with lazy deletion, and the creases of a plain mesh it keeps.
//
// Vertices are of three kinds:
//   free    -> moves to the quadric's optimum (or onto a feature neighbour);
//   crease  -> on a crease (has a crease edge): may only slide along its
//              crease edges, staying on the segment; the constraint planes
//              of the crease edges (Garland-Heckbert) price moving a line
//              sideways, and the face planes moving a corner where lines meet;
//   locked  -> never removed (the feature points of ALGORITHMS.md S4 and the
//              ends of label-boundary edges).
// An edge whose two ends are both crease or locked vertices collapses only if
// it is itself a crease edge (otherwise it would cut across a feature).
// Each edge's cost is computed once when one of its ends changes; a popped
// entry whose ends have changed since is stale and skipped, and the flip,
// topology and error tests are repeated on the current mesh before the
// collapse runs. A large mesh is collapsed in two lanes (halves) at once,
// then as a whole (see Collapser::AssignLanes).
#ifndef MESHSEG_VOXEL_EDGE_COLLAPSE_H_
#define MESHSEG_VOXEL_EDGE_COLLAPSE_H_

#include <Eigen/Dense>
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "meshseg/mesh.h"
#include "meshseg/run_context.h"

namespace meshseg::voxel_internal {

// Quadric of squared distances, weighted: x^T A x + 2 b^T x + c; `area` is
// the total weight, so error / area is a mean squared distance.
struct Quadric {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double c = 0.0;
  double area = 0.0;

  void AddPlane(const Eigen::Vector3d& n, double d, double w) {
    a += w * n * n.transpose();
    b += w * d * n;
    c += w * d * d;
    area += w;
  }
  Quadric& operator+=(const Quadric& q) {
    a += q.a, b += q.b, c += q.c, area += q.area;
    return *this;
  }
  double Error(const Eigen::Vector3d& x) const {
    return std::max(0.0, x.dot(a * x) + 2.0 * b.dot(x) + c);
  }
};

// argmin q over space if A is well conditioned (determinant against the cube
// of its trace) and the optimum is near the edge, else over the segment.
inline Eigen::Vector3d OnSegment(const Quadric& q, const Eigen::Vector3d& p0,
                                 const Eigen::Vector3d& p1) {
  const Eigen::Vector3d d = p1 - p0;
  const double dad = d.dot(q.a * d);
  double t = 0.5;
  if (dad > 0.0) t = std::clamp(-(d.dot(q.a * p0) + q.b.dot(d)) / dad, 0.0, 1.0);
  return p0 + t * d;
}

inline Eigen::Vector3d Optimum(const Quadric& q, const Eigen::Vector3d& p0,
                               const Eigen::Vector3d& p1) {
  const double trace = q.a.trace();
  const double det = q.a.determinant();
  if (trace > 0.0 && det > 1e-6 * trace * trace * trace) {
    const Eigen::Vector3d x = -(q.a.inverse() * q.b);
    // Stay near the edge: an optimum far off it is a conditioning artefact.
    if ((x - 0.5 * (p0 + p1)).squaredNorm() <= 4.0 * (p1 - p0).squaredNorm()) return x;
  }
  return OnSegment(q, p0, p1);
}

// One flag per edge of `mesh`: the edge is a crease, i.e. its two faces'
// normals differ by more than `min_deg` after the face normals were
// denoised (see creases.cc).
std::vector<uint8_t> CreaseEdges(const TriMesh& mesh, double min_deg);

struct CollapseParams {
  size_t target_faces = 0;              // stop at this many faces (0 = none)
  double max_error = 0.0;               // rms quadric error bound, model units (0 = none)
  double min_cos_normal = 0.5;          // a face may turn by at most acos of this
  size_t two_lanes_min_faces = 200000;  // see SimplifyParams
  // Constraint planes on interior creases too (always on open borders). A
  // border has one face plane, which does not price moving the border
  // sideways within it; an interior crease where the surface turns by an
  // angle a has two, and moving it by d within one costs d sin a from the
  // other.
  bool interior_crease_planes = true;
};

// Collapses edges of `mesh` (which needs status attributes) in order of
// quadric error until `target_faces` or no legal collapse is left.
// `locked` has one flag per vertex, `crease` one per edge (either may be
// empty). Deleted elements are only marked; the caller compacts. If
// `crease_after` is given it receives the crease flag of every edge of the
// collapsed mesh (deleted edges included, as 0 or their last flag): where a
// collapse merges two edges the survivor is a crease if either was.
absl::Status CollapseEdges(TriMesh& mesh, const CollapseParams& params,
                           std::span<const uint8_t> locked, std::span<const uint8_t> crease,
                           const RunContext& ctx, std::vector<uint8_t>* crease_after = nullptr);

}  // namespace meshseg::voxel_internal

#endif  // MESHSEG_VOXEL_EDGE_COLLAPSE_H_
